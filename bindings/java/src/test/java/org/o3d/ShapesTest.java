// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.ByteBuffer;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Oriented boxes, hulls, line sets, voxel grids, octrees and covariances: the same scenarios as
 * bindings/csharp/tests/Test.cs (ShapesTests). Orders and indices checked against Open3D 0.20:
 * tools/reference/record_shapes_bindings.py.
 */
class ShapesTest {
    static O3dException assertStatus(Status s, org.junit.jupiter.api.function.Executable e) {
        O3dException ex = assertThrows(O3dException.class, e);
        assertEquals(s, ex.getStatus(), ex.getMessage());
        assertFalse(ex.getMessage().isEmpty());
        return ex;
    }

    /** The 8 corners of [0,1]^3 (index = x + 2y + 4z) then 5 interior points. */
    static double[] cubeWithInterior() {
        double[] p = new double[3 * 13];
        for (int c = 0; c < 8; c++) {
            p[3 * c] = c & 1;
            p[3 * c + 1] = (c >> 1) & 1;
            p[3 * c + 2] = (c >> 2) & 1;
        }
        double[] inner = {0.5, 0.5, 0.5, 0.2, 0.3, 0.4, 0.9, 0.1, 0.5, 0.7, 0.7, 0.2, 0.1, 0.8, 0.9};
        System.arraycopy(inner, 0, p, 24, inner.length);
        return p;
    }

    /** a and b hold the same rows of 3 (any order). */
    static boolean sameRows(double[] a, double[] b, double tol) {
        if (a.length != b.length) return false;
        boolean[] used = new boolean[b.length / 3];
        for (int i = 0; i < a.length / 3; i++) {
            boolean found = false;
            for (int j = 0; j < b.length / 3 && !found; j++)
                if (!used[j] && Math.abs(a[3 * i] - b[3 * j]) <= tol && Math.abs(a[3 * i + 1] - b[3 * j + 1]) <= tol
                        && Math.abs(a[3 * i + 2] - b[3 * j + 2]) <= tol) {
                    used[j] = true;
                    found = true;
                }
            if (!found) return false;
        }
        return true;
    }

    static double det3(double[] m, int o) {
        return m[o] * (m[o + 4] * m[o + 8] - m[o + 5] * m[o + 7]) - m[o + 1] * (m[o + 3] * m[o + 8] - m[o + 5] * m[o + 6])
                + m[o + 2] * (m[o + 3] * m[o + 7] - m[o + 4] * m[o + 6]);
    }

