// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;

/** JUnit 5 tests of the generated Java binding (the same behaviours as bindings/csharp/tests/Test.cs). */
class O3dTest {
    static double[] randomPoints(int n, long seed, double sx, double sy, double sz) {
        Random r = new Random(seed);
        double[] p = new double[3 * n];
        for (int i = 0; i < n; i++) {
            p[3 * i] = r.nextDouble() * sx;
            p[3 * i + 1] = r.nextDouble() * sy;
            p[3 * i + 2] = r.nextDouble() * sz;
        }
        return p;
    }

    static double[] applyTransform(double[] t, double[] p) {
        double[] q = new double[p.length];
        for (int i = 0; i < p.length / 3; i++)
            for (int r = 0; r < 3; r++)
                q[3 * i + r] = t[4 * r] * p[3 * i] + t[4 * r + 1] * p[3 * i + 1] + t[4 * r + 2] * p[3 * i + 2] + t[4 * r + 3];
        return q;
    }

    static PointCloud cloud(double[] pts) {
        PointCloud pc = new PointCloud();
        pc.setArray(Library.POINTCLOUD_POINTS, pts);
        return pc;
    }

    static O3dException throwsStatus(int status, org.junit.jupiter.api.function.Executable e) {
        O3dException ex = assertThrows(O3dException.class, e);
        assertEquals(status, ex.getStatus(), ex.getMessage());
        assertFalse(ex.getMessage().isEmpty());
        return ex;
    }

    @Test
    void versionAndStatus() {
        assertEquals(Library.VERSION_MAJOR, Library.versionMajor());
        assertEquals(Library.versionMajor() + "." + Library.versionMinor() + "." + Library.versionPatch(), Library.version());
        assertEquals("O3D_ERROR_IO", Library.statusString(Library.ERROR_IO));
    }

    @Test
    void arraysRoundTrip() {
        double[] pts = {1, 2, 3, 4.5, -5.25, 6, 1e-3, 7, -8};
        try (PointCloud pc = new PointCloud()) {
            assertEquals(0, pc.size());
            assertFalse(pc.hasArray(Library.POINTCLOUD_POINTS));
            pc.setArray(Library.POINTCLOUD_POINTS, pts);
            assertEquals(3, pc.size());
            assertArrayEquals(pts, pc.getArray(Library.POINTCLOUD_POINTS), 0);
            pts[0] = 99;
            assertEquals(1, pc.getArray(Library.POINTCLOUD_POINTS)[0], 0, "the cloud holds a copy");
            float[] f = {0.5f, 1.25f, -2f, 3f, 4f, 5.5f};
            pc.setArray(Library.POINTCLOUD_POINTS, f);
            assertEquals(2, pc.size());
            assertArrayEquals(new double[] {0.5, 1.25, -2, 3, 4, 5.5}, pc.getArray(Library.POINTCLOUD_POINTS), 0);
            throwsStatus(Library.ERROR_INVALID_ARGUMENT, () -> pc.setArray(Library.POINTCLOUD_POINTS, new double[4]));
            try (PointCloud c = pc.clone()) {
                pc.clear();
                assertEquals(0, pc.size());
                assertEquals(2, c.size(), "clone is deep");
            }
        }
    }

    @Test
    void voxelDownSampleAverages() {
        double[] pts = {0, 0, 0, 0.1, 0, 0, 0, 0.1, 0.2, 5, 5, 5, 5.2, 5, 5};
        try (PointCloud pc = cloud(pts); PointCloud down = pc.voxelDownSample(1.0)) {
            assertEquals(2, down.size());
            double[] d = down.getArray(Library.POINTCLOUD_POINTS);
            int a = d[0] < d[3] ? 0 : 1, b = 1 - a;
            assertArrayEquals(new double[] {0.1 / 3, 0.1 / 3, 0.2 / 3}, java.util.Arrays.copyOfRange(d, 3 * a, 3 * a + 3), 1e-12);
            assertArrayEquals(new double[] {5.1, 5, 5}, java.util.Arrays.copyOfRange(d, 3 * b, 3 * b + 3), 1e-12);
        }
    }

