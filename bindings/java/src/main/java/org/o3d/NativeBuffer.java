// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.nio.ByteBuffer;

/** An owned native byte buffer (o3d_buffer_t), e.g. an encoded cloud. */
public final class NativeBuffer extends NativeResource {
    NativeBuffer(long handle) {
        super(handle, O3dNative::o3d_buffer_destroy);
    }

    /** Zero-copy read-only view of the bytes; valid until close(). */
    public ByteBuffer view() {
        long[] data = new long[1];
        long[] size = new long[1];
        O3dNative.o3d_buffer_view(data, size, handle());
        Reference.reachabilityFence(this);
        ByteBuffer b = O3dNative.o3dj_direct_buffer(data[0], size[0]);
        return b == null ? ByteBuffer.allocateDirect(0) : b.asReadOnlyBuffer();
    }

    /** A copy of the bytes. */
    public byte[] toByteArray() {
        long h = handle();
        long[] size = new long[1];
        O3dNative.o3d_buffer_get_data(null, 0, size, h);
        if (size[0] > Integer.MAX_VALUE - 8) throw new IllegalStateException("buffer too large for a Java array");
        byte[] out = new byte[(int) size[0]];
        O3dNative.o3d_buffer_get_data(out, out.length, size, h);
        Reference.reachabilityFence(this);
        return out;
    }
}
