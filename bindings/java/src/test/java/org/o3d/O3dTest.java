// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;

import java.io.File;
import java.nio.ByteBuffer;
import java.nio.DoubleBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Random;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The same scenarios as bindings/csharp/tests/Test.cs and tests/capi. */
class O3dTest {
    @TempDir
    Path tmp;

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

    static O3dException assertStatus(Status s, org.junit.jupiter.api.function.Executable e) {
        O3dException ex = assertThrows(O3dException.class, e);
        assertEquals(s, ex.getStatus(), ex.getMessage());
        assertFalse(ex.getMessage().isEmpty());
        return ex;
    }

    static File dataFile(String rel) {
        String dir = System.getenv("O3D_TEST_DATA");
        if (dir == null || dir.isEmpty()) dir = System.getenv("O3D_TEST_DATA_DEFAULT");
        if (dir == null || dir.isEmpty()) dir = System.getProperty("o3d.test.data.default", "../shared/data");
        File f = new File(dir, rel);
        if (!f.isFile()) {
            if ("1".equals(System.getenv("O3D_REQUIRE_TEST_DATA")))
                fail("missing test data (O3D_REQUIRE_TEST_DATA=1): " + f);
            Assumptions.assumeTrue(false, "missing test data " + f);
        }
        return f;
    }

    @Test
    void version() {
        assertEquals(0, Library.versionMajor());
        assertEquals(Library.versionMajor() + "." + Library.versionMinor() + "." + Library.versionPatch(), Library.version());
        assertEquals("O3D_ERROR_IO", Library.statusString(Status.IO));
        assertEquals("O3D_ERROR_PARSE", Status.PARSE.cName());
    }

    @Test
    void pointsRoundTripFloat64AndFloat32() {
        double[] pts = {1, 2, 3, 4.5, -5.25, 6, 1e-3, 7, -8};
        try (PointCloud pc = new PointCloud()) {
            assertEquals(0, pc.size());
            assertFalse(pc.hasPoints());
            pc.setPoints(pts);
            assertEquals(3, pc.size());
            assertTrue(pc.hasPoints());
            assertFalse(pc.hasNormals());
            assertArrayEquals(pts, pc.getPoints(), 0.0);
            pts[0] = 99;
            assertEquals(1.0, pc.getPoints()[0], 0.0, "the cloud holds a copy");
            float[] f = {0.5f, 1.25f, -2f, 3f, 4f, 5.5f};
            pc.setPoints(f);
            assertEquals(2, pc.size());
            assertArrayEquals(new double[] {0.5, 1.25, -2, 3, 4, 5.5}, pc.getPoints(), 0.0);
            pc.setNormals(new double[] {0, 0, 1, 0, 1, 0});
            pc.setColors(new float[] {1, 0, 0, 0, 0.5f, 1});
            assertTrue(pc.hasNormals() && pc.hasColors());
            assertArrayEquals(new double[] {1, 0, 0, 0, 0.5, 1}, pc.getColors(), 0.0);
            assertThrows(IllegalArgumentException.class, () -> pc.setPoints(new double[4]));

            DoubleBuffer view = pc.pointsView().asDoubleBuffer();
            assertEquals(6, view.capacity());
            assertEquals(3.0, view.get(3), 0.0);
            assertTrue(pc.pointsView().isReadOnly());
            DoubleBuffer mv = pc.pointsMutableView().asDoubleBuffer();
            mv.put(0, 7).put(1, 8).put(2, 9);
            assertArrayEquals(new double[] {7, 8, 9}, Arrays.copyOf(pc.getPoints(), 3), 0.0);
            assertEquals(6, pc.normalsView().asDoubleBuffer().capacity());
            try (PointCloud c = pc.copy()) {
                pc.clear();
                assertEquals(0, pc.size());
                assertEquals(2, c.size());
            }
        }
    }