    @Test
    void knnMatchesBruteForce() {
        double[] pts = randomPoints(500, 1, 1, 1, 1), queries = randomPoints(20, 2, 1, 1, 1);
        int k = 5;
        try (KDTreeFlann tree = KDTreeFlann.createFromPoints(pts); SearchParam p = new SearchParam()) {
            p.setKind(Library.SEARCH_KNN);
            p.setKnn(k);
            try (SearchResult res = tree.search(queries, p, 0)) {
                int[] idx = res.getIndices();
                long[] off = res.getOffsets();
                assertEquals(20 * k, idx.length);
                assertEquals(21, off.length);
                for (int q = 0; q < 20; q++) {
                    final int qq = q;
                    int[] expect = IntStream.range(0, 500).boxed().sorted((x, y) -> Double.compare(d2(pts, x, queries, qq), d2(pts, y, queries, qq)))
                            .limit(k).mapToInt(Integer::intValue).toArray();
                    assertEquals(q * k, off[q]);
                    for (int j = 0; j < k; j++) assertEquals(expect[j], idx[q * k + j]);
                }
            }
        }
    }

    static double d2(double[] p, int i, double[] q, int j) {
        double dx = p[3 * i] - q[3 * j], dy = p[3 * i + 1] - q[3 * j + 1], dz = p[3 * i + 2] - q[3 * j + 2];
        return dx * dx + dy * dy + dz * dz;
    }

    @Test
    void icpRecoversTransformAndCallbackCancels() {
        double[] src = randomPoints(800, 3, 1.0, 2.0, 0.5);
        double a = 5 * Math.PI / 180, c = Math.cos(a), s = Math.sin(a);
        double[] t = {c, -s, 0, 0.05, s, c, 0, -0.03, 0, 0, 1, 0.02, 0, 0, 0, 1};
        try (PointCloud source = cloud(src); PointCloud target = cloud(applyTransform(t, src)); IcpOptions opts = new IcpOptions()) {
            assertEquals(Library.ESTIMATION_POINT_TO_POINT, opts.getEstimation(), "defaults from o3d_icp_options_init");
            opts.setMaxIteration(100);
            opts.setRelativeFitness(1e-10);
            opts.setRelativeRmse(1e-10);
            int[] calls = {0};
            opts.setProgress(f -> { calls[0]++; return true; });
            try (RegistrationResult r = Library.registerIcp(source, target, 0.3, null, opts)) {
                assertArrayEquals(t, r.getTransformation(), 1e-4);
                assertEquals(1, r.getFitness(), 1e-9);
                assertEquals(2 * 800, r.getCorrespondenceSet().length);
            }
            assertTrue(calls[0] > 0, "progress called");
            opts.setProgress(f -> false);
            throwsStatus(Library.ERROR_CANCELLED, () -> Library.registerIcp(source, target, 0.3, null, opts));
            opts.setProgress(f -> { throw new IllegalStateException("boom"); });
            throwsStatus(Library.ERROR_CANCELLED, () -> Library.registerIcp(source, target, 0.3, null, opts));
            opts.setProgress(null);
            try (RegistrationResult r = Library.registerIcp(source, target, 0.3, null, opts)) {
                assertEquals(1, r.getFitness(), 1e-9);
            }
        }
    }

