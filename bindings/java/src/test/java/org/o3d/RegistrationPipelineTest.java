// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The registration pipeline from Java: features, KD-trees over them, robust kernels, the ICP variants,
 * correspondence checkers, RANSAC, FGR, pose graphs and global optimization (the same scenarios as
 * bindings/csharp/tests/RegistrationPipelineTest.cs).
 */
class RegistrationPipelineTest {
    @TempDir
    Path tmp;

    static final int FD = Library.FEATURE_DATA;

    // ---- rigid-transform helpers (row-major 4x4) ----
    static double[] mul4(double[] a, double[] b) {
        double[] c = new double[16];
        for (int r = 0; r < 4; r++)
            for (int k = 0; k < 4; k++)
                for (int j = 0; j < 4; j++) c[4 * r + j] += a[4 * r + k] * b[4 * k + j];
        return c;
    }

    /** Rotation about the unit axis (x, y, z) by {@code deg} degrees, then translation (tx, ty, tz). */
    static double[] rigid(double x, double y, double z, double deg, double tx, double ty, double tz) {
        double a = Math.toRadians(deg), c = Math.cos(a), s = Math.sin(a), v = 1 - c;
        return new double[] {
            c + x * x * v, x * y * v - z * s, x * z * v + y * s, tx,
            y * x * v + z * s, c + y * y * v, y * z * v - x * s, ty,
            z * x * v - y * s, z * y * v + x * s, c + z * z * v, tz,
            0, 0, 0, 1};
    }

