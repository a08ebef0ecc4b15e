// SPDX-License-Identifier: MIT
package org.o3d;

/** Mesh read options (o3d.io.read_triangle_mesh keyword arguments). */
public final class MeshReadOptions {
    /** Merge duplicated vertices and drop degenerate triangles. */
    public boolean enablePostProcessing;

    public MeshReadOptions() {}

    public MeshReadOptions(boolean enablePostProcessing) {
        this.enablePostProcessing = enablePostProcessing;
    }

    o3d_mesh_read_options_t toNative() {
        o3d_mesh_read_options_t o = new o3d_mesh_read_options_t();
        O3dNative.o3d_mesh_read_options_init(o, O3dNative.o3dx_sizeof_mesh_read_options());
        o.setEnable_post_processing(enablePostProcessing ? 1 : 0);
        return o;
    }
}