    @Test
    void voxelDownSampleAverages() {
        double[] pts = {0, 0, 0, 0.1, 0, 0, 0, 0.1, 0.2, 5, 5, 5, 5.2, 5, 5};
        try (PointCloud pc = new PointCloud(pts); PointCloud down = pc.voxelDownSample(1.0)) {
            assertEquals(2, down.size());
            double[] d = down.getPoints();
            int a = d[0] < d[3] ? 0 : 1;
            int b = 1 - a;
            assertArrayEquals(new double[] {0.1 / 3, 0.1 / 3, 0.2 / 3}, Arrays.copyOfRange(d, 3 * a, 3 * a + 3), 1e-12);
            assertArrayEquals(new double[] {5.1, 5, 5}, Arrays.copyOfRange(d, 3 * b, 3 * b + 3), 1e-12);
            assertEquals(5, pc.size());
        }
    }

    @Test
    void normalsOfASampledPlane() {
        double[] pts = new double[3 * 400];
        int k = 0;
        for (int i = 0; i < 20; i++)
            for (int j = 0; j < 20; j++) {
                double x = i * 0.05, y = j * 0.05;
                pts[k++] = x;
                pts[k++] = y;
                pts[k++] = 0.3 * x + 0.2 * y;
            }
        double nn = Math.sqrt(0.09 + 0.04 + 1);
        try (PointCloud pc = new PointCloud(pts)) {
            pc.estimateNormals(SearchParam.hybrid(0.2, 16));
            assertTrue(pc.hasNormals());
            double[] n = pc.getNormals();
            assertEquals(pts.length, n.length);
            for (int i = 0; i < n.length / 3; i++) {
                double dot = (-0.3 * n[3 * i] - 0.2 * n[3 * i + 1] + n[3 * i + 2]) / nn;
                assertEquals(1.0, Math.abs(dot), 1e-6, "normal " + i);
            }
            pc.orientNormalsToAlignWithDirection(new double[] {0, 0, -1});
            assertTrue(pc.getNormals()[2] < 0);
            pc.estimateNormals();
        }
    }

    @Test
    void knnVsBruteForce() {
        double[] pts = randomPoints(500, 1, 1, 1, 1);
        double[] queries = randomPoints(20, 2, 1, 1, 1);
        int knn = 5;
        try (KDTreeFlann tree = new KDTreeFlann(pts)) {
            assertEquals(500, tree.size());
            NeighborResult res = tree.searchKnn(queries, knn);
            assertEquals(20, res.numQueries());
            assertEquals(20 * knn, res.indices.length);
            for (int q = 0; q < 20; q++) {
                final int qq = q;
                double[] d2 = new double[500];
                for (int i = 0; i < 500; i++) {
                    double dx = pts[3 * i] - queries[3 * q], dy = pts[3 * i + 1] - queries[3 * q + 1], dz = pts[3 * i + 2] - queries[3 * q + 2];
                    d2[i] = dx * dx + dy * dy + dz * dz;
                }
                int[] order = IntStream.range(0, 500).boxed().sorted(Comparator.comparingDouble(i -> d2[i]))
                        .mapToInt(Integer::intValue).limit(knn).toArray();
                assertEquals(q * knn, res.offsets[q]);
                assertArrayEquals(order, res.indicesOf(qq), "query " + q);
                for (int j = 0; j < knn; j++) assertEquals(d2[order[j]], res.distances2[q * knn + j], 1e-12);
            }
            float[] fq = new float[queries.length];
            for (int i = 0; i < fq.length; i++) fq[i] = (float) queries[i];
            try (PointCloud pc = new PointCloud(pts); KDTreeFlann tree2 = new KDTreeFlann(pc);
                 SearchResult raw = tree2.search(fq, SearchParam.knn(1), 0)) {
                assertArrayEquals(new long[] {20, 20}, raw.counts());
                ByteBuffer idx = raw.indicesView();
                assertEquals(20 * Integer.BYTES, idx.capacity());
                for (int q = 0; q < 20; q++) assertEquals(res.indices[q * knn], idx.asIntBuffer().get(q), "f32 nearest " + q);
                assertEquals(21, raw.offsetsView().asLongBuffer().capacity());
                assertEquals(20, raw.distances2View().asDoubleBuffer().capacity());
            }
            NeighborResult rad = tree.searchRadius(queries, 0.1);
            for (int q = 0; q < 20; q++) {
                int expect = 0;
                for (int i = 0; i < 500; i++) {
                    double dx = pts[3 * i] - queries[3 * q], dy = pts[3 * i + 1] - queries[3 * q + 1], dz = pts[3 * i + 2] - queries[3 * q + 2];
                    if (dx * dx + dy * dy + dz * dz <= 0.01) expect++;
                }
                assertEquals(expect, rad.offsets[q + 1] - rad.offsets[q], "radius count " + q);
            }
        }
    }

