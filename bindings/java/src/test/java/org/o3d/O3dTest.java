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

    // ---- point-cloud tools (the same fixtures as Test.cs) ----

    /** A 10 x 10 grid (spacing 0.1) at z = 0, indices 0..99, then two far outliers (100, 101). */
    static double[] gridWithOutliers() {
        double[] p = new double[3 * 102];
        int k = 0;
        for (int i = 0; i < 10; i++)
            for (int j = 0; j < 10; j++) {
                p[k++] = i * 0.1;
                p[k++] = j * 0.1;
                p[k++] = 0;
            }
        double[] far = {5, 5, 5, -5, -5, 5};
        System.arraycopy(far, 0, p, k, 6);
        return p;
    }

    static int[] range(int start, int count) {
        return IntStream.range(start, start + count).toArray();
    }

    /** A 3 x 3 x 3 grid (spacing 0.1) around (cx, cy, cz). */
    static double[] blob(double cx, double cy, double cz) {
        double[] p = new double[81];
        int n = 0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                for (int k = 0; k < 3; k++) {
                    p[n++] = cx + i * 0.1;
                    p[n++] = cy + j * 0.1;
                    p[n++] = cz + k * 0.1;
                }
        return p;
    }

    @Test
    void removeStatisticalAndRadiusOutliers() {
        double[] pts = gridWithOutliers();
        double[] grid = Arrays.copyOf(pts, 300);
        try (PointCloud pc = new PointCloud(pts)) {
            try (OutlierRemovalResult r = pc.removeStatisticalOutlier(8, 2.0)) {
                assertArrayEquals(range(0, 100), r.indices, "statistical: kept indices");
                assertEquals(100, r.cloud.size());
                assertArrayEquals(grid, r.cloud.getPoints(), 0.0);
            }
            try (OutlierRemovalResult r = pc.removeRadiusOutlier(3, 0.15)) {
                assertArrayEquals(range(0, 100), r.indices, "radius: kept indices");
                assertArrayEquals(grid, r.cloud.getPoints(), 0.0);
            }
            // every grid point has at most 8 others within 0.15: nothing survives nb_points = 9
            try (OutlierRemovalResult r = pc.removeRadiusOutlier(9, 0.15)) {
                assertEquals(0, r.indices.length);
                assertEquals(0, r.cloud.size());
            }
            assertEquals(102, pc.size(), "input untouched");
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.removeStatisticalOutlier(0, 2.0));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.removeStatisticalOutlier(8, -1));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.removeRadiusOutlier(3, 0));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.removeRadiusOutlier(0, 0.1));
        }
        try (PointCloud empty = new PointCloud()) {
            assertStatus(Status.INVALID_ARGUMENT, () -> empty.removeStatisticalOutlier(8, 2.0));
        }
    }

    @Test
    void cropAabbInclusiveAndInvert() {
        double[] pts = {0, 0, 0, 1, 1, 1, 0.5, 0.5, 0.5, 2, 0, 0, 1, 1, 1.0001, 0.5, -1e-9, 0.5};
        try (PointCloud pc = new PointCloud(pts)) {
            double[] colors = new double[18];
            for (int i = 0; i < 18; i++) colors[i] = i / 18.0;
            pc.setColors(colors);
            double[] min = {0, 0, 0}, max = {1, 1, 1};
            try (PointCloud inside = pc.cropAabb(min, max)) {
                assertArrayEquals(new double[] {0, 0, 0, 1, 1, 1, 0.5, 0.5, 0.5}, inside.getPoints(), 0.0, "bounds inclusive");
                assertArrayEquals(Arrays.copyOf(colors, 9), inside.getColors(), 0.0, "colors follow");
            }
            try (PointCloud outside = pc.cropAabb(min, max, true)) {
                assertArrayEquals(new double[] {2, 0, 0, 1, 1, 1.0001, 0.5, -1e-9, 0.5}, outside.getPoints(), 0.0);
            }
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.cropAabb(max, min));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.cropAabb(new double[] {0, 0, Double.NaN}, max));
            assertThrows(IllegalArgumentException.class, () -> pc.cropAabb(new double[] {0, 0}, max));
        }
    }

    @Test
    void segmentPlaneRecoversAKnownPlane() {
        // z = 0.5 x + 0.2 y + 1  <=>  0.5 x + 0.2 y - z + 1 = 0; 400 inliers then 20 points >= 1.7 off it
        double[] p = new double[3 * 420];
        int n = 0;
        for (int i = 0; i < 20; i++)
            for (int j = 0; j < 20; j++) {
                double x = i * 0.1, y = j * 0.1;
                p[n++] = x;
                p[n++] = y;
                p[n++] = 0.5 * x + 0.2 * y + 1;
            }
        for (int k = 0; k < 20; k++) {
            double x = (k % 5) * 0.4, y = (k / 5) * 0.5;
            p[n++] = x;
            p[n++] = y;
            p[n++] = 0.5 * x + 0.2 * y + 3 + 0.1 * k;
        }
        double norm = Math.sqrt(0.25 + 0.04 + 1);
        double[] expected = {0.5 / norm, 0.2 / norm, -1 / norm, 1 / norm};
        try (PointCloud pc = new PointCloud(p)) {
            PlaneSegmentationResult r = pc.segmentPlane(0.01, 3, 1000, 0.99999999, 42);
            assertArrayEquals(range(0, 400), r.inliers);
            assertEquals(4, r.plane.length);
            double sign = r.plane[2] < 0 ? 1 : -1; // normal up to sign
            double[] signed = Arrays.stream(r.plane).map(v -> v * sign).toArray();
            assertArrayEquals(expected, signed, 1e-9);
            PlaneSegmentationResult again = pc.segmentPlane(0.01, 3, 1000, 0.99999999, 42);
            assertArrayEquals(r.plane, again.plane, 0.0, "same seed, same plane");
            assertArrayEquals(r.inliers, again.inliers, "same seed, same inliers");
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.segmentPlane(0.01, 2, 1000));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.segmentPlane(0.01, 3, 0));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.segmentPlane(-0.01, 3, 100));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.segmentPlane(0.01, 3, 100, 1.5, 0));
        }
    }

    @Test
    void clusterDbscanOnSeparatedBlobs() {
        // blob at (10, 0, 0): 0..26, a lone noise point: 27, blob at the origin: 28..54
        double[] pts = new double[3 * 55];
        System.arraycopy(blob(10, 0, 0), 0, pts, 0, 81);
        pts[81] = 5;
        pts[82] = 5;
        pts[83] = 5;
        System.arraycopy(blob(0, 0, 0), 0, pts, 84, 81);
        try (PointCloud pc = new PointCloud(pts)) {
            int[] labels = pc.clusterDbscan(0.15, 3);
            int[] expected = IntStream.range(0, 55).map(i -> i < 27 ? 0 : i == 27 ? -1 : 1).toArray();
            assertArrayEquals(expected, labels);
            assertArrayEquals(range(0, 55), pc.clusterDbscan(0.05, 1), "eps below the spacing: singletons");
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.clusterDbscan(0, 3));
            assertStatus(Status.INVALID_ARGUMENT, () -> pc.clusterDbscan(0.1, -1));
        }
    }

    @Test
    void meanCovarianceAndMahalanobisAnalytic() {
        // (1, 2, 3) +- (1, 0, 0), (0, 2, 0), (0, 0, 3): mean (1, 2, 3), covariance diag(1/3, 4/3, 3)
        double[] pts = {2, 2, 3, 0, 2, 3, 1, 4, 3, 1, 0, 3, 1, 2, 6, 1, 2, 0};
        try (PointCloud pc = new PointCloud(pts)) {
            MeanAndCovariance mc = pc.computeMeanAndCovariance();
            assertArrayEquals(new double[] {1, 2, 3}, mc.mean, 1e-12);
            assertArrayEquals(new double[] {1.0 / 3, 0, 0, 0, 4.0 / 3, 0, 0, 0, 3}, mc.covariance, 1e-12);
            double[] d = pc.computeMahalanobisDistance();
            double[] expected = new double[6];
            Arrays.fill(expected, Math.sqrt(3));
            assertArrayEquals(expected, d, 1e-9);
        }
        try (PointCloud empty = new PointCloud()) {
            assertStatus(Status.INVALID_ARGUMENT, empty::computeMeanAndCovariance);
            assertStatus(Status.INVALID_ARGUMENT, empty::computeMahalanobisDistance);
        }
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
