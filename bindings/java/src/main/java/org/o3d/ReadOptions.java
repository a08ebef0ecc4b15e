// SPDX-License-Identifier: MIT
package org.o3d;

/** Read options (o3d.io.read_point_cloud keyword arguments). */
public final class ReadOptions {
    public boolean removeNanPoints;
    public boolean removeInfinitePoints;

    o3d_read_options_t toNative() {
        o3d_read_options_t o = new o3d_read_options_t();
        O3dNative.o3d_read_options_init(o, O3dNative.o3dx_sizeof_read_options());
        o.setRemove_nan_points(removeNanPoints ? 1 : 0);
        o.setRemove_infinite_points(removeInfinitePoints ? 1 : 0);
        return o;
    }
}