    static double[] invertRigid(double[] t) {
        double[] r = new double[16];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) r[4 * i + j] = t[4 * j + i];
        for (int i = 0; i < 3; i++) r[4 * i + 3] = -(r[4 * i] * t[3] + r[4 * i + 1] * t[7] + r[4 * i + 2] * t[11]);
        r[15] = 1;
        return r;
    }

    static double angleDeg(double[] t) {
        double cos = Math.max(-1, Math.min(1, (t[0] + t[5] + t[10] - 1) / 2));
        return Math.toDegrees(Math.acos(cos));
    }

    /** RMS distance between the points moved by {@code a} and by {@code b}. */
    static double rmsGap(double[] a, double[] b, double[] points) {
        double[] pa = applyTransform(a, points), pb = applyTransform(b, points);
        double s = 0;
        for (int i = 0; i < pa.length; i++) s += (pa[i] - pb[i]) * (pa[i] - pb[i]);
        return Math.sqrt(s / (points.length / 3));
    }

    static PointCloud withUnitNormals(PointCloud pc, double radius) {
        try (SearchParam p = hybrid(radius, 30)) {
            pc.estimateNormals(p, 0);
        }
        return pc;
    }

    static double[] diagonal6(double v) {
        double[] m = new double[36];
        for (int i = 0; i < 6; i++) m[7 * i] = v;
        return m;
    }

    static double[] range(int n) {
        return IntStream.range(0, n).asDoubleStream().toArray();
    }

    static Feature feature(double[] data, long dim, long num) {
        return Feature.createFromData(data, dim, num);
    }

    static Feature fpfh(PointCloud pc, double radius, int knn, long[] indices, int threads) {
        try (SearchParam p = hybrid(radius, knn)) {
            return Library.computeFpfhFeature(pc, p, indices, threads);
        }
    }

    /** Runs a registration, returns {transformation (16), fitness, inlier rmse} and closes the result. */
    static double[] run(RegistrationResult r) {
        try (r) {
            double[] out = Arrays.copyOf(r.getTransformation(), 18);
            out[16] = r.getFitness();
            out[17] = r.getInlierRmse();
            return out;
        }
    }

    static double[] tf(double[] result) {
        return Arrays.copyOf(result, 16);
    }

    static IcpOptions icpOptions(int estimation, int maxIteration, double relative) {
        IcpOptions o = new IcpOptions();
        o.setEstimation(estimation);
        o.setMaxIteration(maxIteration);
        o.setRelativeFitness(relative);
        o.setRelativeRmse(relative);
        return o;
    }

    static CorrespondenceChecker checker(int kind, double threshold) {
        CorrespondenceChecker c = new CorrespondenceChecker(kind);
        c.setThreshold(threshold);
        return c;
    }

    static PoseGraphEdge edge(int s, int t, double[] tr, double[] info, boolean uncertain) {
        PoseGraphEdge e = new PoseGraphEdge();
        e.setSourceNodeId(s);
        e.setTargetNodeId(t);
        if (tr != null) e.setTransformation(tr);
        if (info != null) e.setInformation(info);
        e.setUncertain(uncertain ? 1 : 0);
        return e;
    }

    static double[][] nodes(PoseGraph g) {
        double[][] n = new double[(int) g.numNodes()][];
        for (int i = 0; i < n.length; i++) n[i] = g.getNode(i);
        return n;
    }

    @Test
    void featureCreateDataViewResizeSelectCopy() {
        double[] values = range(12); // 3 descriptors of 4
        try (Feature f = feature(values, 4, 3)) {
            assertEquals(4, f.dimension());
            assertEquals(3, f.num());
            assertArrayEquals(values, f.getArray(FD));
            try (FeatureArrayShapeResult s = f.arrayShape(FD)) {
                assertEquals(3, s.rows());
                assertEquals(4, s.cols());
            }
            double[] view = new double[12];
            f.arrayView(FD).asDoubleBuffer().get(view);
            assertArrayEquals(values, view);
            try (Feature picked = f.selectByIndex(new long[] {2, 0}, 0)) {
                assertArrayEquals(new double[] {8, 9, 10, 11, 0, 1, 2, 3}, picked.getArray(FD));
            }
            try (Feature rest = f.selectByIndex(new long[] {1}, 1)) {
                assertArrayEquals(new double[] {0, 1, 2, 3, 8, 9, 10, 11}, rest.getArray(FD));
            }
            double[] negated = Arrays.stream(values).map(v -> -v).toArray();
            try (Feature copy = f.clone()) {
                f.setArray(FD, negated);
                assertArrayEquals(values, copy.getArray(FD), "copy is deep");
                assertEquals(-5, f.getArray(FD)[5]);
            }
            f.resize(4, 5);
            double[] resized = f.getArray(FD);
            assertArrayEquals(negated, Arrays.copyOf(resized, 12));
            assertTrue(Arrays.stream(resized, 12, 20).allMatch(v -> v == 0), "zero padding");
            assertInvalid(() -> f.setArray(FD, new double[3]));
            assertInvalid(() -> f.selectByIndex(new long[] {5}, 0));
            assertThrows(O3dException.class, () -> f.resize(-1, 2)); // size_t: -1 is SIZE_MAX
        }
        try (Feature zeros = Feature.create(33, 2)) {
            assertArrayEquals(new double[66], zeros.getArray(FD));
        }
        try (Feature empty = Feature.create(0, 0)) {
            assertEquals(0, empty.dimension());
            assertEquals(0, empty.getArray(FD).length);
        }
        assertInvalid(() -> feature(new double[] {1, Double.NaN}, 2, 1));
        assertInvalid(() -> feature(new double[5], 2, 3));
        Feature gone = Feature.create(2, 2);
        gone.close();
        assertThrows(IllegalStateException.class, gone::num);
    }

    @Test
    void nullHandlesThrowO3dException() {
        // A null (Java) handle reaches C as NULL: an O3dException, never a crash.
        try (PointCloud pc = cloud(randomPoints(10, 1, 1, 1, 1))) {
            assertInvalid(() -> Library.globalOptimization(null, null));
            assertInvalid(() -> Library.registerRansacBasedOnFeatureMatching(null, null, null, null, 0.1, null, null));
            assertInvalid(() -> Library.registerFgrBasedOnCorrespondence(null, null, null, null));
            assertInvalid(() -> Library.computeFpfhFeature(null, null, null, 0));
            assertInvalid(() -> KDTreeFlann.createFromFeature(null));
            assertInvalid(() -> Library.registerIcp(pc, null, 0.1, null, null));
        }
        PoseGraph g = new PoseGraph();
        g.close();
        assertThrows(IllegalStateException.class, g::numNodes);
    }

    @Test
    void featureFileRoundTripAndBadFiles() throws Exception {
        double[] values = IntStream.range(0, 15).mapToDouble(i -> Math.sqrt(i) - 1.5).toArray();
        String path = tmp.resolve("f.bin").toString();
        try (Feature f = feature(values, 5, 3)) {
            Library.ioWriteFeature(path, f);
        }
        assertEquals(8 + 15 * 8, Files.size(Path.of(path)), "int32 dimension, int32 num, then float64 values");
        try (Feature back = Library.ioReadFeature(path)) {
            assertEquals(5, back.dimension());
            assertEquals(3, back.num());
            assertArrayEquals(values, back.getArray(FD), 0.0);
        }
        Files.write(Path.of(path), new byte[] {33, 0, 0, 0, 10, 0, 0, 0, 1, 2, 3});
        assertStatus(Library.ERROR_PARSE, () -> Library.ioReadFeature(path));
        assertStatus(Library.ERROR_IO, () -> Library.ioReadFeature(tmp.resolve("missing.bin").toString()));
        assertInvalid(() -> Library.ioWriteFeature(path, null));
    }

    static double dist2(double[] pts, int i, double[] queries, int q) {
        double s = 0;
        for (int k = 0; k < 5; k++) s += Math.pow(pts[5 * i + k] - queries[5 * q + k], 2);
        return s;
    }

    @Test
    void kdTreeOverAFeatureAndOverXdPoints() {
        Random rnd = new Random(11);
        double[] pts = rnd.doubles(1000).toArray(); // 200 points of 5 dimensions
        double[] queries = rnd.doubles(15).toArray();
        try (Feature f = feature(pts, 5, 200); KDTreeFlann tree = KDTreeFlann.createFromFeature(f);
             KDTreeFlann xd = KDTreeFlann.createFromPointsXd(pts, 5, 200); SearchParam k3 = knn(3);
             SearchResult r = tree.searchXd(queries, 5, k3, 0); SearchResult rx = xd.searchXd(queries, 5, k3, 0)) {
            assertEquals(5, tree.dimension());
            assertEquals(5, xd.dimension());
            assertEquals(200, tree.size());
            int[] idx = r.getIndices();
            long[] off = r.getOffsets();
            assertArrayEquals(idx, rx.getIndices(), "feature tree == xd tree");
            for (int q = 0; q < 3; q++) {
                final int qq = q;
                int[] order = IntStream.range(0, 200).boxed()
                        .sorted((i, j) -> Double.compare(dist2(pts, i, queries, qq), dist2(pts, j, queries, qq)))
                        .limit(3).mapToInt(Integer::intValue).toArray();
                assertArrayEquals(order, Arrays.copyOfRange(idx, (int) off[q], (int) off[q + 1]), "query " + q);
            }
            try (SearchParam rad = radius(0.3); SearchResult rr = tree.searchXd(queries, 5, rad, 0)) {
                assertEquals(4, rr.getOffsets().length);
            }
            assertInvalid(() -> tree.searchXd(new double[] {1, 2, 3}, 5, k3, 0));
            assertInvalid(() -> KDTreeFlann.createFromPointsXd(new double[7], 2, 4));
        }
        try (PointCloud pc = cloud(randomPoints(10, 1, 1, 1, 1)); KDTreeFlann t3 = KDTreeFlann.createFromPointcloud(pc)) {
            assertEquals(3, t3.dimension());
        }
    }

    @Test
    void correspondencesFromFeaturesFindAPermutation() {
        Random rnd = new Random(5);
        int n = 50, d = 8;
        double[] src = rnd.doubles(n * d).toArray();
        List<Integer> perm = new ArrayList<>();
        for (int i = 0; i < n; i++) perm.add(i);
        Collections.shuffle(perm, rnd);
        double[] tgt = new double[n * d];
        for (int i = 0; i < n; i++) System.arraycopy(src, d * i, tgt, d * perm.get(i), d); // source i is target perm[i]
        try (Feature fs = feature(src, d, n); Feature ft = feature(tgt, d, n)) {
            for (int mutual : new int[] {0, 1}) {
                int[] pairs = Library.correspondencesFromFeatures(fs, ft, mutual, 0.1, 0);
                assertEquals(2 * n, pairs.length);
                for (int i = 0; i < n; i++) {
                    assertEquals(i, pairs[2 * i]);
                    assertEquals((int) perm.get(i), pairs[2 * i + 1], "pair " + i);
                }
            }
            try (Feature other = Feature.create(3, n)) {
                assertInvalid(() -> Library.correspondencesFromFeatures(fs, other, 0, 0.1, 0));
            }
        }
    }

    @Test
    void fpfhOnCloudBin0MatchesTheStoredFeaturesShape() {
        try (Feature stored = Library.ioReadFeature(data("open3d/Feature/cloud_bin_0.fpfh.bin"));
             PointCloud pc = read(data("open3d/Feature/cloud_bin_0.pcd"));
             Feature fp = fpfh(pc, 0.25, 100, null, 0)) {
            assertEquals(33, stored.dimension());
            assertEquals(3903, stored.num());
            assertEquals(stored.dimension(), fp.dimension());
            assertEquals(pc.size(), fp.num());
            double[] data = fp.getArray(FD);
            // Open3D's FPFH normalises each 11-bin block of a point's own SPFH and of the distance-weighted sum of
            // its neighbours' SPFHs to 100, so every block of the result sums to 200.
            for (int i = 0; i < fp.num(); i += 97)
                for (int b = 0; b < 3; b++)
                    assertEquals(200, Arrays.stream(data, 33 * i + 11 * b, 33 * i + 11 * b + 11).sum(), 1e-9, "p" + i + " b" + b);
            long[] some = {0, 1234, 3902};
            try (Feature part = fpfh(pc, 0.25, 100, some, 0); Feature picked = fp.selectByIndex(some, 0)) {
                assertArrayEquals(picked.getArray(FD), part.getArray(FD), 1e-12, "indices: neighbourhoods from the whole cloud");
            }
            try (Feature one = fpfh(pc, 0.25, 100, null, 1)) {
                assertArrayEquals(data, one.getArray(FD), 0.0, "same on 1 thread");
            }
        }
        try (PointCloud bare = cloud(randomPoints(50, 2, 1, 1, 1))) {
            assertInvalid(() -> Library.computeFpfhFeature(bare, null, null, 0));
        }
    }

    @Test
    void robustKernelWeights() {
        assertEquals(1, Library.robustKernelWeight(Library.KERNEL_L2, 0, 3), 0);
        assertEquals(0.5, Library.robustKernelWeight(Library.KERNEL_L1, 0, -2), 1e-15);
        assertEquals(1, Library.robustKernelWeight(Library.KERNEL_HUBER, 1, 0.5), 1e-15);
        assertEquals(0.25, Library.robustKernelWeight(Library.KERNEL_HUBER, 1, 4), 1e-15);
        assertEquals(0.5, Library.robustKernelWeight(Library.KERNEL_CAUCHY, 2, 2), 1e-15);
        assertEquals(0.25, Library.robustKernelWeight(Library.KERNEL_GM, 1, 1), 1e-15);
        assertEquals(0.5625, Library.robustKernelWeight(Library.KERNEL_TUKEY, 1, 0.5), 1e-15);
        assertEquals(0, Library.robustKernelWeight(Library.KERNEL_TUKEY, 1, 1.5), 0);
        try (IcpOptions opts = new IcpOptions()) {
            assertEquals(Library.KERNEL_L2, opts.getKernel());
            assertEquals(0.968, opts.getLambdaGeometric());
            assertEquals(1e-3, opts.getEpsilon());
        }
        assertInvalid(() -> Library.robustKernelWeight(Library.KERNEL_HUBER, -1, 1));
    }

    @Test
    void coloredGeneralizedAndSymmetricIcpRecoverASmallTransform() {
        double[] t = rigid(0.6, 0.0, 0.8, 3, 0.02, -0.015, 0.01);
        try (PointCloud fragment = read(data("open3d/fragment.pcd"));
             PointCloud source = withUnitNormals(fragment.voxelDownSample(0.02), 0.04);
             PointCloud target = source.clone();
             IcpOptions opts = icpOptions(Library.ESTIMATION_COLORED, 60, 1e-9)) {
            target.transform(t);
            assertTrue(source.hasArray(Library.POINTCLOUD_COLORS) && target.hasArray(Library.POINTCLOUD_NORMALS));
            double[] colored = run(Library.registerIcp(source, target, 0.05, null, opts));
            assertArrayEquals(t, tf(colored), 2e-3, "colored");
            opts.setEstimation(Library.ESTIMATION_GENERALIZED);
            double[] generalized = run(Library.registerIcp(source, target, 0.05, null, opts));
            assertArrayEquals(t, tf(generalized), 2e-3, "generalized");
            opts.setEstimation(Library.ESTIMATION_SYMMETRIC);
            double[] symmetric = run(Library.registerIcp(source, target, 0.05, null, opts));
            assertArrayEquals(t, tf(symmetric), 2e-3, "symmetric");
            assertTrue(colored[16] > 0.99 && generalized[16] > 0.99 && symmetric[16] > 0.99);
            opts.setEstimation(Library.ESTIMATION_GENERALIZED);
            assertArrayEquals(tf(generalized), tf(run(Library.registerIcp(source, target, 0.05, null, opts))), 0.0);
            try (PointCloud plain = cloud(points(source)); IcpOptions c = icpOptions(Library.ESTIMATION_COLORED, 30, 1e-6)) {
                assertInvalid(() -> Library.registerIcp(plain, target, 0.05, null, c));
            }
        }
    }

    @Test
    void tukeyKernelKeepsPointToPlaneIcpOnTargetWith30PercentOutliers() {
        // 30% of the source are outliers: points lifted 4 to 8 cm off the surface along their normals. Near the true
        // transform their point-to-plane residuals exceed the Tukey scale (3 cm), so they get weight 0; L2 is pulled off.
        double[] t = rigid(0, 0, 1, 1, 0.02, 0.01, 0);
        try (PointCloud scan = read(data("open3d/Feature/cloud_bin_0.pcd"));
             PointCloud clean = withUnitNormals(scan.voxelDownSample(0.03), 0.06);
             PointCloud target = clean.clone();
             PointCloud source = clean.clone();
             IcpOptions opts = icpOptions(Library.ESTIMATION_POINT_TO_PLANE, 100, 1e-9)) {
            target.transform(t);
            double[] pts = points(clean), nrm = clean.getArray(Library.POINTCLOUD_NORMALS);
            int n = (int) clean.size(), outliers = (int) (0.3 * n / 0.7);
            Random rnd = new Random(3);
            double[] all = Arrays.copyOf(pts, 3 * (n + outliers));
            for (int i = 0; i < outliers; i++) {
                int j = rnd.nextInt(n);
                double lift = 0.04 + 0.04 * rnd.nextDouble();
                for (int k = 0; k < 3; k++) all[3 * (n + i) + k] = pts[3 * j + k] + lift * nrm[3 * j + k];
            }
            source.setArray(Library.POINTCLOUD_POINTS, all);
            source.setArray(Library.POINTCLOUD_NORMALS, new double[0]);
            opts.setKernel(Library.KERNEL_TUKEY);
            opts.setKernelK(0.03);
            double[] robust = tf(run(Library.registerIcp(source, target, 0.1, null, opts)));
            opts.setKernel(Library.KERNEL_L2);
            double[] plain = tf(run(Library.registerIcp(source, target, 0.1, null, opts)));
            double robustGap = rmsGap(robust, t, pts), plainGap = rmsGap(plain, t, pts);
            System.out.println("  Tukey: " + robustGap + " m off, L2: " + plainGap + " m off");
            assertTrue(angleDeg(mul4(robust, invertRigid(t))) < 0.05, "rotation within 0.05 deg");
            assertTrue(robustGap < 1e-3, "Tukey within 1 mm: " + robustGap);
            assertTrue(plainGap > 0.01, "L2 is pulled more than 1 cm off by the outliers: " + plainGap);
        }
    }

    @Test
    void correspondenceCheckers() {
        double[] pts = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        double[] move = rigid(0, 0, 1, 90, 5, 0, 0);
        try (PointCloud source = cloud(pts); PointCloud target = cloud(applyTransform(move, pts))) {
            int[] corres = {0, 0, 1, 1, 2, 2};
            try (CorrespondenceChecker edge = new CorrespondenceChecker(Library.CHECKER_EDGE_LENGTH)) {
                assertEquals(0.9, edge.getThreshold(), "default from o3d_correspondence_checker_init");
                assertEquals(1, edge.check(source, target, corres, null), "rigid motion keeps edge lengths");
                try (PointCloud stretched = cloud(new double[] {0, 0, 0, 2, 0, 0, 0, 1, 0})) {
                    assertEquals(0, edge.check(source, stretched, corres, null));
                }
            }
            CorrespondenceChecker distance = checker(Library.CHECKER_DISTANCE, 0.01);
            assertEquals(0, distance.check(source, target, corres, null));
            assertEquals(1, distance.check(source, target, corres, move));
            source.setArray(Library.POINTCLOUD_NORMALS, new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1});
            target.setArray(Library.POINTCLOUD_NORMALS, new double[] {0, 0, 1, 0, 0, 1, 1, 0, 0});
            assertEquals(0, checker(Library.CHECKER_NORMAL, 0.5).check(source, target, corres, null), "a normal off by 90 deg");
            target.setArray(Library.POINTCLOUD_NORMALS, new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1});
            assertEquals(1, new CorrespondenceChecker(Library.CHECKER_NORMAL).check(source, target, corres, null));
            assertInvalid(() -> checker(Library.CHECKER_DISTANCE, -1).check(source, target, corres, null));
            assertInvalid(() -> distance.check(source, target, new int[] {0, 7}, null));
            assertInvalid(() -> distance.check(source, target, new int[] {0}, null));
            distance.close();
        }
    }

    /** A global registration {@code r} of the source moved by {@code moved} recovers moved^-1: r * moved is near the identity. */
    static void checkGlobal(double[] r, double[] moved, double[] truthPoints, String what) {
        double[] residual = mul4(tf(r), moved);
        double angle = angleDeg(residual), gap = rmsGap(residual, IDENTITY, truthPoints);
        System.out.println("  " + what + ": " + angle + " deg, " + gap + " m, fitness " + r[16]);
        assertTrue(angle < 5, what + ": rotation error " + angle + " deg");
        assertTrue(gap < 0.1, what + ": RMS gap " + gap + " m");
    }

    /** A 0.05-voxel copy of a shared scan with unit normals, as in Open3D's global registration tutorial. */
    static PointCloud preprocessed(String rel) {
        try (PointCloud full = read(data(rel))) {
            return withUnitNormals(full.voxelDownSample(0.05), 0.1);
        }
    }

    @Test
    void ransacAndFgrRecoverALargeRotationOfCloudBin0OntoCloudBin1() {
        try (PointCloud source = preprocessed("open3d/Feature/cloud_bin_0.pcd");
             PointCloud target = preprocessed("open3d/Feature/cloud_bin_1.pcd");
             Feature f0 = fpfh(source, 0.25, 100, null, 0);
             Feature f1 = fpfh(target, 0.25, 100, null, 0);
             RansacOptions opts = new RansacOptions(); RansacOptions defaults = new RansacOptions();
             FgrOptions fgrOpts = new FgrOptions()) {
            // cloud_bin_0 and cloud_bin_1 are aligned (to about 0.4 deg / 17 mm): moving the source by T makes the
            // registration T^-1. FPFH is rotation invariant, so f0 still describes the moved source.
            double[] truthPoints = points(source);
            double[] t = rigid(0.48, 0.6, 0.64, 70, 0.4, -0.3, 0.2);
            source.transform(t);
            CorrespondenceChecker[] checkers = {checker(Library.CHECKER_EDGE_LENGTH, 0.9), checker(Library.CHECKER_DISTANCE, 0.075)};
            assertEquals(0, defaults.getUseSeed(), "unseeded by default");
            assertEquals(3, defaults.getRansacN());
            opts.setUseSeed(1);
            opts.setSeed(42);
            opts.setMaxIteration(100000);
            opts.setConfidence(0.999);
            opts.setMutualFilter(1);
            double[] r = run(Library.registerRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts));
            checkGlobal(r, t, truthPoints, "RANSAC");
            assertTrue(r[16] > 0.3, "fitness " + r[16]);
            // refined by point-to-plane ICP, it lands within the accuracy of the two scans' own alignment
            try (IcpOptions p2l = new IcpOptions()) {
                p2l.setEstimation(Library.ESTIMATION_POINT_TO_PLANE);
                double[] refined = tf(run(Library.registerIcp(source, target, 0.05, tf(r), p2l)));
                assertTrue(angleDeg(mul4(refined, t)) < 1, "refined rotation error");
                assertTrue(rmsGap(mul4(refined, t), IDENTITY, truthPoints) < 0.02, "refined within 2 cm");
            }
            double[] again = run(Library.registerRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts));
            assertArrayEquals(tf(r), tf(again), 0.0, "same seed, same result");
            opts.setNumThreads(1);
            double[] one = run(Library.registerRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts));
            opts.setNumThreads(2);
            double[] two = run(Library.registerRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts));
            assertArrayEquals(tf(one), tf(two), 0.0, "1 vs 2 threads");
            assertArrayEquals(tf(r), tf(one), 0.0, "explicit vs default thread count");

            int[] corres = Library.correspondencesFromFeatures(f0, f1, 1, 0.1, 0);
            checkGlobal(run(Library.registerRansacBasedOnCorrespondence(source, target, corres, 0.075, checkers, opts)), t, truthPoints,
                    "RANSAC on correspondences");

            fgrOpts.setMaximumCorrespondenceDistance(0.025);
            fgrOpts.setUseSeed(1);
            fgrOpts.setSeed(7);
            checkGlobal(run(Library.registerFgrBasedOnFeatureMatching(source, target, f0, f1, fgrOpts)), t, truthPoints, "FGR");
            checkGlobal(run(Library.registerFgrBasedOnCorrespondence(source, target, corres, fgrOpts)), t, truthPoints,
                    "FGR on correspondences");

            // cancel from the callbacks; a throwing callback cancels too
            int[] calls = {0};
            opts.setProgress(f -> { calls[0]++; return false; });
            assertStatus(Library.ERROR_CANCELLED,
                    () -> Library.registerRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts));
            assertEquals(1, calls[0], "no progress call after cancelling");
            opts.setProgress(f -> { throw new IllegalStateException("boom"); });
            assertStatus(Library.ERROR_CANCELLED, () -> Library.registerRansacBasedOnCorrespondence(source, target, corres, 0.075, null, opts));
            opts.setProgress(null);
            try (FgrOptions cancel = new FgrOptions()) {
                cancel.setProgress(f -> false);
                assertStatus(Library.ERROR_CANCELLED, () -> Library.registerFgrBasedOnFeatureMatching(source, target, f0, f1, cancel));
            }

            // bad arguments
            try (RansacOptions two3 = new RansacOptions(); FgrOptions half = new FgrOptions()) {
                two3.setRansacN(2);
                assertInvalid(() -> Library.registerRansacBasedOnCorrespondence(source, target, corres, 0.075, null, two3));
                half.setDivisionFactor(0.5);
                assertInvalid(() -> Library.registerFgrBasedOnCorrespondence(source, target, corres, half));
            }
            assertInvalid(() -> Library.registerRansacBasedOnCorrespondence(source, target, new int[] {0, 1, 2, 3, 4, 1 << 30}, 0.075, null, null));
            assertInvalid(() -> Library.registerRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075,
                    new CorrespondenceChecker[] {checker(Library.CHECKER_EDGE_LENGTH, 2)}, null));
            try (Feature wrong = Feature.create(33, 10)) {
                assertInvalid(() -> Library.registerFgrBasedOnFeatureMatching(source, target, wrong, f1, null));
            }
            assertInvalid(() -> Library.registerRansacBasedOnFeatureMatching(source, target, null, f1, 0.075, null, null));
        }
    }

    @Test
    void globalRandomSeedMakesUnseededRansacReproducible() {
        double[] pts = randomPoints(300, 9, 1, 1, 1);
        double[] t = rigid(0, 0.6, 0.8, 40, 0.1, 0.2, -0.1);
        try (PointCloud source = cloud(pts); PointCloud target = cloud(applyTransform(t, pts)); RansacOptions opts = new RansacOptions()) {
            // the true pair of every point, except every 10th, which is paired with a wrong point
            int[] corres = new int[600];
            for (int i = 0; i < 300; i++) {
                corres[2 * i] = i;
                corres[2 * i + 1] = i % 10 == 0 ? (i * 7 + 3) % 300 : i;
            }
            opts.setMaxIteration(2000);
            Library.randomSeed(123);
            double[] a = run(Library.registerRansacBasedOnCorrespondence(source, target, corres, 0.01, null, opts));
            Library.randomSeed(123);
            double[] b = run(Library.registerRansacBasedOnCorrespondence(source, target, corres, 0.01, null, opts));
            assertArrayEquals(tf(a), tf(b), 0.0, "same global seed, same result");
            assertArrayEquals(t, tf(a), 1e-6, "exact pairs give the transform");
            assertTrue(a[16] >= 0.9 - 1e-12, "fitness " + a[16]);
        }
    }

    @Test
    void poseGraphNodesEdgesCopyClearBadInput() {
        try (PoseGraph g = new PoseGraph()) {
            g.addNode(null);
            double[] p1 = rigid(0, 0, 1, 30, 1, 2, 3);
            g.addNode(p1);
            assertEquals(2, g.numNodes());
            assertArrayEquals(IDENTITY, g.getNode(0), 0.0);
            assertArrayEquals(p1, g.getNode(1), 0.0);
            double[] info = diagonal6(100);
            PoseGraphEdge e = edge(1, 0, p1, info, true);
            e.setConfidence(0.5);
            g.addEdge(e);
            try (PoseGraphEdge back = g.getEdge(0)) {
                assertEquals(1, back.getSourceNodeId());
                assertEquals(0, back.getTargetNodeId());
                assertEquals(1, back.getUncertain());
                assertEquals(0.5, back.getConfidence());
                assertArrayEquals(p1, back.getTransformation(), 0.0);
                assertArrayEquals(info, back.getInformation(), 0.0);
            }
            PoseGraphEdge d = new PoseGraphEdge();
            assertArrayEquals(IDENTITY, d.getTransformation(), 0.0, "defaults from o3d_pose_graph_edge_init");
            assertArrayEquals(diagonal6(1), d.getInformation(), 0.0);
            assertEquals(0, d.getUncertain());
            assertEquals(1, d.getConfidence());
            assertInvalid(() -> d.setTransformation(new double[3]));
            g.setEdge(0, d);
            assertEquals(0, g.getEdge(0).getUncertain());
            assertEquals(1, g.numEdges());
            g.setNode(0, p1);
            assertArrayEquals(p1, nodes(g)[0], 0.0);
            try (PoseGraph copy = g.clone()) {
                g.clear();
                assertEquals(0, g.numNodes());
                assertEquals(0, g.numEdges());
                assertEquals(2, copy.numNodes());
                assertEquals(1, copy.numEdges());
            }
            assertInvalid(() -> g.getNode(0));
            assertInvalid(() -> g.getEdge(3));
            double[] scaled = IDENTITY.clone();
            scaled[0] = 2;
            assertInvalid(() -> g.addNode(scaled));
            double[] nan = IDENTITY.clone();
            nan[3] = Double.NaN;
            assertInvalid(() -> g.addNode(nan));
            assertInvalid(() -> g.addNode(new double[15]));
            assertInvalid(() -> g.addEdge(null));
            g.addNode(null);
            g.addEdge(edge(0, 5, null, null, false));
            assertInvalid(() -> Library.globalOptimization(g, null));
            assertEquals(1, g.numNodes());
            assertEquals(1, g.numEdges());
        }
        PoseGraph gone = new PoseGraph();
        gone.close();
        assertThrows(IllegalStateException.class, () -> gone.addNode(null));
    }

    @Test
    void poseGraphJsonRoundTripOfTestPoseGraph() throws Exception {
        try (PoseGraph g = Library.ioReadPoseGraph(data("open3d/test_pose_graph.json"))) {
            assertEquals(2, g.numNodes());
            assertEquals(2, g.numEdges());
            // The file is column-major: row-major (0, 1) is its element 4 (poses) / 6 (information).
            double[] n0 = g.getNode(0);
            assertEquals(0.1700186162907804, n0[1], 0.0);
            assertEquals(0.12717062898648024, n0[4], 0.0);
            try (PoseGraphEdge e0 = g.getEdge(0)) {
                assertEquals(1, e0.getSourceNodeId());
                assertEquals(0, e0.getTargetNodeId());
                assertEquals(0, e0.getUncertain());
                assertEquals(-0.03012176885280926, e0.getTransformation()[1], 0.0);
                assertEquals(0.03976561784722432, e0.getInformation()[1], 0.0);
                assertEquals(-0.2957548753318888, e0.getInformation()[6], 0.0);
            }
            String path = tmp.resolve("graph.json").toString();
            Library.ioWritePoseGraph(path, g);
            try (PoseGraph back = Library.ioReadPoseGraph(path)) {
                assertEquals(2, back.numNodes());
                assertEquals(2, back.numEdges());
                for (int i = 0; i < 2; i++) {
                    assertArrayEquals(g.getNode(i), back.getNode(i), 0.0, "node " + i);
                    try (PoseGraphEdge a = g.getEdge(i); PoseGraphEdge b = back.getEdge(i)) {
                        assertEquals(a.getSourceNodeId(), b.getSourceNodeId());
                        assertEquals(a.getTargetNodeId(), b.getTargetNodeId());
                        assertEquals(a.getUncertain(), b.getUncertain());
                        assertEquals(a.getConfidence(), b.getConfidence());
                        assertArrayEquals(a.getTransformation(), b.getTransformation(), 0.0);
                        assertArrayEquals(a.getInformation(), b.getInformation(), 0.0);
                    }
                }
            }
            // its second edge joins node 2 of a two-node graph: refused, graph unchanged (Open3D refuses it too)
            double[][] before = nodes(g);
            assertInvalid(() -> Library.globalOptimization(g, null));
            assertArrayEquals(before[0], g.getNode(0), 0.0);
            assertArrayEquals(before[1], g.getNode(1), 0.0);
            assertEquals(2, g.numEdges());
        }
        Path bad = tmp.resolve("bad.json");
        Files.writeString(bad, "{\"class_name\": \"PoseGraph\", \"nodes\": [");
        assertStatus(Library.ERROR_PARSE, () -> Library.ioReadPoseGraph(bad.toString()));
        assertStatus(Library.ERROR_IO, () -> Library.ioReadPoseGraph(tmp.resolve("missing.json").toString()));
    }

    @Test
    void globalOptimizationPrunesAFalseLoopClosure() {
        // Five poses 1 m apart on x. Edge (s, t, T) with T = pose_t^-1 pose_s. Odometry i -> i+1, two true loop
        // closures and one false one (0 -> 4 claiming a 30 deg turn and a 2 m sideways step).
        double[] info = diagonal6(1000);
        try (PoseGraph g = new PoseGraph(); GlobalOptimizationOptions cancel = new GlobalOptimizationOptions();
             GlobalOptimizationOptions opts = new GlobalOptimizationOptions()) {
            for (int i = 0; i < 5; i++) g.addNode(rigid(0, 0, 1, 0, i, 0, 0));
            g.setNode(2, rigid(0, 0, 1, 2, 2.05, 0.03, 0)); // a perturbed start
            for (int i = 0; i < 4; i++) g.addEdge(edge(i, i + 1, rigid(0, 0, 1, 0, -1, 0, 0), info, false));
            g.addEdge(edge(0, 3, rigid(0, 0, 1, 0, -3, 0, 0), info, true));
            g.addEdge(edge(1, 4, rigid(0, 0, 1, 0, -3, 0, 0), info, true));
            g.addEdge(edge(0, 4, rigid(0, 0, 1, 30, -1, 2, 0), info, true));
            double[][] before = nodes(g);
            cancel.setProgress(f -> false);
            assertStatus(Library.ERROR_CANCELLED, () -> Library.globalOptimization(g, cancel));
            for (int i = 0; i < 5; i++) assertArrayEquals(before[i], g.getNode(i), 0.0, "cancel leaves node " + i);
            assertEquals(7, g.numEdges());

            int[] calls = {0};
            opts.setProgress(f -> { calls[0]++; return true; });
            assertEquals(Library.GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT, opts.getMethod());
            assertEquals(-1, opts.getReferenceNode());
            assertEquals(0.25, opts.getEdgePruneThreshold());
            try (GlobalOptimizationSummary summary = Library.globalOptimization(g, opts)) {
                String text = summary.getIterations() + " iterations, " + summary.getInitialResidual() + " -> " + summary.getFinalResidual();
                assertTrue(calls[0] > 0, "progress called");
                assertEquals(1, summary.getPrunedEdges(), text);
                assertEquals(6, g.numEdges());
                for (int i = 0; i < g.numEdges(); i++)
                    try (PoseGraphEdge e = g.getEdge(i)) {
                        assertFalse(e.getSourceNodeId() == 0 && e.getTargetNodeId() == 4, "the false closure is gone");
                        if (e.getUncertain() != 0) assertTrue(e.getConfidence() > 0.9, "true closures keep their confidence");
                    }
                assertTrue(summary.getFinalResidual() < summary.getInitialResidual() && summary.getIterations() > 0, text);
            }
            for (int i = 0; i < 5; i++) assertArrayEquals(rigid(0, 0, 1, 0, i, 0, 0), g.getNode(i), 1e-4, "node " + i);
        }
    }
}
