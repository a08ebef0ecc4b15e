// SPDX-License-Identifier: MIT
package org.o3d;

import java.io.File;

/**
 * Loads libo3d_java.so (the SWIG/JNI wrapper; it finds libo3d.so.0 through its RUNPATH or
 * LD_LIBRARY_PATH). Search order, first hit wins:
 * <ol>
 *   <li>system property {@code o3d.native.dir} (a directory holding libo3d_java.so);</li>
 *   <li>environment variable {@code O3D_NATIVE_DIR};</li>
 *   <li>{@code System.loadLibrary("o3d_java")}, i.e. {@code java.library.path};</li>
 *   <li>the CMake build directory baked into the jar at build time ({@code BuildConfig.NATIVE_DIR}).</li>
 * </ol>
 * The library is not extracted from the jar: it depends on libo3d.so.0, which a deployment installs
 * anyway, so the jar locates an installed or built copy instead.
 */
final class NativeLoader {
    private static boolean loaded;

    private NativeLoader() {}

    static synchronized void load() {
        if (loaded) return;
        String file = System.mapLibraryName("o3d_java");
        StringBuilder tried = new StringBuilder();
        for (String dir : new String[] {System.getProperty("o3d.native.dir"), System.getenv("O3D_NATIVE_DIR")}) {
            if (dir == null || dir.isEmpty()) continue;
            File f = new File(dir, file);
            tried.append(f).append("; ");
            if (f.isFile()) {
                System.load(f.getAbsolutePath());
                loaded = true;
                return;
            }
        }
        try {
            System.loadLibrary("o3d_java");
            loaded = true;
            return;
        } catch (UnsatisfiedLinkError e) {
            tried.append("java.library.path (").append(e.getMessage()).append("); ");
        }
        File f = new File(BuildConfig.NATIVE_DIR, file);
        tried.append(f);
        if (f.isFile()) {
            System.load(f.getAbsolutePath());
            loaded = true;
            return;
        }
        throw new UnsatisfiedLinkError("o3d: cannot find " + file + "; tried " + tried
                + ". Set -Do3d.native.dir=<dir> or O3D_NATIVE_DIR.");
    }
}
