// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import org.junit.jupiter.api.Test;

/**
 * SelectionPolygonVolume and the editing viewer's crop, the scenarios of tests/capi/test_selection.c: a unit
 * square across z crops a 30 x 30 grid to its 100 inner points, Open3D's crop of its fragment keeps 29873
 * points (recorded from the open3d 0.20 wheel), and K / drag / C crops the viewer's cloud.
 */
class SelectionTest {
    /** 30 x 30 points of step 0.1 from -0.95 at height z: exactly 100 inside [0, 1]^2, none on its edges. */
    static PointCloud grid(double z) {
        double[] p = new double[900 * 3];
        for (int i = 0; i < 30; i++)
            for (int j = 0; j < 30; j++) {
                int k = 3 * (30 * i + j);
                p[k] = -0.95 + 0.1 * i;
                p[k + 1] = -0.95 + 0.1 * j;
                p[k + 2] = z;
            }
        return cloud(p);
    }

    @Test
    void unitSquareCropsTheGrid() {
        try (SelectionPolygonVolume v = new SelectionPolygonVolume(); PointCloud inside = grid(0.5);
             PointCloud above = grid(1.5)) {
            v.setBoundingPolygon(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
            v.setOrthogonalAxis(Library.AXIS_Z);
            v.setAxisMin(0);
            v.setAxisMax(1);
            assertEquals(Library.AXIS_Z, v.getOrthogonalAxis());
            assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, v.getBoundingPolygon(), 0);
            try (PointCloud kept = v.cropPointCloud(inside); PointCloud none = v.cropPointCloud(above)) {
                assertEquals(300, points(kept).length);
                assertEquals(0, points(none).length);
            }
            int[] indices = v.cropInPolygon(inside);
            assertEquals(100, indices.length);
            assertEquals(10 * 30 + 10, indices[0]);
            v.setAxisMin(2);
            assertInvalid(() -> v.cropPointCloud(inside));  // axis_min > axis_max
        }
    }

    @Test
    void open3dFragmentReference() {
        try (SelectionPolygonVolume v = SelectionPolygonVolume.readJson(data("open3d/Crop/cropped.json"));
             PointCloud pc = read(data("open3d/fragment.pcd")); PointCloud chair = v.cropPointCloud(pc)) {
            assertEquals(Library.AXIS_Y, v.getOrthogonalAxis());
            assertEquals(29873 * 3, points(chair).length);
        }
    }

    @Test
    void editingViewerCropsADraggedRectangle() {
        try (Visualizer v = Visualizer.create(1); PointCloud pc = grid(0)) {
            v.createWindow("crop", 160, 120, -1, -1, 0);
            v.addPointcloud("grid", pc, 1);
            assertNull(v.getCroppedPointcloud());
            v.sendKey('K', Library.KEY_ACTION_PRESS, 0);
            assertTrue(v.isSelecting());
            v.sendMouseMove(50, 40);
            v.sendMouseButton(Library.MOUSE_BUTTON_LEFT, Library.KEY_ACTION_PRESS, 0);
            v.sendMouseMove(110, 80);
            v.sendMouseButton(Library.MOUSE_BUTTON_LEFT, Library.KEY_ACTION_RELEASE, 0);
            v.sendKey('C', Library.KEY_ACTION_PRESS, 0);
            assertFalse(v.isSelecting());
            try (PointCloud cropped = v.getCroppedPointcloud()) {
                int n = points(cropped).length / 3;
                assertTrue(n > 20 && n < 900, "kept " + n);
            }
            assertNull(v.getCroppedTrianglemesh());
        }
    }
}
