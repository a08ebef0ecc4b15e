// SPDX-License-Identifier: MIT
package org.o3d;

/** The occupied voxels of a {@link VoxelGrid}, sorted by grid index (x, then y, then z). */
public final class Voxels {
    /** Grid index (i, j, k) of each voxel, 3 ints per voxel. */
    public final int[] gridIndices;
    /** Mean RGB color of each voxel, 3 doubles per voxel. */
    public final double[] colors;

    Voxels(int[] gridIndices, double[] colors) {
        this.gridIndices = gridIndices;
        this.colors = colors;
    }

    public int count() {
        return gridIndices.length / 3;
    }
}