    @Test
    void icpRecoversAKnownTransform() {
        double[] src = randomPoints(800, 3, 1.0, 2.0, 0.5);
        double a = Math.toRadians(5), c = Math.cos(a), s = Math.sin(a);
        double[] t = {c, -s, 0, 0.05, s, c, 0, -0.03, 0, 0, 1, 0.02, 0, 0, 0, 1};
        try (PointCloud source = new PointCloud(src); PointCloud target = new PointCloud(applyTransform(t, src))) {
            int[] calls = {0};
            IcpOptions opts = new IcpOptions().maxIteration(100).relativeFitness(1e-10).relativeRmse(1e-10)
                    .progress(f -> { calls[0]++; return true; });
            assertEquals(IcpOptions.Estimation.POINT_TO_POINT, opts.estimation);
            RegistrationResult r = Registration.registrationIcp(source, target, 0.3, null, opts);
            assertArrayEquals(t, r.transformation, 1e-4);
            assertEquals(1.0, r.fitness, 1e-9);
            assertTrue(r.inlierRmse < 1e-4, "rmse " + r.inlierRmse);
            assertEquals(2 * 800, r.correspondenceSet.length);
            assertTrue(calls[0] > 0, "progress called");
            RegistrationResult e = Registration.evaluateRegistration(source, target, 0.01, t);
            assertEquals(1.0, e.fitness, 1e-12);
            double[] info = Registration.getInformationMatrixFromPointClouds(source, target, 0.01, t);
            assertEquals(36, info.length);
            assertTrue(info[0] > 0);
            opts.progress(f -> false);
            assertStatus(Status.CANCELLED, () -> Registration.registrationIcp(source, target, 0.3, null, opts));
        }
    }

    @Test
    void readWriteFileAndMemoryRoundTrip() throws Exception {
        double[] pts = randomPoints(100, 4, 1, 1, 1);
        double[] nrm = new double[300];
        for (int i = 0; i < 100; i++) nrm[3 * i + 2] = 1;
        try (PointCloud pc = new PointCloud(pts)) {
            pc.setNormals(nrm);
            pc.paintUniformColor(new double[] {1, 0.5, 0});
            for (String fmt : new String[] {"ply", "pcd", "xyz"}) {
                String path = tmp.resolve("c." + fmt).toString();
                IO.writePointCloud(path, pc);
                assertTrue(new File(path).isFile());
                try (PointCloud back = IO.readPointCloud(path)) {
                    assertEquals(100, back.size(), fmt);
                    assertArrayEquals(pts, back.getPoints(), 1e-5, fmt);
                }
            }
            try (PointCloud back = IO.readPointCloud(tmp.resolve("c.ply").toString())) {
                assertTrue(back.hasNormals() && back.hasColors());
                assertArrayEquals(nrm, back.getNormals(), 1e-6);
            }
            for (WriteOptions opt : new WriteOptions[] {new WriteOptions(), new WriteOptions(true, false), new WriteOptions(false, true)}) {
                byte[] bytes = IO.writePointCloudToMemory(pc, "pcd", opt);
                assertTrue(bytes.length > 100 * 3 * 4);
                try (PointCloud back = IO.readPointCloudFromMemory(bytes, "pcd")) {
                    assertEquals(100, back.size());
                    assertArrayEquals(pts, back.getPoints(), 1e-5);
                }
            }
            try (NativeBuffer buf = IO.writePointCloudToNativeBuffer(pc, "ply", null)) {
                byte[] bytes = buf.toByteArray();
                ByteBuffer view = buf.view();
                assertEquals(bytes.length, view.capacity());
                byte[] viewed = new byte[view.capacity()];
                view.get(viewed);
                assertArrayEquals(bytes, viewed);
                assertEquals("ply", new String(bytes, 0, 3, StandardCharsets.US_ASCII));
            }
        }
    }

