// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import java.util.Arrays;
import java.util.HashSet;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * Surface reconstruction, tetra meshes, consistent normal orientation, duplicated points and ISS keypoints through
 * the generated classes only: the same scenarios as bindings/csharp/tests/SurfaceReconstructionTest.cs. Poisson
 * and ball pivoting rebuild a sampled sphere, a huge alpha gives the convex hull, the Delaunay tetra mesh of a cube
 * fills it, progress rises and cancels, and bad input throws O3dException.
 */
class SurfaceReconstructionTest {
    /**
     * {@code n} points spread evenly over the sphere of {@code radius} about the origin (a Fibonacci lattice, spacing
     * about radius * sqrt(4 pi / n)), with outward unit normals.
     */
    static PointCloud sphereCloud(int n, double radius) {
        double golden = Math.PI * (3 - Math.sqrt(5));
        double[] p = new double[3 * n], nrm = new double[3 * n];
        for (int i = 0; i < n; i++) {
            double z = 1 - (2.0 * i + 1) / n, r = Math.sqrt(1 - z * z), phi = golden * i;
            nrm[3 * i] = r * Math.cos(phi);
            nrm[3 * i + 1] = r * Math.sin(phi);
            nrm[3 * i + 2] = z;
            for (int k = 0; k < 3; k++) p[3 * i + k] = radius * nrm[3 * i + k];
        }
        PointCloud pc = cloud(p);
        pc.setArray(Library.POINTCLOUD_NORMALS, nrm);
        return pc;
    }

    static double norm3(double[] a, int i) {
        return Math.sqrt(a[3 * i] * a[3 * i] + a[3 * i + 1] * a[3 * i + 1] + a[3 * i + 2] * a[3 * i + 2]);
    }

