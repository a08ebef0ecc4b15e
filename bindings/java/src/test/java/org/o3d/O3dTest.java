// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Point clouds, KD-trees, ICP, I/O and errors: the same scenarios as bindings/csharp/tests/Test.cs and tests/capi. */
class O3dTest {
    @TempDir
    Path tmp;

    static final int P = Library.POINTCLOUD_POINTS, N = Library.POINTCLOUD_NORMALS, C = Library.POINTCLOUD_COLORS;

    @Test
    void version() {
        assertEquals(Library.VERSION_MAJOR, Library.versionMajor());
        assertEquals(0, Library.versionMajor());
        assertEquals(Library.versionMajor() + "." + Library.versionMinor() + "." + Library.versionPatch(), Library.version());
        assertEquals("O3D_ERROR_IO", Library.statusString(Library.ERROR_IO));
        assertEquals("O3D_ERROR_PARSE", Library.statusString(Library.ERROR_PARSE));
    }

    @Test
    void pointsRoundTripFloat64AndFloat32() {
        double[] pts = {1, 2, 3, 4.5, -5.25, 6, 1e-3, 7, -8};
        try (PointCloud pc = new PointCloud()) {
            assertEquals(0, pc.size());
            assertFalse(pc.hasArray(P));
            pc.setArray(P, pts);
            assertEquals(3, pc.size());
            assertTrue(pc.hasArray(P));
            assertFalse(pc.hasArray(N));
            assertArrayEquals(pts, points(pc), 0.0);
            pts[0] = 99;
            assertEquals(1.0, points(pc)[0], 0.0, "the cloud holds a copy");
            float[] f = {0.5f, 1.25f, -2f, 3f, 4f, 5.5f};
            pc.setArray(P, f);
            assertEquals(2, pc.size());
            assertArrayEquals(new double[] {0.5, 1.25, -2, 3, 4, 5.5}, points(pc), 0.0);
            pc.setArray(N, new double[] {0, 0, 1, 0, 1, 0});
            pc.setArray(C, new float[] {1, 0, 0, 0, 0.5f, 1});
            assertTrue(pc.hasArray(N) && pc.hasArray(C));
            assertArrayEquals(new double[] {1, 0, 0, 0, 0.5, 1}, pc.getArray(C), 0.0);
            try (PointcloudArrayShapeResult s = pc.arrayShape(P)) {
                assertEquals(2, s.rows());
                assertEquals(3, s.cols());
            }
            assertInvalid(() -> pc.setArray(P, new double[4]));

            java.nio.DoubleBuffer view = pc.arrayView(P).asDoubleBuffer();
            assertEquals(6, view.capacity());
            assertEquals(3.0, view.get(3), 0.0);
            assertTrue(pc.arrayView(P).isReadOnly());
            pc.arrayMutableView(P).asDoubleBuffer().put(0, 7).put(1, 8).put(2, 9);
            assertArrayEquals(new double[] {7, 8, 9}, Arrays.copyOf(points(pc), 3), 0.0);
            assertEquals(6, pc.arrayView(N).asDoubleBuffer().capacity());
            try (PointCloud c = pc.clone()) {
                pc.clear();
                assertEquals(0, pc.size());
                assertEquals(2, c.size(), "clone is deep");
                assertArrayEquals(new double[] {0, 0, 1, 0, 1, 0}, c.getArray(N), 0.0);
            }
        }
    }

