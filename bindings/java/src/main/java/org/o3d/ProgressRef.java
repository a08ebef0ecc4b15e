// SPDX-License-Identifier: MIT
package org.o3d;

/**
 * A {@link ProgressCallback} handed to native code for one call: the C trampoline's address and a JNI
 * global reference to the callback as its user_data (both 0 without a callback). Close it after the call.
 */
final class ProgressRef implements AutoCloseable {
    final long function;
    final long userData;

    ProgressRef(ProgressCallback callback) {
        if (callback == null) {
            function = 0;
            userData = 0;
        } else {
            userData = O3dNative.o3dj_new_global_ref(callback);
            function = O3dNative.o3dj_progress_trampoline_address();
        }
    }

    @Override
    public void close() {
        O3dNative.o3dj_delete_global_ref(userData);
    }
}
