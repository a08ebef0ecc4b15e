// SPDX-License-Identifier: MIT
package org.o3d;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Loads libo3d_java.so (the SWIG/JNI wrapper) and through it libo3d.so.0. First hit wins:
 * <ol>
 *   <li>system property {@code o3d.native.dir}, then environment variable {@code O3D_NATIVE_DIR}: a
 *       directory holding libo3d_java.so (a build tree, or a system install);</li>
 *   <li>the copy inside this jar, under {@code org/o3d/native/<os>-<arch>/} (as sqlite-jdbc does):
 *       libo3d_java.so, libo3d.so.0 and the libraries they need beyond the C and C++ runtime, each with
 *       RUNPATH $ORIGIN. They are unpacked into a fresh temporary directory, loaded, and deleted again
 *       (a loaded library stays mapped), so nothing is left behind. System property {@code o3d.tmpdir}
 *       overrides where (default {@code java.io.tmpdir});</li>
 *   <li>{@code System.loadLibrary("o3d_java")}, i.e. {@code java.library.path}.</li>
 * </ol>
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
        String bundled = "/org/o3d/native/" + platform() + "/";
        tried.append("jar resource ").append(bundled).append("; ");
        if (NativeLoader.class.getResource(bundled + "FILES") != null) {
            loadBundled(bundled);
            loaded = true;
            return;
        }
        try {
            System.loadLibrary("o3d_java");
            loaded = true;
        } catch (UnsatisfiedLinkError e) {
            tried.append("java.library.path (").append(e.getMessage()).append(")");
            throw new UnsatisfiedLinkError("o3d: cannot find " + file + "; tried " + tried
                    + ". This jar carries " + bundledPlatforms() + "; elsewhere set -Do3d.native.dir=<dir>.");
        }
    }

    /** "linux-x86_64" style: the name of the resource folder built for this machine. */
    static String platform() {
        String os = System.getProperty("os.name", "").toLowerCase(Locale.ROOT);
        String arch = System.getProperty("os.arch", "").toLowerCase(Locale.ROOT);
        if (os.startsWith("linux")) os = "linux";
        if (arch.equals("amd64") || arch.equals("x86-64")) arch = "x86_64";
        return os + "-" + arch;
    }

    private static String bundledPlatforms() {
        return NativeLoader.class.getResource("/org/o3d/native/linux-x86_64/FILES") != null
                ? "linux-x86_64 only" : "no native library";
    }

    private static void loadBundled(String folder) {
        List<String> names = new ArrayList<>();
        Path dir = null;
        try {
            try (InputStream index = NativeLoader.class.getResourceAsStream(folder + "FILES");
                 BufferedReader r = new BufferedReader(new InputStreamReader(index, StandardCharsets.UTF_8))) {
                for (String line; (line = r.readLine()) != null; ) if (!line.isBlank()) names.add(line.trim());
            }
            // o3d.tmpdir: for machines whose java.io.tmpdir is mounted noexec
            String tmp = System.getProperty("o3d.tmpdir", System.getProperty("java.io.tmpdir"));
            dir = Files.createTempDirectory(Paths.get(tmp), "o3d-native-");
            for (String name : names) {
                try (InputStream in = NativeLoader.class.getResourceAsStream(folder + name)) {
                    if (in == null) throw new IOException("the jar's index names " + name + ", which it lacks");
                    Files.copy(in, dir.resolve(name), StandardCopyOption.REPLACE_EXISTING);
                }
            }
            // The index lists the JNI wrapper first; its RUNPATH ($ORIGIN) finds the rest beside it.
            System.load(dir.resolve(names.get(0)).toAbsolutePath().toString());
        } catch (IOException e) {
            throw new UnsatisfiedLinkError("o3d: cannot unpack the native library from the jar: " + e.getMessage());
        } finally {
            if (dir != null) {
                for (String name : names) dir.resolve(name).toFile().delete();
                dir.toFile().delete();
            }
        }
    }
}
