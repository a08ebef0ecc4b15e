// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * Native search result (o3d_search_result_t). {@link #toArrays()} copies it out; {@link #offsetsView()},
 * {@link #indicesView()}, {@link #distances2View()} are zero-copy direct buffers valid until close().
 */
public final class SearchResult extends NativeResource {
    SearchResult(long handle) {
        super(handle, O3dNative::o3d_search_result_destroy);
    }

    /** {numQueries, totalNeighbours}. */
    public long[] counts() {
        long[] q = new long[1];
        long[] t = new long[1];
        O3dNative.o3d_search_result_counts(q, t, handle());
        Reference.reachabilityFence(this);
        return new long[] {q[0], t[0]};
    }

    private ByteBuffer view(int which, long elements, int elementBytes) {
        long[] o = new long[1];
        long[] i = new long[1];
        long[] d = new long[1];
        O3dNative.o3d_search_result_view(o, i, d, handle());
        Reference.reachabilityFence(this);
        long address = which == 0 ? o[0] : which == 1 ? i[0] : d[0];
        ByteBuffer b = O3dNative.o3dj_direct_buffer(address, elements * elementBytes);
        if (b == null) b = ByteBuffer.allocateDirect(0);
        return b.asReadOnlyBuffer().order(ByteOrder.nativeOrder());
    }

    /** numQueries + 1 int64 offsets (use asLongBuffer()). */
    public ByteBuffer offsetsView() { return view(0, counts()[0] + 1, Long.BYTES); }
    /** total int32 indices (use asIntBuffer()). */
    public ByteBuffer indicesView() { return view(1, counts()[1], Integer.BYTES); }
    /** total squared distances (use asDoubleBuffer()). */
    public ByteBuffer distances2View() { return view(2, counts()[1], Double.BYTES); }

    public NeighborResult toArrays() {
        long[] c = counts();
        long h = handle();
        long[] offsets = new long[(int) c[0] + 1];
        int[] indices = new int[(int) c[1]];
        double[] d2 = new double[(int) c[1]];
        O3dNative.o3d_search_result_get_offsets(offsets, offsets.length, h);
        O3dNative.o3d_search_result_get_indices(indices, indices.length, h);
        O3dNative.o3d_search_result_get_distances2(d2, d2.length, h);
        Reference.reachabilityFence(this);
        return new NeighborResult(offsets, indices, d2);
    }
}
