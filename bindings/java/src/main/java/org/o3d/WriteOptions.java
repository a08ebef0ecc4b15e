// SPDX-License-Identifier: MIT
package org.o3d;

/** Write options (o3d.io.write_point_cloud keyword arguments). */
public final class WriteOptions {
    /** PLY/PCD: text instead of binary. */
    public boolean writeAscii;
    /** PCD: binary_compressed (LZF). */
    public boolean compressed;

    public WriteOptions() {}

    public WriteOptions(boolean writeAscii, boolean compressed) {
        this.writeAscii = writeAscii;
        this.compressed = compressed;
    }

    o3d_write_options_t toNative() {
        o3d_write_options_t o = new o3d_write_options_t();
        O3dNative.o3d_write_options_init(o, O3dNative.o3dx_sizeof_write_options());
        o.setWrite_ascii(writeAscii ? 1 : 0);
        o.setCompressed(compressed ? 1 : 0);
        return o;
    }
}