    /** Sum of |det| / 6 over the tetras. */
    static double tetraVolume(TetraMesh t) {
        double[] v = t.getArray(Library.TETRAMESH_VERTICES);
        int[] q = t.getIndexArray(Library.TETRAMESH_TETRAS);
        double total = 0;
        for (int i = 0; i < q.length; i += 4) {
            double[] m = new double[9];  // the three edges from the first vertex, as rows
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++) m[3 * r + c] = v[3 * q[i + r + 1] + c] - v[3 * q[i] + c];
            double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6])
                    + m[2] * (m[3] * m[7] - m[4] * m[6]);
            total += Math.abs(det) / 6;
        }
        return total;
    }

    /** The 8 corners of [0,1]^3, index = x + 2y + 4z. */
    static double[] cubeCorners() {
        double[] p = new double[24];
        for (int c = 0; c < 8; c++) {
            p[3 * c] = c & 1;
            p[3 * c + 1] = (c >> 1) & 1;
            p[3 * c + 2] = (c >> 2) & 1;
        }
        return p;
    }

    @Test
    void poissonOfASphereIsAClosedSphereAndProgressCancels() {
        try (PointCloud pc = sphereCloud(2000, 2); PoissonOptions opts = new PoissonOptions()) {
            assertEquals(8, opts.getDepth());
            assertEquals(1.1, opts.getScale());
            assertEquals(0, opts.getLinearFit());
            opts.setDepth(6);
            double[] last = {-1};
            boolean[] rising = {true};
            opts.setProgress(f -> {
                rising[0] &= f >= last[0] && f <= 1;
                last[0] = f;
                return true;
            });
            try (CreateFromPointCloudPoissonResult res = TriangleMesh.createFromPointCloudPoisson(pc, opts);
                    TriangleMesh mesh = res.mesh(); Feature densities = res.densities()) {
                assertTrue(mesh.numTriangles() > 100);
                assertEquals(1, densities.dimension());
                assertEquals(mesh.numVertices(), densities.num());
                for (double d : densities.getArray(Library.FEATURE_DATA)) assertTrue(Double.isFinite(d));
                double[] v = mesh.getArray(Library.MESH_VERTICES);
                // Cells at depth 6 of a 4.4-wide cube are 0.07 wide: the vertices lie on the sphere to a fraction of that.
                for (int i = 0; i < v.length / 3; i++) assertEquals(2, norm3(v, i), 0.05, "vertex " + i);
                assertTrue(mesh.isEdgeManifold(0), "closed");
                assertEquals(2, mesh.eulerPoincareCharacteristic(), "a sphere's topology");
                double ball = 4.0 / 3 * Math.PI * 8;
                assertEquals(ball, mesh.getVolume(), 0.01 * ball);
                // Open3D's trim: drop the vertices whose density is below a quantile.
                double[] d = densities.getArray(Library.FEATURE_DATA);
                double cut = Arrays.stream(d).sorted().toArray()[d.length / 10];
                byte[] low = new byte[d.length];
                int nLow = 0;
                for (int i = 0; i < d.length; i++)
                    if (d[i] < cut) {
                        low[i] = 1;
                        nLow++;
                    }
                long before = mesh.numVertices();
                mesh.removeVerticesByMask(low);
                assertEquals(before - nLow, mesh.numVertices());
            }
            assertTrue(last[0] >= 0 && rising[0], "progress rises within [0, 1]");
            opts.setProgress(f -> false);
            assertStatus(Library.ERROR_CANCELLED, () -> TriangleMesh.createFromPointCloudPoisson(pc, opts));
            opts.setProgress(null);
            opts.setDepth(17);
            assertInvalid(() -> TriangleMesh.createFromPointCloudPoisson(pc, opts));
        }
        try (PointCloud bare = cloud(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1})) {
            assertInvalid(() -> TriangleMesh.createFromPointCloudPoisson(bare, null));
        }
        assertInvalid(() -> TriangleMesh.createFromPointCloudPoisson(null, null));
    }

    @Test
    void ballPivotingCoversADenseSphereWithItsOwnPoints() {
        // 4000 points on the unit sphere are about 0.056 apart: balls of twice and three times that close it.
        try (PointCloud pc = sphereCloud(4000, 1)) {
            try (TriangleMesh mesh = TriangleMesh.createFromPointCloudBallPivoting(pc, new double[] {0.1, 0.15}, null)) {
                assertArrayEquals(points(pc), mesh.getArray(Library.MESH_VERTICES));
                assertTrue(mesh.isEdgeManifold(0), "closed");
                assertEquals(2, mesh.eulerPoincareCharacteristic(), "a sphere's topology");
                assertEquals(4 * Math.PI, mesh.getSurfaceArea(), 0.01 * 4 * Math.PI);
            }
            try (ProgressOptions opts = new ProgressOptions()) {
                assertEquals(0, opts.getNumThreads());
                int[] calls = {0};
                opts.setProgress(f -> {
                    calls[0]++;
                    return true;
                });
                try (TriangleMesh mesh = TriangleMesh.createFromPointCloudBallPivoting(pc, new double[] {0.1, 0.15}, opts)) {
                    assertTrue(mesh.numTriangles() > 7000);
                }
                assertTrue(calls[0] > 0);
                opts.setProgress(f -> false);
                assertStatus(Library.ERROR_CANCELLED,
                        () -> TriangleMesh.createFromPointCloudBallPivoting(pc, new double[] {0.1}, opts));
            }
            assertInvalid(() -> TriangleMesh.createFromPointCloudBallPivoting(pc, new double[0], null));
            assertInvalid(() -> TriangleMesh.createFromPointCloudBallPivoting(pc, new double[] {0.1, -0.2}, null));
        }
    }

    @Test
    void alphaShapeWithAHugeAlphaIsTheConvexHull() {
        // Random points in a cube: in general position, so the hull's faces are triangles.
        try (PointCloud pc = cloud(randomPoints(400, 5, 1, 1, 1)); PointcloudComputeConvexHullResult hull = pc.computeConvexHull(0);
                TriangleMesh hullMesh = hull.mesh();
                TriangleMesh shape = TriangleMesh.createFromPointCloudAlphaShape(pc, 1e6, null, null, null)) {
            assertEquals(hullMesh.numTriangles(), shape.numTriangles());
            // The alpha is beyond every circumradius: even the flat slivers on the hull (four nearly coplanar points,
            // radii up to ~1e3 for such samplings) are in, so the shape is the whole Delaunay volume.
            assertEquals(hullMesh.getSurfaceArea(), shape.getSurfaceArea(), 1e-9);
            assertEquals(hullMesh.getVolume(), shape.getVolume(), 1e-9);
            try (CreateFromPointCloudResult tetra = TetraMesh.createFromPointCloud(pc); TetraMesh t = tetra.value()) {
                int[] map = tetra.pointMap();
                for (double alpha : new double[] {0.3, 1e6}) {
                    try (TriangleMesh fresh = TriangleMesh.createFromPointCloudAlphaShape(pc, alpha, null, null, null);
                            TriangleMesh reused = TriangleMesh.createFromPointCloudAlphaShape(pc, alpha, t, map, null)) {
                        assertEquals(fresh.numTriangles(), reused.numTriangles(), "alpha " + alpha);
                        assertEquals(fresh.getSurfaceArea(), reused.getSurfaceArea(), 1e-9, "alpha " + alpha);
                    }
                }
                assertInvalid(() -> TriangleMesh.createFromPointCloudAlphaShape(pc, 1, t, Arrays.copyOf(map, map.length - 1), null));
            }
            try (TriangleMesh none = TriangleMesh.createFromPointCloudAlphaShape(pc, 1e-4, null, null, null)) {
                assertEquals(0, none.numTriangles(), "no tetra is that small");
            }
            try (ProgressOptions opts = new ProgressOptions()) {
                opts.setProgress(f -> false);
                assertStatus(Library.ERROR_CANCELLED, () -> TriangleMesh.createFromPointCloudAlphaShape(pc, 0.5, null, null, opts));
            }
            assertInvalid(() -> TriangleMesh.createFromPointCloudAlphaShape(pc, 0, null, null, null));
            assertInvalid(() -> TriangleMesh.createFromPointCloudAlphaShape(pc, -1, null, null, null));
        }
    }

    @Test
    void tetraMeshOfACubeFillsItAndCutsAPlane() {
        double[] corners = cubeCorners();
        try (PointCloud pc = cloud(corners); CreateFromPointCloudResult res = TetraMesh.createFromPointCloud(pc);
                TetraMesh t = res.value()) {
            assertEquals(8, t.numVertices());
            assertTrue(t.numTetras() == 5 || t.numTetras() == 6, "tetras: " + t.numTetras());
            assertEquals(1, tetraVolume(t), 1e-12);
            int[] map = res.pointMap();
            assertArrayEquals(range(0, 8), Arrays.stream(map).sorted().toArray());
            double[] v = t.getArray(Library.TETRAMESH_VERTICES);
            for (int i = 0; i < 8; i++)
                for (int k = 0; k < 3; k++) assertEquals(corners[3 * map[i] + k], v[3 * i + k], "vertex " + i);
            // z = 0.5 cuts the cube in the unit square.
            double[] z = new double[8];
            for (int i = 0; i < 8; i++) z[i] = v[3 * i + 2];
            try (TriangleMesh square = t.extractTriangleMesh(z, 0.5)) {
                assertEquals(1, square.getSurfaceArea(), 1e-9);
                double[] sv = square.getArray(Library.MESH_VERTICES);
                for (int i = 0; i < sv.length / 3; i++) assertEquals(0.5, sv[3 * i + 2], 1e-12);
            }
            assertInvalid(() -> t.extractTriangleMesh(new double[7], 0.5));
            try (TetraMesh copy = t.clone()) {
                copy.setIndexArray(Library.TETRAMESH_TETRAS, new int[] {0, 1, 2, 8});
                assertEquals(1, copy.numTetras());
                assertTrue(t.numTetras() >= 5, "clone is deep");
                assertInvalid(() -> copy.extractTriangleMesh(z, 0.5));
            }
        }
        try (TetraMesh t = new TetraMesh()) {
            t.setArray(Library.TETRAMESH_VERTICES, new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
            t.setIndexArray(Library.TETRAMESH_TETRAS, new int[] {0, 1, 2, 3});
            try (TetrameshArrayShapeResult shape = t.arrayShape(Library.TETRAMESH_TETRAS)) {
                assertEquals(1, shape.rows());
                assertEquals(4, shape.cols());
            }
            assertEquals(1.0 / 6, tetraVolume(t), 1e-15);
            assertInvalid(() -> t.setIndexArray(Library.TETRAMESH_TETRAS, new int[] {0, 1, 2}));
        }
        try (PointCloud flat = cloud(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.3, 0.6, 0})) {
            assertInvalid(() -> TetraMesh.createFromPointCloud(flat));
        }
    }

    @Test
    void consistentTangentPlaneNormalsAgreeOnASphere() {
        try (PointCloud pc = sphereCloud(1000, 1)) {
            double[] n = pc.getArray(Library.POINTCLOUD_NORMALS);
            Random rng = new Random(3);
            for (int i = 0; i < n.length / 3; i++)
                if (rng.nextBoolean())
                    for (int k = 0; k < 3; k++) n[3 * i + k] = -n[3 * i + k];
            pc.setArray(Library.POINTCLOUD_NORMALS, n);
            pc.orientNormalsConsistentTangentPlane(10, 0, 1);
            double[] p = points(pc), got = pc.getArray(Library.POINTCLOUD_NORMALS);
            double sign = got[0] * p[0] + got[1] * p[1] + got[2] * p[2];
            for (int i = 0; i < got.length / 3; i++) {
                double d = got[3 * i] * p[3 * i] + got[3 * i + 1] * p[3 * i + 1] + got[3 * i + 2] * p[3 * i + 2];
                assertEquals(1, d * sign, 1e-12, "normal " + i);
            }
            assertInvalid(() -> pc.orientNormalsConsistentTangentPlane(0, 0, 1));
        }
        try (PointCloud bare = cloud(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0})) {
            assertInvalid(() -> bare.orientNormalsConsistentTangentPlane(5, 0, 1));
        }
    }

    @Test
    void removeDuplicatedPointsKeepsTheFirstOfEach() {
        try (PointCloud pc = cloud(new double[] {0, 0, 0, 1, 2, 3, 0, 0, 0, 4, 5, 6, 1, 2, 3})) {
            pc.setArray(Library.POINTCLOUD_COLORS, new double[] {0, 0, 0, 0.1, 0, 0, 0.2, 0, 0, 0.3, 0, 0, 0.4, 0, 0});
            pc.removeDuplicatedPoints();
            assertArrayEquals(new double[] {0, 0, 0, 1, 2, 3, 4, 5, 6}, points(pc));
            assertArrayEquals(new double[] {0, 0, 0, 0.1, 0, 0, 0.3, 0, 0}, pc.getArray(Library.POINTCLOUD_COLORS));
        }
    }

    @Test
    void issKeypointsOfABoxAreAtItsCorners() {
        // The surface of the unit cube on a grid of 21 points a side.
        double[] pts = new double[3 * (21 * 21 * 21 - 19 * 19 * 19)];
        int n = 0;
        for (int i = 0; i <= 20; i++)
            for (int j = 0; j <= 20; j++)
                for (int k = 0; k <= 20; k++)
                    if (i == 0 || i == 20 || j == 0 || j == 20 || k == 0 || k == 20) {
                        pts[n++] = i / 20.0;
                        pts[n++] = j / 20.0;
                        pts[n++] = k / 20.0;
                    }
        try (PointCloud pc = cloud(pts); IssOptions opts = new IssOptions()) {
            assertEquals(0, opts.getSalientRadius());
            assertEquals(0, opts.getNonMaxRadius());
            assertEquals(0.975, opts.getGamma21());
            assertEquals(0.975, opts.getGamma32());
            assertEquals(5, opts.getMinNeighbors());
            opts.setSalientRadius(0.2);
            opts.setNonMaxRadius(0.6);
            try (ComputeIssKeypointsResult res = pc.computeIssKeypoints(opts); PointCloud kp = res.cloud()) {
                int[] idx = res.indices();
                double[] k = points(kp);
                assertTrue(idx.length > 0);
                assertEquals(kp.size(), idx.length);
                Set<Integer> corners = new HashSet<>();
                for (int i = 0; i < idx.length; i++) {
                    double d2 = 0;
                    for (int c = 0; c < 3; c++) {
                        assertEquals(pts[3 * idx[i] + c], k[3 * i + c], "index names the point");
                        double m = Math.min(k[3 * i + c], 1 - k[3 * i + c]);
                        d2 += m * m;
                    }
                    assertTrue(Math.sqrt(d2) < 0.2, "keypoint " + i + " near a corner");
                    corners.add((k[3 * i] > 0.5 ? 1 : 0) + (k[3 * i + 1] > 0.5 ? 2 : 0) + (k[3 * i + 2] > 0.5 ? 4 : 0));
                }
                assertEquals(8, corners.size(), "every corner has one");
            }
            opts.setSalientRadius(-1);
            assertInvalid(() -> pc.computeIssKeypoints(opts));
        }
    }
}
