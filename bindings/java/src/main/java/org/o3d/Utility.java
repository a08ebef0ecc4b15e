// SPDX-License-Identifier: MIT
package org.o3d;

/** o3d.utility. */
public final class Utility {
    private Utility() {}

    /** o3d.utility.random: the global generator of randomized calls not given a seed (RANSAC, FGR). */
    public static final class Random {
        private Random() {}

        /** Seed the global generator (an unsigned 64-bit value); without it, it starts from a random device. */
        public static void seed(long seed) {
            O3dNative.o3d_random_seed(seed);
        }
    }
}