    @Test
    void convexHullOfCubeWithInteriorPoints() {
        double[] pts = cubeWithInterior();
        try (PointCloud pc = new PointCloud(pts); ConvexHullResult hull = pc.computeConvexHull()) {
            assertEquals(8, hull.mesh.numVertices());
            assertEquals(12, hull.mesh.numTriangles());
            assertEquals(1, hull.mesh.getVolume(), 1e-12);
            assertTrue(hull.mesh.isWatertight());
            assertEquals(8, hull.pointIndices.length);
            double[] v = hull.mesh.getVertices();
            for (int i = 0; i < 8; i++) {
                int k = hull.pointIndices[i];
                assertTrue(k >= 0 && k < 8, "hull vertex " + i + " is a corner: " + k);
                assertArrayEquals(Arrays.copyOfRange(pts, 3 * k, 3 * k + 3), Arrays.copyOfRange(v, 3 * i, 3 * i + 3), 0);
            }
            assertEquals(8, Arrays.stream(hull.pointIndices).distinct().count());
        }
        try (TriangleMesh box = TriangleMesh.createBox(1, 2, 3); ConvexHullResult hull = box.computeConvexHull()) {
            assertEquals(6, hull.mesh.getVolume(), 1e-12);
            assertEquals(12, hull.mesh.numTriangles());
            assertEquals(8, hull.pointIndices.length);
        }
        try (PointCloud flat = new PointCloud(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 0})) {
            assertThrows(O3dException.class, () -> flat.computeConvexHull());
            try (ConvexHullResult j = flat.computeConvexHull(true)) {
                assertTrue(j.mesh.numTriangles() > 0);
            }
        }
        try (PointCloud three = new PointCloud(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0})) {
            assertThrows(O3dException.class, () -> three.computeConvexHull(true));
        }
        try (PointCloud empty = new PointCloud()) {
            assertThrows(O3dException.class, () -> empty.computeConvexHull());
        }
    }

    @Test
    void hiddenPointRemoval() {
        // Points on the unit sphere seen from (0, 0, 5): only the cap facing the camera is visible.
        Random r = new Random(3);
        double[] pts = new double[3 * 400];
        for (int n = 0; n < 400;) {
            double x = 2 * r.nextDouble() - 1, y = 2 * r.nextDouble() - 1, z = 2 * r.nextDouble() - 1;
            double len = Math.sqrt(x * x + y * y + z * z);
            if (len < 0.1 || len > 1) continue;
            pts[3 * n] = x / len;
            pts[3 * n + 1] = y / len;
            pts[3 * n + 2] = z / len;
            n++;
        }
        try (PointCloud pc = new PointCloud(pts); ConvexHullResult res = pc.hiddenPointRemoval(new double[] {0, 0, 5}, 500)) {
            assertTrue(res.pointIndices.length > 20 && res.pointIndices.length < 250, "visible " + res.pointIndices.length);
            for (int i : res.pointIndices) {
                assertTrue(i >= 0 && i < 400);
                assertTrue(pts[3 * i + 2] > 0, "visible point faces the camera");
            }
            assertTrue(res.mesh.numTriangles() > 0);
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.hiddenPointRemoval(new double[] {0, 0, 5}, -1));
            assertThrows(IllegalArgumentException.class, () -> pc.hiddenPointRemoval(new double[] {0, 0}, 1));
        }
    }

    @Test
    void orientedBoundingBox() {
        OrientedBoundingBox aabb = OrientedBoundingBox.createFromAxisAlignedBoundingBox(new double[] {0, 0, 0},
                new double[] {1, 2, 3});
        assertArrayEquals(new double[] {0.5, 1, 1.5}, aabb.center(), 1e-15);
        assertArrayEquals(new double[] {1, 2, 3}, aabb.extent(), 1e-15);
        assertArrayEquals(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, aabb.R(), 0);
        assertEquals(6, aabb.volume(), 1e-12);
        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3, 1, 2, 3, 0, 2, 3, 1, 0, 3, 1, 2, 0},
                aabb.getBoxPoints(), 1e-12, "box points in Open3D's order");
        assertArrayEquals(new int[] {0, 2},
                aabb.getPointIndicesWithinBoundingBox(new double[] {0.5, 0.5, 0.5, 2, 0, 0, 1, 2, 3, -0.1, 1, 1}));
        assertEquals(aabb, OrientedBoundingBox.createFromAxisAlignedBoundingBox(new double[] {0, 0, 0}, new double[] {1, 2, 3}));

        // PCA box of a 2 x 3 x 4 block: volume 24, extents {2, 3, 4}, orthonormal R.
        double[] pts = new double[3 * 10];
        for (int c = 0; c < 8; c++) {
            pts[3 * c] = 2 * (c & 1);
            pts[3 * c + 1] = 3 * ((c >> 1) & 1);
            pts[3 * c + 2] = 4 * ((c >> 2) & 1);
        }
        System.arraycopy(new double[] {1, 1.5, 2, 0.5, 0.5, 0.5}, 0, pts, 24, 6);
        OrientedBoundingBox obb = OrientedBoundingBox.createFromPoints(pts);
        assertEquals(24, obb.volume(), 1e-9);
        double[] e = obb.extent();
        Arrays.sort(e);
        assertArrayEquals(new double[] {2, 3, 4}, e, 1e-9);
        assertArrayEquals(new double[] {1, 1.5, 2}, obb.center(), 1e-9);
        double[] rot = obb.R();
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                assertEquals(i == j ? 1 : 0, rot[i] * rot[j] + rot[3 + i] * rot[3 + j] + rot[6 + i] * rot[6 + j], 1e-9);
        assertTrue(sameRows(obb.getBoxPoints(), Arrays.copyOf(pts, 24), 1e-9), "PCA box corners are the block's");
        try (PointCloud pc = new PointCloud(pts)) {
            assertEquals(24, pc.getOrientedBoundingBox().volume(), 1e-9);
        }
        try (TriangleMesh mesh = TriangleMesh.createBox(2, 3, 4)) {
            assertEquals(24, mesh.getOrientedBoundingBox().volume(), 1e-9);
        }
        assertThrows(O3dException.class, () -> OrientedBoundingBox.createFromPoints(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}));
        double[] planar = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
        assertThrows(O3dException.class, () -> OrientedBoundingBox.createFromPoints(planar));
        assertEquals(0, OrientedBoundingBox.createFromPoints(planar, true).volume(), 1e-3);
        assertStatus(Status.INVALID_ARGUMENT,
                () -> OrientedBoundingBox.createFromPoints(new double[] {0, 0, Double.NaN, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
        assertThrows(IllegalArgumentException.class, () -> new OrientedBoundingBox(new double[3], new double[8], new double[3]));
    }

    @Test
    void cropByOrientedBox() {
        // A box along the diagonal x = y (45 degrees about z), 2 long, 0.2 wide and high.
        double c = Math.sqrt(0.5);
        OrientedBoundingBox box = new OrientedBoundingBox(new double[] {0, 0, 0}, new double[] {c, -c, 0, c, c, 0, 0, 0, 1},
                new double[] {2, 0.2, 0.2});
        try (PointCloud pc = new PointCloud(new double[] {0.5, 0.5, 0, -0.5, -0.5, 0, 0.5, -0.5, 0, 0, 0, 0})) {
            assertArrayEquals(new int[] {0, 1, 3}, box.getPointIndicesWithinBoundingBox(pc.getPoints()));
            try (PointCloud inside = pc.crop(box)) {
                assertTrue(sameRows(inside.getPoints(), new double[] {0.5, 0.5, 0, -0.5, -0.5, 0, 0, 0, 0}, 0));
            }
            try (PointCloud outside = pc.crop(box, true)) {
                assertArrayEquals(new double[] {0.5, -0.5, 0}, outside.getPoints(), 0);
            }
            assertThrows(NullPointerException.class, () -> pc.crop((OrientedBoundingBox) null));
        }
        try (TriangleMesh mesh = TriangleMesh.createBox()) {
            OrientedBoundingBox bottom = OrientedBoundingBox.createFromAxisAlignedBoundingBox(new double[] {-0.1, -0.1, -0.1},
                    new double[] {1.1, 1.1, 0.5});
            try (TriangleMesh cut = mesh.crop(bottom)) {
                assertEquals(4, cut.numVertices());
                assertEquals(2, cut.numTriangles());
                double[] v = cut.getVertices();
                for (int i = 0; i < 4; i++) assertEquals(0, v[3 * i + 2], 0);
            }
        }
    }

    @Test
    void lineSets() {
        try (LineSet ls = LineSet.createFromAxisAlignedBoundingBox(new double[] {0, 0, 0}, new double[] {1, 2, 3})) {
            assertEquals(8, ls.numPoints());
            assertEquals(12, ls.numLines());
            double[] p = ls.getPoints();
            int[] l = ls.getLines();
            int[] lengths = new int[4];
            for (int i = 0; i < 12; i++) {
                int a = l[2 * i], b = l[2 * i + 1];
                double d = Math.sqrt(Math.pow(p[3 * a] - p[3 * b], 2) + Math.pow(p[3 * a + 1] - p[3 * b + 1], 2)
                        + Math.pow(p[3 * a + 2] - p[3 * b + 2], 2));
                int k = (int) Math.round(d);
                assertEquals(k, d, 1e-12);
                assertTrue(k >= 1 && k <= 3);
                lengths[k]++;
            }
            assertArrayEquals(new int[] {0, 4, 4, 4}, lengths, "4 edges of each length");
            OrientedBoundingBox obb = OrientedBoundingBox.createFromAxisAlignedBoundingBox(new double[] {0, 0, 0},
                    new double[] {1, 2, 3});
            try (LineSet lo = LineSet.createFromOrientedBoundingBox(obb)) {
                assertArrayEquals(obb.getBoxPoints(), lo.getPoints(), 1e-12);
                assertEquals(12, lo.numLines());
            }
            ls.paintUniformColor(new double[] {1, 0.5, 0});
            assertEquals(36, ls.getColors().length);
            assertEquals(0.5, ls.getColors()[1], 0);
            ls.transform(new double[] {1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
            assertEquals(p[0] + 10, ls.getPoints()[0], 0);
            ByteBuffer view = ls.linesView();
            int[] copy = new int[24];
            view.asIntBuffer().get(copy);
            assertArrayEquals(ls.getLines(), copy);
            try (LineSet c = ls.copy()) {
                ls.setLines(new int[0]);
                assertEquals(12, c.numLines());
                assertEquals(0, ls.numLines());
            }
        }
        try (TriangleMesh box = TriangleMesh.createBox(); LineSet edges = LineSet.createFromTriangleMesh(box)) {
            assertEquals(8, edges.numPoints());
            assertEquals(18, edges.numLines(), "12 edges + 6 diagonals");
        }
        try (PointCloud a = new PointCloud(new double[] {0, 0, 0, 1, 0, 0});
             PointCloud b = new PointCloud(new double[] {0, 1, 0, 1, 1, 0, 2, 1, 0})) {
            try (LineSet corr = LineSet.createFromPointCloudCorrespondences(a, b, new int[] {0, 2, 1, 0})) {
                assertEquals(5, corr.numPoints());
                assertArrayEquals(new int[] {0, 4, 1, 2}, corr.getLines());
            }
            assertStatus(Status.INVALID_ARGUMENT, () -> LineSet.createFromPointCloudCorrespondences(a, b, new int[] {0, 3}));
            assertThrows(IllegalArgumentException.class, () -> LineSet.createFromPointCloudCorrespondences(a, b, new int[] {0}));
        }
        LineSet ls = new LineSet(new double[] {0, 0, 0, 1, 1, 1}, new int[] {0, 1});
        assertEquals(2, ls.numPoints());
        assertArrayEquals(new int[] {0, 1}, ls.getLines());
        assertThrows(IllegalArgumentException.class, () -> ls.setLines(new int[] {0, 1, 2}));
        ls.close();
        ls.close();
        assertThrows(IllegalStateException.class, ls::numLines);
    }

    @Test
    void voxelGrids() {
        try (PointCloud pc = new PointCloud(new double[] {0, 0, 0, 0.05, 0.05, 0.05, 1, 0, 0, 0, 0, 1})) {
            pc.setColors(new double[] {1, 0, 0, 0, 0, 1, 0, 1, 0, 1, 1, 1});
            try (VoxelGrid grid = VoxelGrid.createFromPointCloud(pc, 0.5)) {
                assertEquals(0.5, grid.voxelSize(), 0);
                assertArrayEquals(new double[] {-0.25, -0.25, -0.25}, grid.origin(), 1e-15);
                assertEquals(3, grid.numVoxels());
                Voxels v = grid.getVoxels();
                assertEquals(3, v.count());
                assertArrayEquals(new int[] {0, 0, 0, 0, 0, 2, 2, 0, 0}, v.gridIndices, "sorted grid indices");
                assertArrayEquals(new double[] {0.5, 0, 0.5, 1, 1, 1, 0, 1, 0}, v.colors, 1e-12, "mean colors");
                assertArrayEquals(new int[] {2, 0, 0}, grid.getVoxel(new double[] {1, 0, 0}));
                assertArrayEquals(new boolean[] {true, false}, grid.checkIfIncluded(new double[] {1, 0, 0, 0.5, 0.5, 0.5}));
                assertThrows(IllegalArgumentException.class, () -> grid.getVoxel(new double[] {1, 0}));
            }
            try (VoxelGrid grid = VoxelGrid.createFromPointCloudWithinBounds(pc, 1, new double[] {0, 0, 0},
                    new double[] {2, 2, 2})) {
                assertArrayEquals(new double[] {0, 0, 0}, grid.origin(), 0);
                assertArrayEquals(new int[] {0, 0, 0, 0, 0, 1, 1, 0, 0}, grid.getVoxels().gridIndices);
            }
            assertStatus(Status.INVALID_ARGUMENT, () -> VoxelGrid.createFromPointCloud(pc, 0));
            assertStatus(Status.INVALID_ARGUMENT, () -> VoxelGrid.createFromPointCloud(pc, Double.NaN));
        }
        try (TriangleMesh box = TriangleMesh.createBox(); VoxelGrid grid = VoxelGrid.createFromTriangleMesh(box, 0.5)) {
            assertEquals(26, grid.numVoxels(), "surface voxels of a unit box");
            assertArrayEquals(new boolean[] {false, true}, grid.checkIfIncluded(new double[] {0.5, 0.5, 0.5, 0, 0, 0}));
        }
    }

    @Test
    void octree() {
        try (PointCloud pc = new PointCloud(new double[] {0, 0, 0, 1, 1, 1, 0.1, 0.1, 0.1, 0.9, 0.9, 0.9, 0.2, 0.1, 0.1});
             Octree tree = new Octree(2)) {
            pc.setColors(new double[] {0.3, 0, 0, 1, 1, 1, 0.6, 0, 0, 0, 0, 0, 0, 0.9, 0});
            tree.convertFromPointCloud(pc);
            assertArrayEquals(new double[] {0, 0, 0}, tree.origin(), 0);
            assertEquals(1.01, tree.size(), 1e-12);
            assertEquals(2, tree.maxDepth());
            assertEquals(2, tree.numLeafNodes());
            OctreeLeaf leaf = tree.locateLeafNode(new double[] {0.05, 0.05, 0.05});
            assertNotNull(leaf);
            assertArrayEquals(new int[] {0, 2, 4}, leaf.indices);
            assertArrayEquals(new double[] {0.3, 0.3, 0}, leaf.color, 1e-12);
            assertArrayEquals(new double[] {0, 0, 0}, leaf.info.origin, 0);
            assertEquals(0.2525, leaf.info.size, 1e-12);
            assertEquals(2, leaf.info.depth);
            assertEquals(0, leaf.info.childIndex);
            leaf = tree.locateLeafNode(new double[] {0.95, 0.95, 0.95});
            assertNotNull(leaf);
            assertArrayEquals(new int[] {1, 3}, leaf.indices);
            assertEquals(7, leaf.info.childIndex);
            assertArrayEquals(new double[] {0.7575, 0.7575, 0.7575}, leaf.info.origin, 1e-12);
            assertNull(tree.locateLeafNode(new double[] {0.5, 0.5, 0.5}), "empty cell");
            assertNull(tree.locateLeafNode(new double[] {5, 5, 5}), "outside the root");
            assertStatus(Status.INVALID_ARGUMENT, () -> tree.locateLeafNode(new double[] {Double.NaN, 0, 0}));
            try (PointCloud empty = new PointCloud()) {
                assertStatus(Status.INVALID_ARGUMENT, () -> tree.convertFromPointCloud(empty));
            }
        }
        assertStatus(Status.INVALID_ARGUMENT, () -> new Octree(0));
    }

    @Test
    void covariances() {
        // A planar 10 x 10 patch: every neighbourhood covariance is singular (normal direction z).
        double[] grid = new double[300];
        for (int i = 0; i < 10; i++)
            for (int j = 0; j < 10; j++) {
                grid[3 * (10 * i + j)] = i * 0.1;
                grid[3 * (10 * i + j) + 1] = j * 0.1;
            }
        try (PointCloud pc = new PointCloud(grid)) {
            assertFalse(pc.hasCovariances());
            assertEquals(0, pc.getCovariances().length);
            pc.estimateCovariances(SearchParam.knn(10));
            assertTrue(pc.hasCovariances());
            double[] cov = pc.getCovariances();
            assertEquals(900, cov.length);
            for (int i = 0; i < 100; i++) {
                assertEquals(0, det3(cov, 9 * i), 1e-15, "det " + i);
                assertEquals(0, cov[9 * i + 8], 0, "zz " + i);
                assertTrue(cov[9 * i] > 0 && cov[9 * i + 4] > 0, "in-plane variance " + i);
                assertEquals(cov[9 * i + 1], cov[9 * i + 3], 1e-15, "symmetric " + i);
            }
            double[] viewed = new double[900];
            pc.covariancesView().asDoubleBuffer().get(viewed);
            assertArrayEquals(cov, viewed, 0);
            try (PointCloud some = pc.selectByIndex(new int[] {5, 7})) {
                double[] expect = new double[18];
                System.arraycopy(cov, 45, expect, 0, 9);
                System.arraycopy(cov, 63, expect, 9, 9);
                assertArrayEquals(expect, some.getCovariances(), 0);
            }
            // 90 degrees about x: C -> R C R^T moves the zero variance from z to y.
            pc.rotate(new double[] {1, 0, 0, 0, 0, -1, 0, 1, 0}, null);
            double[] rot = pc.getCovariances();
            assertEquals(0, rot[4], 1e-15);
            assertEquals(cov[4], rot[8], 1e-15);
            pc.setCovariances(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1});
            assertFalse(pc.hasCovariances(), "one matrix for 100 points");
            assertThrows(IllegalArgumentException.class, () -> pc.setCovariances(new double[10]));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.estimateCovariances(SearchParam.knn(0)));
        }
    }
}
