// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.O3dTest.applyTransform;
import static org.o3d.O3dTest.assertStatus;
import static org.o3d.O3dTest.dataFile;
import static org.o3d.O3dTest.randomPoints;

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

    static final double[] IDENTITY = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

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
        pc.estimateNormals(SearchParam.hybrid(radius, 30));
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

    @Test
    void featureCreateDataViewResizeSelectCopy() {
        double[] values = range(12); // 3 descriptors of 4
        try (Feature f = new Feature(values, 4, 3)) {
            assertEquals(4, f.dimension());
            assertEquals(3, f.num());
            assertArrayEquals(values, f.data());
            double[] view = new double[12];
            f.dataView().asDoubleBuffer().get(view);
            assertArrayEquals(values, view);
            try (Feature picked = f.selectByIndex(new long[] {2, 0})) {
                assertArrayEquals(new double[] {8, 9, 10, 11, 0, 1, 2, 3}, picked.data());
            }
            try (Feature rest = f.selectByIndex(new long[] {1}, true)) {
                assertArrayEquals(new double[] {0, 1, 2, 3, 8, 9, 10, 11}, rest.data());
            }
            double[] negated = Arrays.stream(values).map(v -> -v).toArray();
            try (Feature copy = f.copy()) {
                f.setData(negated);
                assertArrayEquals(values, copy.data(), "copy is deep");
                assertEquals(-5, f.data()[5]);
            }
            f.resize(4, 5);
            double[] resized = f.data();
            assertArrayEquals(negated, Arrays.copyOf(resized, 12));
            assertTrue(Arrays.stream(resized, 12, 20).allMatch(v -> v == 0), "zero padding");
            assertThrows(IllegalArgumentException.class, () -> f.setData(new double[3]));
            assertStatus(Status.INVALID_ARGUMENT, () -> f.selectByIndex(new long[] {5}));
            assertThrows(IllegalArgumentException.class, () -> f.resize(-1, 2));
        }
        try (Feature zeros = new Feature(33, 2)) {
            assertArrayEquals(new double[66], zeros.data());
        }
        try (Feature empty = new Feature()) {
            assertEquals(0, empty.dimension());
            assertEquals(0, empty.data().length);
        }
        assertStatus(Status.INVALID_ARGUMENT, () -> new Feature(new double[] {1, Double.NaN}, 2, 1));
        assertThrows(IllegalArgumentException.class, () -> new Feature(new double[5], 2, 3));
        Feature gone = new Feature(2, 2);
        gone.close();
        assertThrows(IllegalStateException.class, gone::num);
    }

    @Test
    void nullNativeHandlesThrowO3dException() {
        long[] n = new long[1];
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_feature_num(n, 0));
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_pose_graph_num_nodes(n, 0));
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_kdtree_dimension(n, 0));
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_global_optimization(null, 0, null));
        long[] out = new long[1];
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_register_ransac_based_on_feature_matching(
                out, 0, 0, 0, 0, 0.1, null, 0, null));
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_register_fgr_based_on_correspondence(out, 0, 0, null, 0, null));
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_compute_fpfh_feature(out, 0, null, null, 0, 0));
        assertEquals(0, out[0]);
        O3dNative.o3d_feature_destroy(0); // NULL is a no-op
        O3dNative.o3d_pose_graph_destroy(0);
    }

    @Test
    void featureFileRoundTripAndBadFiles() throws Exception {
        double[] values = IntStream.range(0, 15).mapToDouble(i -> Math.sqrt(i) - 1.5).toArray();
        String path = tmp.resolve("f.bin").toString();
        try (Feature f = new Feature(values, 5, 3)) {
            IO.writeFeature(path, f);
        }
        assertEquals(8 + 15 * 8, Files.size(Path.of(path)), "int32 dimension, int32 num, then float64 values");
        try (Feature back = IO.readFeature(path)) {
            assertEquals(5, back.dimension());
            assertEquals(3, back.num());
            assertArrayEquals(values, back.data(), 0.0);
        }
        Files.write(Path.of(path), new byte[] {33, 0, 0, 0, 10, 0, 0, 0, 1, 2, 3});
        assertStatus(Status.PARSE, () -> IO.readFeature(path));
        assertStatus(Status.IO, () -> IO.readFeature(tmp.resolve("missing.bin").toString()));
        assertThrows(NullPointerException.class, () -> IO.writeFeature(path, null));
    }

    @Test
    void kdTreeOverAFeatureAndOverXdPoints() {
        Random rnd = new Random(11);
        double[] pts = rnd.doubles(1000).toArray(); // 200 points of 5 dimensions
        double[] queries = rnd.doubles(15).toArray();
        try (Feature f = new Feature(pts, 5, 200); KDTreeFlann tree = new KDTreeFlann(f);
             KDTreeFlann xd = KDTreeFlann.fromPointsXd(pts, 5)) {
            assertEquals(5, tree.dimension());
            assertEquals(5, xd.dimension());
            assertEquals(200, tree.size());
            NeighborResult r = tree.searchKnnXd(queries, 3);
            assertArrayEquals(r.indices, xd.searchKnnXd(queries, 3).indices, "feature tree == xd tree");
            for (int q = 0; q < 3; q++) {
                final int qq = q;
                int[] order = IntStream.range(0, 200).boxed()
                        .sorted((i, j) -> Double.compare(dist2(pts, i, queries, qq), dist2(pts, j, queries, qq)))
                        .limit(3).mapToInt(Integer::intValue).toArray();
                assertArrayEquals(order, Arrays.copyOfRange(r.indices, (int) r.offsets[q], (int) r.offsets[q + 1]), "query " + q);
            }
            assertEquals(4, tree.searchRadiusXd(queries, 0.3).offsets.length);
            assertThrows(IllegalArgumentException.class, () -> tree.searchKnnXd(new double[] {1, 2, 3}, 1));
            assertThrows(IllegalArgumentException.class, () -> KDTreeFlann.fromPointsXd(new double[7], 2));
        }
        try (PointCloud pc = new PointCloud(randomPoints(10, 1, 1, 1, 1)); KDTreeFlann t3 = new KDTreeFlann(pc)) {
            assertEquals(3, t3.dimension());
        }
    }

    static double dist2(double[] pts, int i, double[] queries, int q) {
        double s = 0;
        for (int k = 0; k < 5; k++) s += Math.pow(pts[5 * i + k] - queries[5 * q + k], 2);
        return s;
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
        try (Feature fs = new Feature(src, d, n); Feature ft = new Feature(tgt, d, n)) {
            for (boolean mutual : new boolean[] {false, true}) {
                int[] pairs = Registration.correspondencesFromFeatures(fs, ft, mutual, 0.1, 0);
                assertEquals(2 * n, pairs.length);
                for (int i = 0; i < n; i++) {
                    assertEquals(i, pairs[2 * i]);
                    assertEquals((int) perm.get(i), pairs[2 * i + 1], "pair " + i);
                }
            }
            try (Feature other = new Feature(3, n)) {
                assertStatus(Status.INVALID_ARGUMENT, () -> Registration.correspondencesFromFeatures(fs, other));
            }
        }
    }

    @Test
    void fpfhOnCloudBin0MatchesTheStoredFeaturesShape() {
        try (Feature stored = IO.readFeature(dataFile("open3d/Feature/cloud_bin_0.fpfh.bin").getPath());
             PointCloud cloud = IO.readPointCloud(dataFile("open3d/Feature/cloud_bin_0.pcd").getPath());
             Feature fpfh = Registration.computeFpfhFeature(cloud, SearchParam.hybrid(0.25, 100))) {
            assertEquals(33, stored.dimension());
            assertEquals(3903, stored.num());
            assertEquals(stored.dimension(), fpfh.dimension());
            assertEquals(cloud.size(), fpfh.num());
            double[] data = fpfh.data();
            // Open3D's FPFH normalises each 11-bin block of a point's own SPFH and of the distance-weighted sum of
            // its neighbours' SPFHs to 100, so every block of the result sums to 200 (analytic; every point here has
            // neighbours within 0.25).
            for (int i = 0; i < fpfh.num(); i += 97)
                for (int b = 0; b < 3; b++)
                    assertEquals(200, Arrays.stream(data, 33 * i + 11 * b, 33 * i + 11 * b + 11).sum(), 1e-9, "p" + i + " b" + b);
            long[] some = {0, 1234, 3902};
            try (Feature part = Registration.computeFpfhFeature(cloud, SearchParam.hybrid(0.25, 100), some, 0);
                 Feature picked = fpfh.selectByIndex(some)) {
                assertArrayEquals(picked.data(), part.data(), 1e-12, "indices: neighbourhoods from the whole cloud");
            }
            try (Feature one = Registration.computeFpfhFeature(cloud, SearchParam.hybrid(0.25, 100), null, 1)) {
                assertArrayEquals(data, one.data(), 0.0, "same on 1 thread");
            }
        }
        try (PointCloud bare = new PointCloud(randomPoints(50, 2, 1, 1, 1))) {
            assertStatus(Status.INVALID_ARGUMENT, () -> Registration.computeFpfhFeature(bare, null));
        }
    }

    @Test
    void robustKernelWeights() {
        assertEquals(1, RobustKernel.l2Loss().weight(3), 0);
        assertEquals(0.5, RobustKernel.l1Loss().weight(-2), 1e-15);
        assertEquals(1, RobustKernel.huberLoss(1).weight(0.5), 1e-15);
        assertEquals(0.25, RobustKernel.huberLoss(1).weight(4), 1e-15);
        assertEquals(0.5, RobustKernel.cauchyLoss(2).weight(2), 1e-15);
        assertEquals(0.25, RobustKernel.gmLoss(1).weight(1), 1e-15);
        assertEquals(0.5625, RobustKernel.tukeyLoss(1).weight(0.5), 1e-15);
        assertEquals(0, RobustKernel.tukeyLoss(1).weight(1.5), 0);
        IcpOptions opts = new IcpOptions();
        assertEquals(RobustKernel.Kind.L2, opts.kernel.kind());
        assertEquals(0.968, opts.lambdaGeometric);
        assertEquals(1e-3, opts.epsilon);
        assertStatus(Status.INVALID_ARGUMENT, () -> RobustKernel.huberLoss(-1).weight(1));
    }

    @Test
    void coloredGeneralizedAndSymmetricIcpRecoverASmallTransform() {
        double[] t = rigid(0.6, 0.0, 0.8, 3, 0.02, -0.015, 0.01);
        IcpOptions opts = new IcpOptions().maxIteration(60).relativeFitness(1e-9).relativeRmse(1e-9);
        try (PointCloud fragment = IO.readPointCloud(dataFile("open3d/fragment.pcd").getPath());
             PointCloud source = withUnitNormals(fragment.voxelDownSample(0.02), 0.04);
             PointCloud target = source.copy()) {
            target.transform(t);
            assertTrue(source.hasColors() && target.hasNormals());
            RegistrationResult colored = Registration.registrationColoredIcp(source, target, 0.05, null, opts);
            assertArrayEquals(t, colored.transformation, 2e-3, "colored");
            RegistrationResult generalized = Registration.registrationGeneralizedIcp(source, target, 0.05, null, opts);
            assertArrayEquals(t, generalized.transformation, 2e-3, "generalized");
            RegistrationResult symmetric = Registration.registrationSymmetricIcp(source, target, 0.05, null, opts);
            assertArrayEquals(t, symmetric.transformation, 2e-3, "symmetric");
            assertTrue(colored.fitness > 0.99 && generalized.fitness > 0.99 && symmetric.fitness > 0.99);
            opts.estimation(IcpOptions.Estimation.GENERALIZED);
            assertArrayEquals(generalized.transformation, Registration.registrationIcp(source, target, 0.05, null, opts).transformation, 0.0);
            try (PointCloud plain = new PointCloud(source.getPoints())) {
                assertStatus(Status.INVALID_ARGUMENT, () -> Registration.registrationColoredIcp(plain, target, 0.05, null, null));
            }
        }
    }

    @Test
    void tukeyKernelKeepsPointToPlaneIcpOnTargetWith30PercentOutliers() {
        // 30% of the source are outliers: points lifted 4 to 8 cm off the surface along their normals. Near the true
        // transform their point-to-plane residuals exceed the Tukey scale (3 cm), so they get weight 0; L2 is pulled off.
        double[] t = rigid(0, 0, 1, 1, 0.02, 0.01, 0);
        try (PointCloud scan = IO.readPointCloud(dataFile("open3d/Feature/cloud_bin_0.pcd").getPath());
             PointCloud clean = withUnitNormals(scan.voxelDownSample(0.03), 0.06);
             PointCloud target = clean.copy();
             PointCloud source = clean.copy()) {
            target.transform(t);
            double[] pts = clean.getPoints(), nrm = clean.getNormals();
            int n = (int) clean.size(), outliers = (int) (0.3 * n / 0.7);
            Random rnd = new Random(3);
            double[] all = Arrays.copyOf(pts, 3 * (n + outliers));
            for (int i = 0; i < outliers; i++) {
                int j = rnd.nextInt(n);
                double lift = 0.04 + 0.04 * rnd.nextDouble();
                for (int k = 0; k < 3; k++) all[3 * (n + i) + k] = pts[3 * j + k] + lift * nrm[3 * j + k];
            }
            source.setPoints(all);
            IcpOptions opts = new IcpOptions().estimation(IcpOptions.Estimation.POINT_TO_PLANE).maxIteration(100)
                    .relativeFitness(1e-9).relativeRmse(1e-9).kernel(RobustKernel.tukeyLoss(0.03));
            RegistrationResult robust = Registration.registrationIcp(source, target, 0.1, null, opts);
            RegistrationResult plain = Registration.registrationIcp(source, target, 0.1, null, opts.kernel(RobustKernel.l2Loss()));
            double robustGap = rmsGap(robust.transformation, t, pts), plainGap = rmsGap(plain.transformation, t, pts);
            System.out.println("  Tukey: " + robustGap + " m off, L2: " + plainGap + " m off");
            assertTrue(angleDeg(mul4(robust.transformation, invertRigid(t))) < 0.05, "rotation within 0.05 deg");
            assertTrue(robustGap < 1e-3, "Tukey within 1 mm: " + robustGap);
            assertTrue(plainGap > 0.01, "L2 is pulled more than 1 cm off by the outliers: " + plainGap);
        }
    }

    @Test
    void correspondenceCheckers() {
        double[] pts = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        double[] move = rigid(0, 0, 1, 90, 5, 0, 0);
        try (PointCloud source = new PointCloud(pts); PointCloud target = new PointCloud(applyTransform(move, pts))) {
            int[] corres = {0, 0, 1, 1, 2, 2};
            assertEquals(0.9, CorrespondenceChecker.edgeLength().threshold());
            assertTrue(CorrespondenceChecker.edgeLength(0.9).check(source, target, corres, null), "rigid motion keeps edge lengths");
            try (PointCloud stretched = new PointCloud(new double[] {0, 0, 0, 2, 0, 0, 0, 1, 0})) {
                assertFalse(CorrespondenceChecker.edgeLength(0.9).check(source, stretched, corres, null));
            }
            CorrespondenceChecker distance = CorrespondenceChecker.distance(0.01);
            assertFalse(distance.check(source, target, corres, null));
            assertTrue(distance.check(source, target, corres, move));
            source.setNormals(new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1});
            target.setNormals(new double[] {0, 0, 1, 0, 0, 1, 1, 0, 0});
            assertFalse(CorrespondenceChecker.normal(0.5).check(source, target, corres, null), "a normal off by 90 deg");
            target.setNormals(new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1});
            assertTrue(CorrespondenceChecker.normal().check(source, target, corres, null));
            assertStatus(Status.INVALID_ARGUMENT, () -> CorrespondenceChecker.distance(-1).check(source, target, corres, null));
            assertStatus(Status.INVALID_ARGUMENT, () -> distance.check(source, target, new int[] {0, 7}, null));
            assertThrows(IllegalArgumentException.class, () -> distance.check(source, target, new int[] {0}, null));
        }
    }

    /** A global registration {@code r} of the source moved by {@code moved} recovers moved^-1: r * moved is near the identity. */
    static void checkGlobal(RegistrationResult r, double[] moved, double[] truthPoints, String what) {
        double[] residual = mul4(r.transformation, moved);
        double angle = angleDeg(residual), gap = rmsGap(residual, IDENTITY, truthPoints);
        System.out.println("  " + what + ": " + angle + " deg, " + gap + " m, fitness " + r.fitness);
        assertTrue(angle < 5, what + ": rotation error " + angle + " deg");
        assertTrue(gap < 0.1, what + ": RMS gap " + gap + " m");
    }

    /** A 0.05-voxel copy of a shared scan with unit normals, as in Open3D's global registration tutorial. */
    static PointCloud preprocessed(String rel) {
        try (PointCloud full = IO.readPointCloud(dataFile(rel).getPath())) {
            return withUnitNormals(full.voxelDownSample(0.05), 0.1);
        }
    }

    @Test
    void ransacAndFgrRecoverALargeRotationOfCloudBin0OntoCloudBin1() {
        try (PointCloud source = preprocessed("open3d/Feature/cloud_bin_0.pcd");
             PointCloud target = preprocessed("open3d/Feature/cloud_bin_1.pcd");
             Feature f0 = Registration.computeFpfhFeature(source, SearchParam.hybrid(0.25, 100));
             Feature f1 = Registration.computeFpfhFeature(target, SearchParam.hybrid(0.25, 100))) {
            // cloud_bin_0 and cloud_bin_1 are aligned (to about 0.4 deg / 17 mm): moving the source by T makes the
            // registration T^-1. FPFH is rotation invariant, so f0 still describes the moved source.
            double[] truthPoints = source.getPoints();
            double[] t = rigid(0.48, 0.6, 0.64, 70, 0.4, -0.3, 0.2);
            source.transform(t);
            List<CorrespondenceChecker> checkers = List.of(CorrespondenceChecker.edgeLength(0.9), CorrespondenceChecker.distance(0.075));
            RansacOptions opts = new RansacOptions().seed(42L).maxIteration(100000).confidence(0.999).mutualFilter(true);
            assertNull(new RansacOptions().seed);
            assertEquals(3, new RansacOptions().ransacN);
            RegistrationResult r = Registration.registrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts);
            checkGlobal(r, t, truthPoints, "RANSAC");
            assertTrue(r.fitness > 0.3, "fitness " + r.fitness);
            // refined by point-to-plane ICP, it lands within the accuracy of the two scans' own alignment
            RegistrationResult refined = Registration.registrationIcp(source, target, 0.05, r.transformation,
                    new IcpOptions().estimation(IcpOptions.Estimation.POINT_TO_PLANE));
            assertTrue(angleDeg(mul4(refined.transformation, t)) < 1, "refined rotation error");
            assertTrue(rmsGap(mul4(refined.transformation, t), IDENTITY, truthPoints) < 0.02, "refined within 2 cm");
            RegistrationResult again = Registration.registrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts);
            assertArrayEquals(r.transformation, again.transformation, 0.0, "same seed, same result");
            RegistrationResult one = Registration.registrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers,
                    opts.numThreads(1));
            RegistrationResult two = Registration.registrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers,
                    opts.numThreads(2));
            assertArrayEquals(one.transformation, two.transformation, 0.0, "1 vs 2 threads");
            assertArrayEquals(r.transformation, one.transformation, 0.0, "explicit vs default thread count");

            int[] corres = Registration.correspondencesFromFeatures(f0, f1, true, 0.1, 0);
            RegistrationResult rc = Registration.registrationRansacBasedOnCorrespondence(source, target, corres, 0.075, checkers, opts);
            checkGlobal(rc, t, truthPoints, "RANSAC on correspondences");

            FgrOptions fgrOpts = new FgrOptions().maximumCorrespondenceDistance(0.025).seed(7L);
            RegistrationResult fgr = Registration.registrationFgrBasedOnFeatureMatching(source, target, f0, f1, fgrOpts);
            checkGlobal(fgr, t, truthPoints, "FGR");
            RegistrationResult fc = Registration.registrationFgrBasedOnCorrespondence(source, target, corres, fgrOpts);
            checkGlobal(fc, t, truthPoints, "FGR on correspondences");

            // cancel from the callbacks; a throwing callback cancels too
            int[] calls = {0};
            opts.progress(f -> { calls[0]++; return false; });
            assertStatus(Status.CANCELLED,
                    () -> Registration.registrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts));
            assertEquals(1, calls[0], "no progress call after cancelling");
            opts.progress(f -> { throw new IllegalStateException("boom"); });
            assertStatus(Status.CANCELLED,
                    () -> Registration.registrationRansacBasedOnCorrespondence(source, target, corres, 0.075, null, opts));
            assertStatus(Status.CANCELLED, () -> Registration.registrationFgrBasedOnFeatureMatching(source, target, f0, f1,
                    new FgrOptions().progress(f -> false)));

            // bad arguments
            assertStatus(Status.INVALID_ARGUMENT, () -> Registration.registrationRansacBasedOnCorrespondence(source, target, corres, 0.075,
                    null, new RansacOptions().ransacN(2)));
            assertStatus(Status.INVALID_ARGUMENT, () -> Registration.registrationRansacBasedOnCorrespondence(source, target,
                    new int[] {0, 1, 2, 3, 4, 1 << 30}, 0.075, null, null));
            assertStatus(Status.INVALID_ARGUMENT, () -> Registration.registrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075,
                    List.of(CorrespondenceChecker.edgeLength(2)), null));
            assertStatus(Status.INVALID_ARGUMENT, () -> Registration.registrationFgrBasedOnCorrespondence(source, target, corres,
                    new FgrOptions().divisionFactor(0.5)));
            try (Feature wrong = new Feature(33, 10)) {
                assertStatus(Status.INVALID_ARGUMENT, () -> Registration.registrationFgrBasedOnFeatureMatching(source, target, wrong, f1, null));
            }
            assertThrows(NullPointerException.class,
                    () -> Registration.registrationRansacBasedOnFeatureMatching(source, target, null, f1, 0.075, null, null));
        }
    }

    @Test
    void globalRandomSeedMakesUnseededRansacReproducible() {
        double[] pts = randomPoints(300, 9, 1, 1, 1);
        double[] t = rigid(0, 0.6, 0.8, 40, 0.1, 0.2, -0.1);
        try (PointCloud source = new PointCloud(pts); PointCloud target = new PointCloud(applyTransform(t, pts))) {
            // the true pair of every point, except every 10th, which is paired with a wrong point
            int[] corres = new int[600];
            for (int i = 0; i < 300; i++) {
                corres[2 * i] = i;
                corres[2 * i + 1] = i % 10 == 0 ? (i * 7 + 3) % 300 : i;
            }
            RansacOptions opts = new RansacOptions().maxIteration(2000);
            Utility.Random.seed(123);
            RegistrationResult a = Registration.registrationRansacBasedOnCorrespondence(source, target, corres, 0.01, null, opts);
            Utility.Random.seed(123);
            RegistrationResult b = Registration.registrationRansacBasedOnCorrespondence(source, target, corres, 0.01, null, opts);
            assertArrayEquals(a.transformation, b.transformation, 0.0, "same global seed, same result");
            assertArrayEquals(t, a.transformation, 1e-6, "exact pairs give the transform");
            assertTrue(a.fitness >= 0.9 - 1e-12, "fitness " + a.fitness);
        }
    }

    @Test
    void poseGraphNodesEdgesCopyClearBadInput() {
        try (PoseGraph g = new PoseGraph()) {
            g.addNode(null);
            double[] p1 = rigid(0, 0, 1, 30, 1, 2, 3);
            g.addNode(p1);
            assertEquals(2, g.nodeCount());
            assertArrayEquals(IDENTITY, g.getNode(0), 0.0);
            assertArrayEquals(p1, g.getNode(1), 0.0);
            double[] info = diagonal6(100);
            PoseGraphEdge e = new PoseGraphEdge(1, 0, p1, info, true);
            e.confidence = 0.5;
            g.addEdge(e);
            PoseGraphEdge back = g.getEdge(0);
            assertEquals(1, back.sourceNodeId);
            assertEquals(0, back.targetNodeId);
            assertTrue(back.uncertain);
            assertEquals(0.5, back.confidence);
            assertArrayEquals(p1, back.transformation, 0.0);
            assertArrayEquals(info, back.information, 0.0);
            PoseGraphEdge d = new PoseGraphEdge();
            assertArrayEquals(IDENTITY, d.transformation, 0.0);
            assertArrayEquals(diagonal6(1), d.information, 0.0);
            assertFalse(d.uncertain);
            assertEquals(1, d.confidence);
            g.setEdge(0, d);
            assertFalse(g.getEdge(0).uncertain);
            assertEquals(1, g.edges().length);
            g.setNode(0, p1);
            assertArrayEquals(p1, g.nodes()[0], 0.0);
            try (PoseGraph copy = g.copy()) {
                g.clear();
                assertEquals(0, g.nodeCount());
                assertEquals(0, g.edgeCount());
                assertEquals(2, copy.nodeCount());
                assertEquals(1, copy.edgeCount());
            }
            assertStatus(Status.INVALID_ARGUMENT, () -> g.getNode(0));
            assertStatus(Status.INVALID_ARGUMENT, () -> g.getEdge(3));
            double[] scaled = IDENTITY.clone();
            scaled[0] = 2;
            assertStatus(Status.INVALID_ARGUMENT, () -> g.addNode(scaled));
            double[] nan = IDENTITY.clone();
            nan[3] = Double.NaN;
            assertStatus(Status.INVALID_ARGUMENT, () -> g.addNode(nan));
            assertThrows(IllegalArgumentException.class, () -> g.addNode(new double[15]));
            assertThrows(NullPointerException.class, () -> g.addEdge(null));
            g.addNode(null);
            g.addEdge(new PoseGraphEdge(0, 5, null, null, false));
            assertStatus(Status.INVALID_ARGUMENT, () -> Registration.globalOptimization(g));
            assertEquals(1, g.nodeCount());
            assertEquals(1, g.edgeCount());
        }
        PoseGraph gone = new PoseGraph();
        gone.close();
        assertThrows(IllegalStateException.class, () -> gone.addNode(null));
    }

    @Test
    void poseGraphJsonRoundTripOfTestPoseGraph() throws Exception {
        try (PoseGraph g = IO.readPoseGraph(dataFile("open3d/test_pose_graph.json").getPath())) {
            assertEquals(2, g.nodeCount());
            assertEquals(2, g.edgeCount());
            // The file is column-major: row-major (0, 1) is its element 4 (poses) / 6 (information).
            double[] n0 = g.getNode(0);
            assertEquals(0.1700186162907804, n0[1], 0.0);
            assertEquals(0.12717062898648024, n0[4], 0.0);
            PoseGraphEdge e0 = g.getEdge(0);
            assertEquals(1, e0.sourceNodeId);
            assertEquals(0, e0.targetNodeId);
            assertFalse(e0.uncertain);
            assertEquals(-0.03012176885280926, e0.transformation[1], 0.0);
            assertEquals(0.03976561784722432, e0.information[1], 0.0);
            assertEquals(-0.2957548753318888, e0.information[6], 0.0);
            String path = tmp.resolve("graph.json").toString();
            IO.writePoseGraph(path, g);
            try (PoseGraph back = IO.readPoseGraph(path)) {
                assertEquals(2, back.nodeCount());
                assertEquals(2, back.edgeCount());
                for (int i = 0; i < 2; i++) {
                    assertArrayEquals(g.getNode(i), back.getNode(i), 0.0, "node " + i);
                    PoseGraphEdge a = g.getEdge(i), b = back.getEdge(i);
                    assertEquals(a.sourceNodeId, b.sourceNodeId);
                    assertEquals(a.targetNodeId, b.targetNodeId);
                    assertEquals(a.uncertain, b.uncertain);
                    assertEquals(a.confidence, b.confidence);
                    assertArrayEquals(a.transformation, b.transformation, 0.0);
                    assertArrayEquals(a.information, b.information, 0.0);
                }
            }
            // its second edge joins node 2 of a two-node graph: refused, graph unchanged (Open3D refuses it too)
            double[][] before = g.nodes();
            assertStatus(Status.INVALID_ARGUMENT, () -> Registration.globalOptimization(g));
            assertArrayEquals(before[0], g.getNode(0), 0.0);
            assertArrayEquals(before[1], g.getNode(1), 0.0);
            assertEquals(2, g.edgeCount());
        }
        Path bad = tmp.resolve("bad.json");
        Files.writeString(bad, "{\"class_name\": \"PoseGraph\", \"nodes\": [");
        assertStatus(Status.PARSE, () -> IO.readPoseGraph(bad.toString()));
        assertStatus(Status.IO, () -> IO.readPoseGraph(tmp.resolve("missing.json").toString()));
    }

    @Test
    void globalOptimizationPrunesAFalseLoopClosure() {
        // Five poses 1 m apart on x. Edge (s, t, T) with T = pose_t^-1 pose_s. Odometry i -> i+1, two true loop
        // closures and one false one (0 -> 4 claiming a 30 deg turn and a 2 m sideways step).
        double[] info = diagonal6(1000);
        try (PoseGraph g = new PoseGraph()) {
            for (int i = 0; i < 5; i++) g.addNode(rigid(0, 0, 1, 0, i, 0, 0));
            g.setNode(2, rigid(0, 0, 1, 2, 2.05, 0.03, 0)); // a perturbed start
            for (int i = 0; i < 4; i++) g.addEdge(new PoseGraphEdge(i, i + 1, rigid(0, 0, 1, 0, -1, 0, 0), info, false));
            g.addEdge(new PoseGraphEdge(0, 3, rigid(0, 0, 1, 0, -3, 0, 0), info, true));
            g.addEdge(new PoseGraphEdge(1, 4, rigid(0, 0, 1, 0, -3, 0, 0), info, true));
            g.addEdge(new PoseGraphEdge(0, 4, rigid(0, 0, 1, 30, -1, 2, 0), info, true));
            double[][] before = g.nodes();
            assertStatus(Status.CANCELLED, () -> Registration.globalOptimization(g, new GlobalOptimizationOptions().progress(f -> false)));
            for (int i = 0; i < 5; i++) assertArrayEquals(before[i], g.getNode(i), 0.0, "cancel leaves node " + i);
            assertEquals(7, g.edgeCount());

            int[] calls = {0};
            GlobalOptimizationOptions opts = new GlobalOptimizationOptions().progress(f -> { calls[0]++; return true; });
            assertEquals(GlobalOptimizationOptions.Method.LEVENBERG_MARQUARDT, opts.method);
            assertEquals(-1, opts.referenceNode);
            assertEquals(0.25, opts.edgePruneThreshold);
            GlobalOptimizationSummary summary = Registration.globalOptimization(g, opts);
            assertTrue(calls[0] > 0, "progress called");
            assertEquals(1, summary.prunedEdges, summary.toString());
            assertEquals(6, g.edgeCount());
            for (PoseGraphEdge e : g.edges()) {
                assertFalse(e.sourceNodeId == 0 && e.targetNodeId == 4, "the false closure is gone");
                if (e.uncertain) assertTrue(e.confidence > 0.9, "true closures keep their confidence: " + e);
            }
            assertTrue(summary.finalResidual < summary.initialResidual && summary.iterations > 0, summary.toString());
            for (int i = 0; i < 5; i++) assertArrayEquals(rigid(0, 0, 1, 0, i, 0, 0), g.getNode(i), 1e-4, "node " + i);
        }
    }
}