    @Test
    void memoryRoundTripAndErrors() {
        double[] pts = randomPoints(100, 4, 1, 1, 1);
        try (PointCloud pc = cloud(pts); Buffer buf = Library.ioWritePointCloudToMemory(pc, "pcd", null)) {
            byte[] bytes = buf.getData();
            assertTrue(bytes.length > 100 * 3 * 4);
            try (PointCloud back = Library.ioReadPointCloudFromMemory(bytes, "pcd", null)) {
                assertArrayEquals(pts, back.getArray(Library.POINTCLOUD_POINTS), 1e-5);
            }
            throwsStatus(Library.ERROR_INVALID_ARGUMENT, () -> pc.voxelDownSample(Double.NaN));
            throwsStatus(Library.ERROR_INVALID_ARGUMENT, () -> pc.selectByIndex(new int[] {500}, 0));
            assertEquals(Library.ERROR_INVALID_ARGUMENT, Library.lastErrorCode());
            Library.clearError();
            assertEquals(Library.OK, Library.lastErrorCode());
        }
        O3dException e = throwsStatus(Library.ERROR_IO, () -> Library.ioReadPointCloud("/nonexistent/x.pcd", null, null));
        assertTrue(e.getMessage().contains("O3D_ERROR_IO"), e.getMessage());
        throwsStatus(Library.ERROR_PARSE, () -> Library.ioReadPointCloudFromMemory("ply\nformat garbage\n".getBytes(StandardCharsets.US_ASCII), "ply", null));
    }

    @Test
    void closeIsIdempotent() {
        PointCloud pc = cloud(new double[] {1, 2, 3});
        KDTreeFlann tree = KDTreeFlann.createFromPointcloud(pc);
        pc.close();
        pc.close();
        assertThrows(IllegalStateException.class, pc::size);
        assertEquals(1, tree.size(), "tree outlives its cloud");
        tree.close();
        tree.close();
        assertThrows(IllegalStateException.class, tree::size);
    }

    @Test
    void resultsWithSeveralOutputs() {
        List<Double> p = new ArrayList<>();
        for (int i = 0; i < 10; i++) for (int j = 0; j < 10; j++) { p.add(i * 0.1); p.add(j * 0.1); p.add(0.0); }
        for (double v : new double[] {5, 5, 5, -5, -5, 5}) p.add(v);
        try (PointCloud pc = cloud(p.stream().mapToDouble(Double::doubleValue).toArray())) {
            try (RemoveStatisticalOutlierResult r = pc.removeStatisticalOutlier(8, 2.0)) {
                assertArrayEquals(IntStream.range(0, 100).toArray(), r.indices());
                try (PointCloud kept = r.cloud()) {
                    assertEquals(100, kept.size());
                }
            }
            try (SegmentPlaneResult sp = pc.segmentPlane(0.01, 3, 1000, 0.99999999, 42)) {
                assertArrayEquals(IntStream.range(0, 100).toArray(), sp.indices());
                assertEquals(1, Math.abs(sp.plane()[2]), 1e-9);
            }
            int[] labels = pc.clusterDbscan(0.15, 3);
            assertEquals(102, labels.length);
            assertEquals(-1, labels[100]);
        }
    }

    @Test
    void meshesAndValueStructs() {
        try (TriangleMesh box = TriangleMesh.createBox(1, 1, 1)) {
            assertEquals(8, box.numVertices());
            assertEquals(12, box.numTriangles());
            assertEquals(6, box.getSurfaceArea(), 1e-12);
            assertEquals(1, box.getVolume(), 1e-12);
            assertTrue(box.isWatertight());
            assertEquals(2, box.eulerPoincareCharacteristic());
        }
        try (PoseGraphEdge edge = new PoseGraphEdge()) {
            assertEquals(1, edge.getConfidence(), 0, "default from o3d_pose_graph_edge_init");
            double[] m = IntStream.range(0, 16).asDoubleStream().toArray();
            edge.setTransformation(m);
            assertArrayEquals(m, edge.getTransformation(), 0);
            throwsStatus(Library.ERROR_INVALID_ARGUMENT, () -> edge.setTransformation(new double[3]));
        }
    }

    @Test
    void logHandler() {
        List<String> lines = new ArrayList<>();
        Library.setLogHandler((level, msg) -> { synchronized (lines) { lines.add(level + ": " + msg); } });
        assertThrows(O3dException.class, () -> Library.ioReadPointCloud("/nonexistent/none.ply", null, null));
        Library.setLogHandler(null);
    }
}
