// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Cleaner;
import java.util.function.LongConsumer;

/**
 * An owned native o3d object. {@link #close()} destroys it (idempotent); a {@link Cleaner} destroys
 * objects that were never closed once they become unreachable (a safety net, not a substitute).
 */
public abstract class NativeResource implements AutoCloseable {
    static final Cleaner CLEANER = Cleaner.create();

    /** Holds the handle; must not reference the owning object (Cleaner rule). */
    private static final class State implements Runnable {
        private long handle;
        private final LongConsumer destroy;

        State(long handle, LongConsumer destroy) {
            this.handle = handle;
            this.destroy = destroy;
        }

        @Override
        public synchronized void run() {
            long h = handle;
            handle = 0;
            if (h != 0) destroy.accept(h);
        }

        synchronized long get() {
            return handle;
        }
    }

    private final State state;
    private final Cleaner.Cleanable cleanable;

    NativeResource(long handle, LongConsumer destroy) {
        if (handle == 0) throw new O3dException(Status.INTERNAL.code(), "null handle");
        this.state = new State(handle, destroy);
        this.cleanable = CLEANER.register(this, state);
    }

    /** The raw o3d handle (an address). Throws IllegalStateException once closed. */
    public long handle() {
        long h = state.get();
        if (h == 0) throw new IllegalStateException(getClass().getSimpleName() + " is closed");
        return h;
    }

    public boolean isClosed() {
        return state.get() == 0;
    }

    /** Destroys the native object. Idempotent. */
    @Override
    public void close() {
        cleanable.clean();
    }

    static long rows3(int length, String name) {
        if (length % 3 != 0)
            throw new IllegalArgumentException(name + ": length " + length + " is not a multiple of 3");
        return length / 3;
    }

    /** A read-only direct ByteBuffer (native order) over a borrowed o3d view; empty for address 0. */
    static java.nio.ByteBuffer readOnlyView(long address, long bytes) {
        java.nio.ByteBuffer b = O3dNative.o3dj_direct_buffer(address, bytes);
        if (b == null) b = java.nio.ByteBuffer.allocateDirect(0);
        return b.asReadOnlyBuffer().order(java.nio.ByteOrder.nativeOrder());
    }

    /** {@code values} cut to the {@code n} items a copy-out call reported. */
    static int[] trimTo(int[] values, long n) {
        return n >= values.length ? values : java.util.Arrays.copyOf(values, (int) n);
    }

    static double[] fixed(double[] values, int length, String name, boolean nullable) {
        if (values == null) {
            if (nullable) return null;
            throw new NullPointerException(name);
        }
        if (values.length != length)
            throw new IllegalArgumentException(name + ": expected " + length + " values, got " + values.length);
        return values;
    }
}
