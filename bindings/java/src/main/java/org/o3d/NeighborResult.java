// SPDX-License-Identifier: MIT
package org.o3d;

import java.util.Arrays;

/**
 * Flat batch search result in Java arrays: neighbours of query i are
 * {@code indices[offsets[i] .. offsets[i+1]-1]}, sorted by increasing distance, with squared distances.
 */
public final class NeighborResult {
    public final long[] offsets;
    public final int[] indices;
    public final double[] distances2;

    NeighborResult(long[] offsets, int[] indices, double[] distances2) {
        this.offsets = offsets;
        this.indices = indices;
        this.distances2 = distances2;
    }

    public int numQueries() {
        return offsets.length - 1;
    }

    /** Neighbour indices of one query. */
    public int[] indicesOf(int query) {
        return Arrays.copyOfRange(indices, (int) offsets[query], (int) offsets[query + 1]);
    }
}
