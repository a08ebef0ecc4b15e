// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

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
    static final int LP = Library.LINESET_POINTS, LL = Library.LINESET_LINES, LC = Library.LINESET_COLORS,
            COV = Library.POINTCLOUD_COVARIANCES;

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

    static double volume(OrientedBoundingBox b) {
        double[] e = b.getExtent();
        return e[0] * e[1] * e[2];
    }

    static OrientedBoundingBox obb(double[] center, double[] r, double[] extent) {
        OrientedBoundingBox b = new OrientedBoundingBox();
        b.setCenter(center);
        b.setR(r);
        b.setExtent(extent);
        return b;
    }

    static OrientedBoundingBox fromAabb(double[] min, double[] max) {
        return OrientedBoundingBox.createFromAxisAlignedBoundingBox(min, max);
    }

    @Test
    void convexHullOfCubeWithInteriorPoints() {
        double[] pts = cubeWithInterior();
        try (PointCloud pc = cloud(pts); PointcloudComputeConvexHullResult hull = pc.computeConvexHull(0); TriangleMesh m = hull.mesh()) {
            assertEquals(8, m.numVertices());
            assertEquals(12, m.numTriangles());
            assertEquals(1, m.getVolume(), 1e-12);
            assertTrue(m.isWatertight());
            int[] idx = hull.pointIndices();
            assertEquals(8, idx.length);
            double[] v = m.getArray(Library.MESH_VERTICES);
            for (int i = 0; i < 8; i++) {
                int k = idx[i];
                assertTrue(k >= 0 && k < 8, "hull vertex " + i + " is a corner: " + k);
                assertArrayEquals(Arrays.copyOfRange(pts, 3 * k, 3 * k + 3), Arrays.copyOfRange(v, 3 * i, 3 * i + 3), 0);
            }
            assertEquals(8, Arrays.stream(idx).distinct().count());
            assertInvalid(hull::mesh); // a result's handle is taken once
        }
        try (TriangleMesh box = TriangleMesh.createBox(1, 2, 3); TrianglemeshComputeConvexHullResult hull = box.computeConvexHull(0);
             TriangleMesh m = hull.mesh()) {
            assertEquals(6, m.getVolume(), 1e-12);
            assertEquals(12, m.numTriangles());
            assertEquals(8, hull.pointIndices().length);
        }
        try (PointCloud flat = cloud(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 0})) {
            assertThrows(O3dException.class, () -> flat.computeConvexHull(0));
            try (PointcloudComputeConvexHullResult j = flat.computeConvexHull(1); TriangleMesh m = j.mesh()) {
                assertTrue(m.numTriangles() > 0);
            }
        }
        try (PointCloud three = cloud(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0})) {
            assertThrows(O3dException.class, () -> three.computeConvexHull(1));
        }
        try (PointCloud empty = new PointCloud()) {
            assertThrows(O3dException.class, () -> empty.computeConvexHull(0));
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
        try (PointCloud pc = cloud(pts); HiddenPointRemovalResult res = pc.hiddenPointRemoval(new double[] {0, 0, 5}, 500);
             TriangleMesh m = res.mesh()) {
            int[] idx = res.pointIndices();
            assertTrue(idx.length > 20 && idx.length < 250, "visible " + idx.length);
            for (int i : idx) {
                assertTrue(i >= 0 && i < 400);
                assertTrue(pts[3 * i + 2] > 0, "visible point faces the camera");
            }
            assertTrue(m.numTriangles() > 0);
            assertInvalid(() -> pc.hiddenPointRemoval(new double[] {0, 0, 5}, -1));
            assertInvalid(() -> pc.hiddenPointRemoval(new double[] {0, 0}, 1));
        }
    }

    @Test
    void orientedBoundingBox() {
        OrientedBoundingBox aabb = fromAabb(new double[] {0, 0, 0}, new double[] {1, 2, 3});
        assertArrayEquals(new double[] {0.5, 1, 1.5}, aabb.getCenter(), 1e-15);
        assertArrayEquals(new double[] {1, 2, 3}, aabb.getExtent(), 1e-15);
        assertArrayEquals(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, aabb.getR(), 0);
        assertEquals(6, volume(aabb), 1e-12);
        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3, 1, 2, 3, 0, 2, 3, 1, 0, 3, 1, 2, 0},
                aabb.getBoxPoints(), 1e-12, "box points in Open3D's order");
        assertArrayEquals(new int[] {0, 2}, aabb.getPointIndicesWithin(new double[] {0.5, 0.5, 0.5, 2, 0, 0, 1, 2, 3, -0.1, 1, 1}));

        // PCA box of a 2 x 3 x 4 block: volume 24, extents {2, 3, 4}, orthonormal R.
        double[] pts = new double[3 * 10];
        for (int c = 0; c < 8; c++) {
            pts[3 * c] = 2 * (c & 1);
            pts[3 * c + 1] = 3 * ((c >> 1) & 1);
            pts[3 * c + 2] = 4 * ((c >> 2) & 1);
        }
        System.arraycopy(new double[] {1, 1.5, 2, 0.5, 0.5, 0.5}, 0, pts, 24, 6);
        OrientedBoundingBox obb = OrientedBoundingBox.createFromPoints(pts, 0);
        assertEquals(24, volume(obb), 1e-9);
        double[] e = obb.getExtent();
        Arrays.sort(e);
        assertArrayEquals(new double[] {2, 3, 4}, e, 1e-9);
        assertArrayEquals(new double[] {1, 1.5, 2}, obb.getCenter(), 1e-9);
        double[] rot = obb.getR();
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                assertEquals(i == j ? 1 : 0, rot[i] * rot[j] + rot[3 + i] * rot[3 + j] + rot[6 + i] * rot[6 + j], 1e-9);
        assertTrue(sameRows(obb.getBoxPoints(), Arrays.copyOf(pts, 24), 1e-9), "PCA box corners are the block's");
        try (PointCloud pc = cloud(pts); OrientedBoundingBox b = pc.getOrientedBoundingBox(0)) {
            assertEquals(24, volume(b), 1e-9);
        }
        try (TriangleMesh mesh = TriangleMesh.createBox(2, 3, 4); OrientedBoundingBox b = mesh.getOrientedBoundingBox(0)) {
            assertEquals(24, volume(b), 1e-9);
        }
        assertThrows(O3dException.class, () -> OrientedBoundingBox.createFromPoints(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, 0));
        double[] planar = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
        assertThrows(O3dException.class, () -> OrientedBoundingBox.createFromPoints(planar, 0));
        assertEquals(0, volume(OrientedBoundingBox.createFromPoints(planar, 1)), 1e-3);
        assertInvalid(() -> OrientedBoundingBox.createFromPoints(new double[] {0, 0, Double.NaN, 1, 0, 0, 0, 1, 0, 0, 0, 1}, 0));
        assertInvalid(() -> obb(new double[3], new double[8], new double[3]));
    }

    @Test
    void cropByOrientedBox() {
        // A box along the diagonal x = y (45 degrees about z), 2 long, 0.2 wide and high.
        double c = Math.sqrt(0.5);
        OrientedBoundingBox box = obb(new double[] {0, 0, 0}, new double[] {c, -c, 0, c, c, 0, 0, 0, 1}, new double[] {2, 0.2, 0.2});
        try (PointCloud pc = cloud(new double[] {0.5, 0.5, 0, -0.5, -0.5, 0, 0.5, -0.5, 0, 0, 0, 0})) {
            assertArrayEquals(new int[] {0, 1, 3}, box.getPointIndicesWithin(points(pc)));
            try (PointCloud inside = pc.cropObb(box, 0)) {
                assertTrue(sameRows(points(inside), new double[] {0.5, 0.5, 0, -0.5, -0.5, 0, 0, 0, 0}, 0));
            }
            try (PointCloud outside = pc.cropObb(box, 1)) {
                assertArrayEquals(new double[] {0.5, -0.5, 0}, points(outside), 0);
            }
            assertInvalid(() -> pc.cropObb(null, 0));
        }
        try (TriangleMesh mesh = box(); OrientedBoundingBox bottom = fromAabb(new double[] {-0.1, -0.1, -0.1}, new double[] {1.1, 1.1, 0.5});
             TriangleMesh cut = mesh.cropObb(bottom)) {
            assertEquals(4, cut.numVertices());
            assertEquals(2, cut.numTriangles());
            double[] v = cut.getArray(Library.MESH_VERTICES);
            for (int i = 0; i < 4; i++) assertEquals(0, v[3 * i + 2], 0);
        }
    }

    @Test
    void lineSets() {
        try (LineSet ls = LineSet.createFromAxisAlignedBoundingBox(new double[] {0, 0, 0}, new double[] {1, 2, 3})) {
            assertEquals(8, ls.numPoints());
            assertEquals(12, ls.numLines());
            double[] p = ls.getArray(LP);
            int[] l = ls.getIndexArray(LL);
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
            try (OrientedBoundingBox obb = fromAabb(new double[] {0, 0, 0}, new double[] {1, 2, 3});
                 LineSet lo = LineSet.createFromOrientedBoundingBox(obb)) {
                assertArrayEquals(obb.getBoxPoints(), lo.getArray(LP), 1e-12);
                assertEquals(12, lo.numLines());
            }
            ls.paintUniformColor(new double[] {1, 0.5, 0});
            assertEquals(36, ls.getArray(LC).length);
            assertEquals(0.5, ls.getArray(LC)[1], 0);
            ls.transform(new double[] {1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
            assertEquals(p[0] + 10, ls.getArray(LP)[0], 0);
            ByteBuffer view = ls.indexArrayView(LL);
            int[] copy = new int[24];
            view.asIntBuffer().get(copy);
            assertArrayEquals(ls.getIndexArray(LL), copy);
            assertTrue(view.isReadOnly());
            try (LineSet c = ls.clone()) {
                ls.setIndexArray(LL, new int[0]);
                assertEquals(12, c.numLines());
                assertEquals(0, ls.numLines());
            }
        }
        try (TriangleMesh box = box(); LineSet edges = LineSet.createFromTriangleMesh(box)) {
            assertEquals(8, edges.numPoints());
            assertEquals(18, edges.numLines(), "12 edges + 6 diagonals");
        }
        try (PointCloud a = cloud(new double[] {0, 0, 0, 1, 0, 0}); PointCloud b = cloud(new double[] {0, 1, 0, 1, 1, 0, 2, 1, 0})) {
            try (LineSet corr = LineSet.createFromPointCloudCorrespondences(a, b, new int[] {0, 2, 1, 0})) {
                assertEquals(5, corr.numPoints());
                assertArrayEquals(new int[] {0, 4, 1, 2}, corr.getIndexArray(LL));
            }
            assertInvalid(() -> LineSet.createFromPointCloudCorrespondences(a, b, new int[] {0, 3}));
            assertInvalid(() -> LineSet.createFromPointCloudCorrespondences(a, b, new int[] {0}));
        }
        LineSet ls = new LineSet();
        ls.setArray(LP, new double[] {0, 0, 0, 1, 1, 1});
        ls.setIndexArray(LL, new int[] {0, 1});
        assertEquals(2, ls.numPoints());
        assertArrayEquals(new int[] {0, 1}, ls.getIndexArray(LL));
        assertInvalid(() -> ls.setIndexArray(LL, new int[] {0, 1, 2}));
        ls.close();
        ls.close();
        assertThrows(IllegalStateException.class, ls::numLines);
    }

    @Test
    void voxelGrids() {
        try (PointCloud pc = cloud(new double[] {0, 0, 0, 0.05, 0.05, 0.05, 1, 0, 0, 0, 0, 1})) {
            pc.setArray(Library.POINTCLOUD_COLORS, new double[] {1, 0, 0, 0, 0, 1, 0, 1, 0, 1, 1, 1});
            try (VoxelGrid grid = VoxelGrid.createFromPointCloud(pc, 0.5)) {
                assertEquals(0.5, grid.getVoxelSize(), 0);
                assertArrayEquals(new double[] {-0.25, -0.25, -0.25}, grid.getOrigin(), 1e-15);
                assertEquals(3, grid.numVoxels());
                assertTrue(grid.hasArray(Library.VOXELGRID_COLORS));
                assertArrayEquals(new int[] {0, 0, 0, 0, 0, 2, 2, 0, 0}, grid.getIndexArray(Library.VOXELGRID_GRID_INDEX), "sorted grid indices");
                assertArrayEquals(new double[] {0.5, 0, 0.5, 1, 1, 1, 0, 1, 0}, grid.getArray(Library.VOXELGRID_COLORS), 1e-12, "mean colors");
                assertArrayEquals(new int[] {2, 0, 0}, grid.getVoxel(new double[] {1, 0, 0}));
                assertArrayEquals(new int[] {1, 0}, grid.checkIfIncluded(new double[] {1, 0, 0, 0.5, 0.5, 0.5}));
                assertInvalid(() -> grid.getVoxel(new double[] {1, 0}));
            }
            try (VoxelGrid grid = VoxelGrid.createFromPointCloudWithinBounds(pc, 1, new double[] {0, 0, 0}, new double[] {2, 2, 2})) {
                assertArrayEquals(new double[] {0, 0, 0}, grid.getOrigin(), 0);
                assertArrayEquals(new int[] {0, 0, 0, 0, 0, 1, 1, 0, 0}, grid.getIndexArray(Library.VOXELGRID_GRID_INDEX));
            }
            assertInvalid(() -> VoxelGrid.createFromPointCloud(pc, 0));
            assertInvalid(() -> VoxelGrid.createFromPointCloud(pc, Double.NaN));
        }
        try (TriangleMesh box = box(); VoxelGrid grid = VoxelGrid.createFromTriangleMesh(box, 0.5)) {
            assertEquals(26, grid.numVoxels(), "surface voxels of a unit box");
            assertArrayEquals(new int[] {0, 1}, grid.checkIfIncluded(new double[] {0.5, 0.5, 0.5, 0, 0, 0}));
        }
    }

    @Test
    void octree() {
        try (PointCloud pc = cloud(new double[] {0, 0, 0, 1, 1, 1, 0.1, 0.1, 0.1, 0.9, 0.9, 0.9, 0.2, 0.1, 0.1});
             Octree tree = Octree.create(2)) {
            pc.setArray(Library.POINTCLOUD_COLORS, new double[] {0.3, 0, 0, 1, 1, 1, 0.6, 0, 0, 0, 0, 0, 0, 0.9, 0});
            tree.convertFromPointCloud(pc, 0.01);
            try (GetRootResult root = tree.getRoot()) {
                assertArrayEquals(new double[] {0, 0, 0}, root.origin(), 0);
                assertEquals(1.01, root.size(), 1e-12);
                assertEquals(2, root.maxDepth());
            }
            assertEquals(2, tree.numLeafNodes());
            try (PointCloud empty = new PointCloud()) {
                assertInvalid(() -> tree.convertFromPointCloud(empty, 0.01));
            }
        }
        assertInvalid(() -> Octree.create(0));
    }

    /** Pending: the generator turns o3d_octree_locate_leaf_node's scalar `int32_t* out_found` into an array output. */
    @Test
    void octreeLocateLeafNode() {
        try (PointCloud pc = cloud(new double[] {0, 0, 0, 1, 1, 1, 0.1, 0.1, 0.1, 0.9, 0.9, 0.9, 0.2, 0.1, 0.1});
             Octree tree = Octree.create(2)) {
            pc.setArray(Library.POINTCLOUD_COLORS, new double[] {0.3, 0, 0, 1, 1, 1, 0.6, 0, 0, 0, 0, 0, 0, 0.9, 0});
            tree.convertFromPointCloud(pc, 0.01);
            try (LocateLeafNodeResult leaf = tree.locateLeafNode(new double[] {0.05, 0.05, 0.05}); OctreeNodeInfo info = leaf.info()) {
                assertTrue(leaf.found());
                assertArrayEquals(new int[] {0, 2, 4}, leaf.indices());
                assertArrayEquals(new double[] {0.3, 0.3, 0}, leaf.color(), 1e-12);
                assertArrayEquals(new double[] {0, 0, 0}, info.getOrigin(), 0);
                assertEquals(0.2525, info.getSize(), 1e-12);
                assertEquals(2, info.getDepth());
                assertEquals(0, info.getChildIndex());
            }
            try (LocateLeafNodeResult leaf = tree.locateLeafNode(new double[] {0.95, 0.95, 0.95}); OctreeNodeInfo info = leaf.info()) {
                assertTrue(leaf.found());
                assertArrayEquals(new int[] {1, 3}, leaf.indices());
                assertEquals(7, info.getChildIndex());
                assertArrayEquals(new double[] {0.7575, 0.7575, 0.7575}, info.getOrigin(), 1e-12);
            }
            try (LocateLeafNodeResult leaf = tree.locateLeafNode(new double[] {0.5, 0.5, 0.5})) {
                assertFalse(leaf.found(), "empty cell");
            }
            try (LocateLeafNodeResult leaf = tree.locateLeafNode(new double[] {5, 5, 5})) {
                assertFalse(leaf.found(), "outside the root");
            }
            assertInvalid(() -> tree.locateLeafNode(new double[] {Double.NaN, 0, 0}));
        }
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
        try (PointCloud pc = cloud(grid); SearchParam k10 = knn(10)) {
            assertFalse(pc.hasArray(COV));
            assertEquals(0, pc.getArray(COV).length);
            pc.estimateCovariances(k10);
            assertTrue(pc.hasArray(COV));
            double[] cov = pc.getArray(COV);
            assertEquals(900, cov.length);
            for (int i = 0; i < 100; i++) {
                assertEquals(0, det3(cov, 9 * i), 1e-15, "det " + i);
                assertEquals(0, cov[9 * i + 8], 0, "zz " + i);
                assertTrue(cov[9 * i] > 0 && cov[9 * i + 4] > 0, "in-plane variance " + i);
                assertEquals(cov[9 * i + 1], cov[9 * i + 3], 1e-15, "symmetric " + i);
            }
            double[] viewed = new double[900];
            pc.arrayView(COV).asDoubleBuffer().get(viewed);
            assertArrayEquals(cov, viewed, 0);
            try (PointCloud some = pc.selectByIndex(new int[] {5, 7}, 0)) {
                double[] expect = new double[18];
                System.arraycopy(cov, 45, expect, 0, 9);
                System.arraycopy(cov, 63, expect, 9, 9);
                assertArrayEquals(expect, some.getArray(COV), 0);
            }
            // 90 degrees about x: C -> R C R^T moves the zero variance from z to y.
            pc.rotate(new double[] {1, 0, 0, 0, 0, -1, 0, 1, 0}, null);
            double[] rot = pc.getArray(COV);
            assertEquals(0, rot[4], 1e-15);
            assertEquals(cov[4], rot[8], 1e-15);
            pc.setArray(COV, new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1});
            assertFalse(pc.hasArray(COV), "one matrix for 100 points");
            assertInvalid(() -> pc.setArray(COV, new double[10]));
            assertInvalid(() -> pc.setArray(COV, new double[] {1, 2, 0, 0, 1, 0, 0, 0, 1}));
            try (SearchParam k0 = knn(0)) {
                assertInvalid(() -> pc.estimateCovariances(k0));
            }
        }
    }
}