    @Test
    void exceptionsOnBadInput() {
        try (PointCloud pc = new PointCloud(new double[] {0, 0, 0, 1, 1, 1})) {
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.voxelDownSample(Double.NaN));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.voxelDownSample(-1));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.selectByIndex(new int[] {5}));
            assertFalse(Library.lastErrorMessage().isEmpty());
            assertEquals(Status.INVALID_ARGUMENT, Library.lastErrorCode());
            Library.clearError();
            assertEquals(Status.OK, Library.lastErrorCode());
            assertEquals("", Library.lastErrorMessage());
        }
        O3dException e = assertStatus(Status.IO, () -> IO.readPointCloud("/nonexistent/dir/none.pcd"));
        assertTrue(e.getMessage().contains("O3D_ERROR_IO"), e.getMessage());
        assertStatus(Status.PARSE, () -> IO.readPointCloudFromMemory("ply\nformat garbage\n".getBytes(StandardCharsets.US_ASCII), "ply"));
        assertStatus(Status.PARSE, () -> IO.readPointCloudFromMemory("# .PCD v0.7\nFIELDS x y\nPOINTS x\n".getBytes(StandardCharsets.US_ASCII), "pcd"));
        assertThrows(NullPointerException.class, () -> IO.readPointCloudFromMemory(null, "ply"));
        assertStatus(Status.INVALID_ARGUMENT, () -> Library.setNumThreads(-1));
    }

    @Test
    void closedObjectsThrowAndCloseIsIdempotent() {
        PointCloud pc = new PointCloud(new double[] {1, 2, 3});
        KDTreeFlann tree = new KDTreeFlann(pc);
        pc.close();
        assertTrue(pc.isClosed());
        pc.close();
        assertThrows(IllegalStateException.class, pc::size);
        assertThrows(IllegalStateException.class, () -> pc.voxelDownSample(0.1));
        assertEquals(1, tree.size(), "tree outlives its cloud");
        tree.close();
        tree.close();
        assertThrows(IllegalStateException.class, () -> tree.searchKnn(new double[] {0, 0, 0}, 1));
        for (int i = 0; i < 100; i++) new PointCloud(new double[] {i, i, i}); // left to the Cleaner
        System.gc();
    }

    @Test
    void librarySettingsAndLogHandler() {
        Library.setNumThreads(2);
        assertEquals(2, Library.getNumThreads());
        Library.setNumThreads(0);
        assertTrue(Library.getNumThreads() >= 1);
        int lv = Library.getVerbosityLevel();
        Library.setVerbosityLevel(3);
        assertEquals(3, Library.getVerbosityLevel());
        List<String> lines = new ArrayList<>();
        Library.setLogHandler((level, msg) -> { synchronized (lines) { lines.add(level + ": " + msg); } });
        try (PointCloud pc = new PointCloud(randomPoints(50, 5, 1, 1, 1)); PointCloud d = pc.voxelDownSample(0.2)) {
            assertTrue(d.size() > 0);
        }
        assertThrows(O3dException.class, () -> IO.readPointCloud("/nonexistent/none.ply"));
        Library.setLogHandler(null);
        Library.setVerbosityLevel(lv);
    }

    @Test
    void figure1OnCloudBin0() throws Exception {
        File input = dataFile("open3d/Feature/cloud_bin_0.pcd");
        try (PointCloud pcd = IO.readPointCloud(input.getPath())) {
            assertEquals(3903, pcd.size(), "input size (the PCD header says 3903 points)");
            try (PointCloud down = pcd.voxelDownSample(0.05)) {
                // 2655: Open3D 0.20.0 voxel_down_sample(0.05) on the same file.
                assertEquals(2655, down.size(), "down size");
                down.estimateNormals(SearchParam.hybrid(0.1, 30));
                assertTrue(down.hasNormals());
                double[] n = down.getNormals();
                for (int i = 0; i < n.length / 3; i++)
                    assertEquals(1.0, n[3 * i] * n[3 * i] + n[3 * i + 1] * n[3 * i + 1] + n[3 * i + 2] * n[3 * i + 2], 1e-6);
                String out = tmp.resolve("down.ply").toString();
                IO.writePointCloud(out, down);
                assertTrue(Files.size(Path.of(out)) > 0);
                try (PointCloud back = IO.readPointCloud(out)) {
                    assertEquals(down.size(), back.size());
                    assertTrue(back.hasNormals());
                }
            }
        }
    }
}
