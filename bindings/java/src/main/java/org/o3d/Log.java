// SPDX-License-Identifier: MIT
package org.o3d;

import java.util.function.BiConsumer;

/** Target of the native log trampoline (o3d_java.i looks up org/o3d/Log.dispatch(int, String)). */
final class Log {
    static volatile BiConsumer<Integer, String> handler;

    private Log() {}

    static void dispatch(int level, String message) {
        BiConsumer<Integer, String> h = handler;
        if (h != null) h.accept(level, message);
    }
}
