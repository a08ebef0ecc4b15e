// SPDX-License-Identifier: MIT
package org.o3d;

/** Progress of a long call; called on the calling thread. */
@FunctionalInterface
public interface ProgressCallback {
    /**
     * @param fraction progress in [0, 1]
     * @return true to go on, false to cancel (the call then throws O3dException with CANCELLED;
     *     a callback that throws also cancels)
     */
    boolean onProgress(double fraction);
}