    @Test
    void voxelDownSampleAverages() {
        double[] pts = {0, 0, 0, 0.1, 0, 0, 0, 0.1, 0.2, 5, 5, 5, 5.2, 5, 5};
        try (PointCloud pc = cloud(pts); PointCloud down = pc.voxelDownSample(1.0)) {
            assertEquals(2, down.size());
            double[] d = points(down);
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
        try (PointCloud pc = cloud(pts); SearchParam hy = hybrid(0.2, 16)) {
            pc.estimateNormals(hy, 0);
            assertTrue(pc.hasArray(N));
            double[] n = pc.getArray(N);
            assertEquals(pts.length, n.length);
            for (int i = 0; i < n.length / 3; i++) {
                double dot = (-0.3 * n[3 * i] - 0.2 * n[3 * i + 1] + n[3 * i + 2]) / nn;
                assertEquals(1.0, Math.abs(dot), 1e-6, "normal " + i);
            }
            pc.orientNormalsToAlignWithDirection(new double[] {0, 0, -1});
            assertTrue(pc.getArray(N)[2] < 0);
            pc.estimateNormals(null, 0); // NULL: the default search
            assertEquals(pts.length, pc.getArray(N).length);
        }
    }

    static double d2(double[] p, int i, double[] q, int j) {
        double dx = p[3 * i] - q[3 * j], dy = p[3 * i + 1] - q[3 * j + 1], dz = p[3 * i + 2] - q[3 * j + 2];
        return dx * dx + dy * dy + dz * dz;
    }

    @Test
    void knnVsBruteForce() {
        double[] pts = randomPoints(500, 1, 1, 1, 1);
        double[] queries = randomPoints(20, 2, 1, 1, 1);
        int k = 5;
        try (KDTreeFlann tree = KDTreeFlann.createFromPoints(pts); SearchParam p = knn(k); SearchResult res = tree.search(queries, p, 0)) {
            assertEquals(500, tree.size());
            try (CountsResult c = res.counts()) {
                assertEquals(20, c.numQueries());
                assertEquals(20 * k, c.total());
            }
            int[] idx = res.getIndices();
            long[] off = res.getOffsets();
            double[] dist = res.getDistances2();
            assertEquals(20 * k, idx.length);
            assertEquals(21, off.length);
            for (int q = 0; q < 20; q++) {
                final int qq = q;
                int[] order = IntStream.range(0, 500).boxed().sorted(Comparator.comparingDouble(i -> d2(pts, i, queries, qq)))
                        .mapToInt(Integer::intValue).limit(k).toArray();
                assertEquals(q * k, off[q]);
                assertArrayEquals(order, Arrays.copyOfRange(idx, q * k, q * k + k), "query " + q);
                for (int j = 0; j < k; j++) assertEquals(d2(pts, order[j], queries, q), dist[q * k + j], 1e-12);
            }
            float[] fq = new float[queries.length];
            for (int i = 0; i < fq.length; i++) fq[i] = (float) queries[i];
            try (PointCloud pc = cloud(pts); KDTreeFlann tree2 = KDTreeFlann.createFromPointcloud(pc); SearchParam one = knn(1);
                 SearchResult raw = tree2.search(fq, one, 0); CountsResult c = raw.counts()) {
                assertEquals(20, c.numQueries());
                assertEquals(20, c.total());
                int[] nearest = raw.getIndices();
                for (int q = 0; q < 20; q++) assertEquals(idx[q * k], nearest[q], "f32 nearest " + q);
                assertEquals(21, raw.getOffsets().length);
                assertEquals(20, raw.getDistances2().length);
                try (SearchResultView view = raw.view()) { // zero-copy views of the same arrays
                    int[] vi = new int[20];
                    long[] vo = new long[21];
                    double[] vd = new double[20];
                    view.indices().asIntBuffer().get(vi);
                    view.offsets().asLongBuffer().get(vo);
                    view.distances2().asDoubleBuffer().get(vd);
                    assertArrayEquals(nearest, vi);
                    assertArrayEquals(raw.getOffsets(), vo);
                    assertArrayEquals(raw.getDistances2(), vd, 0);
                    assertEquals(160, view.distances2().capacity());
                }
            }
            try (SearchParam r = radius(0.1); SearchResult rad = tree.search(queries, r, 0)) {
                long[] ro = rad.getOffsets();
                for (int q = 0; q < 20; q++) {
                    int expect = 0;
                    for (int i = 0; i < 500; i++) if (d2(pts, i, queries, q) <= 0.01) expect++;
                    assertEquals(expect, ro[q + 1] - ro[q], "radius count " + q);
                }
            }
            try (SearchParam bad = knn(0)) {
                assertInvalid(() -> tree.search(queries, bad, 0));
            }
            assertInvalid(() -> tree.search(new double[] {1, 2}, p, 0));
        }
    }

    @Test
    void icpRecoversAKnownTransform() {
        double[] src = randomPoints(800, 3, 1.0, 2.0, 0.5);
        double a = Math.toRadians(5), c = Math.cos(a), s = Math.sin(a);
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
                assertEquals(1.0, r.getFitness(), 1e-9);
                assertTrue(r.getInlierRmse() < 1e-4, "rmse " + r.getInlierRmse());
                assertEquals(2 * 800, r.getCorrespondenceSet().length);
            }
            assertTrue(calls[0] > 0, "progress called");
            try (RegistrationResult e = Library.evaluateRegistration(source, target, 0.01, t)) {
                assertEquals(1.0, e.getFitness(), 1e-12);
            }
            double[] info = Library.getInformationMatrixFromPointClouds(source, target, 0.01, t);
            assertEquals(36, info.length);
            assertTrue(info[0] > 0);
            opts.setProgress(f -> false);
            assertStatus(Library.ERROR_CANCELLED, () -> Library.registerIcp(source, target, 0.3, null, opts));
            opts.setProgress(f -> { throw new IllegalStateException("boom"); });
            assertStatus(Library.ERROR_CANCELLED, () -> Library.registerIcp(source, target, 0.3, null, opts));
            opts.setProgress(null);
            try (RegistrationResult r = Library.registerIcp(source, target, 0.3, null, opts)) {
                assertEquals(1.0, r.getFitness(), 1e-9);
            }
        }
    }

    @Test
    void readWriteFileAndMemoryRoundTrip() throws Exception {
        double[] pts = randomPoints(100, 4, 1, 1, 1);
        double[] nrm = new double[300];
        for (int i = 0; i < 100; i++) nrm[3 * i + 2] = 1;
        try (PointCloud pc = cloud(pts)) {
            pc.setArray(N, nrm);
            pc.paintUniformColor(new double[] {1, 0.5, 0});
            for (String fmt : new String[] {"ply", "pcd", "xyz"}) {
                String path = tmp.resolve("c." + fmt).toString();
                Library.ioWritePointCloud(path, pc, null, null);
                assertTrue(new File(path).isFile());
                try (PointCloud back = read(path)) {
                    assertEquals(100, back.size(), fmt);
                    assertArrayEquals(pts, points(back), 1e-5, fmt);
                }
            }
            try (PointCloud back = read(tmp.resolve("c.ply").toString())) {
                assertTrue(back.hasArray(N) && back.hasArray(C));
                assertArrayEquals(nrm, back.getArray(N), 1e-6);
            }
            WriteOptions ascii = new WriteOptions(), compressed = new WriteOptions();
            ascii.setWriteAscii(1);
            compressed.setCompressed(1);
            for (WriteOptions opt : new WriteOptions[] {new WriteOptions(), ascii, compressed, null}) {
                try (Buffer buf = Library.ioWritePointCloudToMemory(pc, "pcd", opt)) {
                    byte[] bytes = buf.getData();
                    assertTrue(bytes.length > 100 * 3 * 4);
                    try (PointCloud back = Library.ioReadPointCloudFromMemory(bytes, "pcd", null)) {
                        assertEquals(100, back.size());
                        assertArrayEquals(pts, points(back), 1e-5);
                    }
                }
            }
            try (Buffer buf = Library.ioWritePointCloudToMemory(pc, "ply", null)) {
                byte[] bytes = buf.getData();
                assertArrayEquals(bytes, buf.getData(), "a buffer reads twice");
                assertEquals("ply", new String(bytes, 0, 3, StandardCharsets.US_ASCII));
            }
        }
    }

    @Test
    void exceptionsOnBadInput() {
        try (PointCloud pc = cloud(new double[] {0, 0, 0, 1, 1, 1})) {
            assertInvalid(() -> pc.voxelDownSample(Double.NaN));
            assertInvalid(() -> pc.voxelDownSample(-1));
            assertInvalid(() -> pc.selectByIndex(new int[] {5}, 0));
            assertFalse(Library.lastErrorMessage().isEmpty());
            assertEquals(Library.ERROR_INVALID_ARGUMENT, Library.lastErrorCode());
            Library.clearError();
            assertEquals(Library.OK, Library.lastErrorCode());
            assertEquals("", Library.lastErrorMessage());
        }
        O3dException e = assertStatus(Library.ERROR_IO, () -> read("/nonexistent/dir/none.pcd"));
        assertTrue(e.getMessage().contains("O3D_ERROR_IO"), e.getMessage());
        assertStatus(Library.ERROR_PARSE,
                () -> Library.ioReadPointCloudFromMemory("ply\nformat garbage\n".getBytes(StandardCharsets.US_ASCII), "ply", null));
        assertStatus(Library.ERROR_PARSE, () -> Library.ioReadPointCloudFromMemory(
                "# .PCD v0.7\nFIELDS x y\nPOINTS x\n".getBytes(StandardCharsets.US_ASCII), "pcd", null));
        assertThrows(O3dException.class, () -> Library.ioReadPointCloudFromMemory(null, "ply", null));
        assertInvalid(() -> Library.setNumThreads(-1));
        assertInvalid(() -> cloud(new double[] {1, 2, 3}).append(null));
    }

    @Test
    void closedObjectsThrowAndCloseIsIdempotent() {
        PointCloud pc = cloud(new double[] {1, 2, 3});
        KDTreeFlann tree = KDTreeFlann.createFromPointcloud(pc);
        pc.close();
        assertEquals(0, PointCloud.getCPtr(pc), "closed");
        pc.close();
        assertThrows(IllegalStateException.class, pc::size);
        assertThrows(IllegalStateException.class, () -> pc.voxelDownSample(0.1));
        assertEquals(1, tree.size(), "tree outlives its cloud");
        tree.close();
        tree.close();
        try (SearchParam p = knn(1)) {
            assertThrows(IllegalStateException.class, () -> tree.search(new double[] {0, 0, 0}, p, 0));
        }
        for (int i = 0; i < 100; i++) cloud(new double[] {i, i, i}); // left to the garbage collector
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
        try (PointCloud pc = cloud(randomPoints(50, 5, 1, 1, 1)); PointCloud d = pc.voxelDownSample(0.2)) {
            assertTrue(d.size() > 0);
        }
        assertThrows(O3dException.class, () -> read("/nonexistent/none.ply"));
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
        System.arraycopy(new double[] {5, 5, 5, -5, -5, 5}, 0, p, k, 6);
        return p;
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
        try (PointCloud pc = cloud(pts)) {
            try (RemoveStatisticalOutlierResult r = pc.removeStatisticalOutlier(8, 2.0); PointCloud kept = r.cloud()) {
                assertArrayEquals(range(0, 100), r.indices(), "statistical: kept indices");
                assertEquals(100, kept.size());
                assertArrayEquals(grid, points(kept), 0.0);
            }
            try (RemoveRadiusOutlierResult r = pc.removeRadiusOutlier(3, 0.15); PointCloud kept = r.cloud()) {
                assertArrayEquals(range(0, 100), r.indices(), "radius: kept indices");
                assertArrayEquals(grid, points(kept), 0.0);
            }
            // every grid point has at most 8 others within 0.15: nothing survives nb_points = 9
            try (RemoveRadiusOutlierResult r = pc.removeRadiusOutlier(9, 0.15); PointCloud kept = r.cloud()) {
                assertEquals(0, r.indices().length);
                assertEquals(0, kept.size());
            }
            assertEquals(102, pc.size(), "input untouched");
            assertInvalid(() -> pc.removeStatisticalOutlier(0, 2.0));
            assertInvalid(() -> pc.removeStatisticalOutlier(8, -1));
            assertInvalid(() -> pc.removeRadiusOutlier(3, 0));
            assertInvalid(() -> pc.removeRadiusOutlier(0, 0.1));
        }
        try (PointCloud empty = new PointCloud()) {
            assertInvalid(() -> empty.removeStatisticalOutlier(8, 2.0));
        }
    }

    @Test
    void cropAabbInclusiveAndInvert() {
        double[] pts = {0, 0, 0, 1, 1, 1, 0.5, 0.5, 0.5, 2, 0, 0, 1, 1, 1.0001, 0.5, -1e-9, 0.5};
        try (PointCloud pc = cloud(pts)) {
            double[] colors = new double[18];
            for (int i = 0; i < 18; i++) colors[i] = i / 18.0;
            pc.setArray(C, colors);
            double[] min = {0, 0, 0}, max = {1, 1, 1};
            try (PointCloud inside = pc.cropAabb(min, max, 0)) {
                assertArrayEquals(new double[] {0, 0, 0, 1, 1, 1, 0.5, 0.5, 0.5}, points(inside), 0.0, "bounds inclusive");
                assertArrayEquals(Arrays.copyOf(colors, 9), inside.getArray(C), 0.0, "colors follow");
            }
            try (PointCloud outside = pc.cropAabb(min, max, 1)) {
                assertArrayEquals(new double[] {2, 0, 0, 1, 1, 1.0001, 0.5, -1e-9, 0.5}, points(outside), 0.0);
            }
            assertInvalid(() -> pc.cropAabb(max, min, 0));
            assertInvalid(() -> pc.cropAabb(new double[] {0, 0, Double.NaN}, max, 0));
            assertInvalid(() -> pc.cropAabb(new double[] {0, 0}, max, 0));
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
        try (PointCloud pc = cloud(p); SegmentPlaneResult r = pc.segmentPlane(0.01, 3, 1000, 0.99999999, 42);
             SegmentPlaneResult again = pc.segmentPlane(0.01, 3, 1000, 0.99999999, 42)) {
            assertArrayEquals(range(0, 400), r.indices());
            double[] plane = r.plane();
            assertEquals(4, plane.length);
            double sign = plane[2] < 0 ? 1 : -1; // normal up to sign
            assertArrayEquals(expected, Arrays.stream(plane).map(v -> v * sign).toArray(), 1e-9);
            assertArrayEquals(plane, again.plane(), 0.0, "same seed, same plane");
            assertArrayEquals(r.indices(), again.indices(), "same seed, same inliers");
            assertInvalid(() -> pc.segmentPlane(0.01, 2, 1000, 0.99, 0));
            assertInvalid(() -> pc.segmentPlane(0.01, 3, 0, 0.99, 0));
            assertInvalid(() -> pc.segmentPlane(-0.01, 3, 100, 0.99, 0));
            assertInvalid(() -> pc.segmentPlane(0.01, 3, 100, 1.5, 0));
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
        try (PointCloud pc = cloud(pts)) {
            int[] expected = IntStream.range(0, 55).map(i -> i < 27 ? 0 : i == 27 ? -1 : 1).toArray();
            assertArrayEquals(expected, pc.clusterDbscan(0.15, 3));
            assertArrayEquals(range(0, 55), pc.clusterDbscan(0.05, 1), "eps below the spacing: singletons");
            assertInvalid(() -> pc.clusterDbscan(0, 3));
            assertInvalid(() -> pc.clusterDbscan(0.1, -1));
        }
    }

    @Test
    void meanCovarianceAndMahalanobisAnalytic() {
        // (1, 2, 3) +- (1, 0, 0), (0, 2, 0), (0, 0, 3): mean (1, 2, 3), covariance diag(1/3, 4/3, 3)
        double[] pts = {2, 2, 3, 0, 2, 3, 1, 4, 3, 1, 0, 3, 1, 2, 6, 1, 2, 0};
        try (PointCloud pc = cloud(pts); ComputeMeanAndCovarianceResult mc = pc.computeMeanAndCovariance()) {
            assertArrayEquals(new double[] {1, 2, 3}, mc.mean(), 1e-12);
            assertArrayEquals(new double[] {1.0 / 3, 0, 0, 0, 4.0 / 3, 0, 0, 0, 3}, mc.covariance(), 1e-12);
            double[] expected = new double[6];
            Arrays.fill(expected, Math.sqrt(3));
            assertArrayEquals(expected, pc.computeMahalanobisDistance(), 1e-9);
        }
        try (PointCloud empty = new PointCloud()) {
            assertInvalid(empty::computeMeanAndCovariance);
            assertInvalid(empty::computeMahalanobisDistance);
        }
    }

    @Test
    void figure1OnCloudBin0() throws Exception {
        try (PointCloud pcd = read(data("open3d/Feature/cloud_bin_0.pcd"))) {
            assertEquals(3903, pcd.size(), "input size (the PCD header says 3903 points)");
            try (PointCloud down = pcd.voxelDownSample(0.05); SearchParam hy = hybrid(0.1, 30)) {
                // 2655: Open3D 0.20.0 voxel_down_sample(0.05) on the same file.
                assertEquals(2655, down.size(), "down size");
                down.estimateNormals(hy, 0);
                assertTrue(down.hasArray(N));
                double[] n = down.getArray(N);
                for (int i = 0; i < n.length / 3; i++)
                    assertEquals(1.0, n[3 * i] * n[3 * i] + n[3 * i + 1] * n[3 * i + 1] + n[3 * i + 2] * n[3 * i + 2], 1e-6);
                String out = tmp.resolve("down.ply").toString();
                Library.ioWritePointCloud(out, down, null, null);
                assertTrue(Files.size(Path.of(out)) > 0);
                try (PointCloud back = read(out)) {
                    assertEquals(down.size(), back.size());
                    assertTrue(back.hasArray(N));
                }
            }
        }
    }
}
