// SPDX-License-Identifier: MIT
package org.o3d;

import java.util.function.BiConsumer;

/** Library-wide functions: version, errors, logging, threads. */
public final class Library {
    private Library() {}

    public static String version() { return O3dNative.o3d_version(); }
    public static int versionMajor() { return O3dNative.o3d_version_major(); }
    public static int versionMinor() { return O3dNative.o3d_version_minor(); }
    public static int versionPatch() { return O3dNative.o3d_version_patch(); }

    /** Message of the last failure on this thread ("" when none). */
    public static String lastErrorMessage() { return O3dNative.o3d_last_error_message(); }
    /** Status of the last failure on this thread (OK when none). */
    public static Status lastErrorCode() { return Status.fromCode(O3dNative.o3d_last_error_code()); }
    public static void clearError() { O3dNative.o3d_clear_error(); }
    public static String statusString(Status status) { return O3dNative.o3d_status_string(status.code()); }

    /** Show messages at {@code level} (0 error .. 3 debug) and more severe. */
    public static void setVerbosityLevel(int level) { O3dNative.o3d_set_verbosity_level(level); }
    public static int getVerbosityLevel() { return O3dNative.o3d_get_verbosity_level(); }

    /** Default thread count of parallel calls (0 restores the OpenMP default). */
    public static void setNumThreads(int numThreads) { O3dNative.o3d_set_num_threads(numThreads); }
    public static int getNumThreads() { return O3dNative.o3d_get_num_threads(); }

    /**
     * Route the library's log lines to {@code handler(level, message)}, called on the logging thread
     * (exceptions it throws are discarded); {@code null} restores the default sink (stderr).
     */
    public static synchronized void setLogHandler(BiConsumer<Integer, String> handler) {
        if (handler == null) {
            O3dNative.o3d_set_log_callback(0, 0);
            Log.handler = null;
            return;
        }
        Log.handler = handler;
        long trampoline = O3dNative.o3dj_log_trampoline_address();
        if (trampoline == 0) throw new IllegalStateException("o3d: log trampoline unavailable");
        O3dNative.o3d_set_log_callback(trampoline, 0);
    }
}
