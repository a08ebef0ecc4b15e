// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.util.List;
import java.util.Objects;

/**
 * Prunes RANSAC hypotheses early (Open3D's CorrespondenceCheckerBasedOnEdgeLength / Distance / Normal).
 * Immutable; the factories without a threshold take the library's default (0.9, 0.075, 30 degrees).
 */
public final class CorrespondenceChecker {
    public enum Kind {
        /** CorrespondenceCheckerBasedOnEdgeLength(similarity_threshold in (0, 1]). */
        EDGE_LENGTH(O3dNativeConstants.O3D_CHECKER_EDGE_LENGTH),
        /** CorrespondenceCheckerBasedOnDistance(distance_threshold). */
        DISTANCE(O3dNativeConstants.O3D_CHECKER_DISTANCE),
        /** CorrespondenceCheckerBasedOnNormal(normal_angle_threshold, radians): both clouds need normals. */
        NORMAL(O3dNativeConstants.O3D_CHECKER_NORMAL);

        final int code;

        Kind(int code) {
            this.code = code;
        }
    }

    private final Kind kind;
    private final double threshold;

    public CorrespondenceChecker(Kind kind, double threshold) {
        this.kind = Objects.requireNonNull(kind, "kind");
        this.threshold = threshold;
    }

    public static CorrespondenceChecker edgeLength(double similarityThreshold) { return new CorrespondenceChecker(Kind.EDGE_LENGTH, similarityThreshold); }
    public static CorrespondenceChecker distance(double distanceThreshold) { return new CorrespondenceChecker(Kind.DISTANCE, distanceThreshold); }
    /** @param normalAngleThreshold radians */
    public static CorrespondenceChecker normal(double normalAngleThreshold) { return new CorrespondenceChecker(Kind.NORMAL, normalAngleThreshold); }
    public static CorrespondenceChecker edgeLength() { return withDefault(Kind.EDGE_LENGTH); }
    public static CorrespondenceChecker distance() { return withDefault(Kind.DISTANCE); }
    public static CorrespondenceChecker normal() { return withDefault(Kind.NORMAL); }

    public Kind kind() { return kind; }
    /** Similarity, distance or angle in radians, by kind. */
    public double threshold() { return threshold; }

    private static CorrespondenceChecker withDefault(Kind kind) {
        o3d_correspondence_checker_t c = newNative(kind);
        try {
            return new CorrespondenceChecker(kind, c.getThreshold());
        } finally {
            c.delete();
        }
    }

    private static o3d_correspondence_checker_t newNative(Kind kind) {
        o3d_correspondence_checker_t c = new o3d_correspondence_checker_t();
        try {
            O3dNative.o3d_correspondence_checker_init(c, O3dNative.o3dx_sizeof_correspondence_checker(), kind.code);
        } catch (RuntimeException e) {
            c.delete();
            throw e;
        }
        return c;
    }

    /** The native checker; the caller deletes it. */
    o3d_correspondence_checker_t toNative() {
        o3d_correspondence_checker_t c = newNative(kind);
        c.setThreshold(threshold);
        return c;
    }

    /**
     * Does the hypothesis pass (CorrespondenceChecker.Check)? {@code corres} holds flattened (source, target)
     * index pairs; {@code transformation} (null: identity) moves the source.
     */
    public boolean check(PointCloud source, PointCloud target, int[] corres, double[] transformation) {
        long n = Registration.pairs(corres, "corres");
        int[] passed = new int[1];
        o3d_correspondence_checker_t c = toNative();
        try {
            O3dNative.o3d_correspondence_checker_check(passed, c, source.handle(), target.handle(), corres, n,
                    NativeResource.fixed(transformation, 16, "transformation", true));
        } finally {
            c.delete();
        }
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        return passed[0] != 0;
    }

    @Override
    public String toString() {
        return "CorrespondenceChecker(" + kind + ", " + threshold + ")";
    }

    /** A native C array of checkers for one call (the `checkers, num_checkers` pair); close frees it. */
    static final class NativeArray implements AutoCloseable {
        /** The array (null when there are no checkers). */
        final o3d_correspondence_checker_t array;
        final long count;

        NativeArray(List<CorrespondenceChecker> checkers) {
            if (checkers == null || checkers.isEmpty()) {
                array = null;
                count = 0;
                return;
            }
            long n = checkers.size();
            o3d_correspondence_checker_t a = O3dNative.o3dx_checkers_new(n);
            if (a == null) throw new OutOfMemoryError("checkers");
            try {
                for (int i = 0; i < checkers.size(); i++) {
                    o3d_correspondence_checker_t c = Objects.requireNonNull(checkers.get(i), "checkers[" + i + "]").toNative();
                    try {
                        O3dNative.o3dx_checkers_set(a, n, i, c);
                    } finally {
                        c.delete();
                    }
                }
            } catch (RuntimeException e) {
                O3dNative.o3dx_checkers_delete(a);
                throw e;
            }
            array = a;
            count = n;
        }

        @Override
        public void close() {
            if (array != null) O3dNative.o3dx_checkers_delete(array);
        }
    }
}
