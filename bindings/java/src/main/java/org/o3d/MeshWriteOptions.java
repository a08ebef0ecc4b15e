// SPDX-License-Identifier: MIT
package org.o3d;

/** Mesh write options (o3d.io.write_triangle_mesh keyword arguments; Open3D's defaults). */
public final class MeshWriteOptions {
    /** PLY/STL: text instead of binary. */
    public boolean writeAscii;
    /** Accepted for Open3D compatibility; no mesh format here compresses. */
    public boolean compressed;
    public boolean writeVertexNormals = true;
    public boolean writeVertexColors = true;
    public boolean writeTriangleUvs = true;

    o3d_mesh_write_options_t toNative() {
        o3d_mesh_write_options_t o = new o3d_mesh_write_options_t();
        O3dNative.o3d_mesh_write_options_init(o, O3dNative.o3dx_sizeof_mesh_write_options());
        o.setWrite_ascii(writeAscii ? 1 : 0);
        o.setCompressed(compressed ? 1 : 0);
        o.setWrite_vertex_normals(writeVertexNormals ? 1 : 0);
        o.setWrite_vertex_colors(writeVertexColors ? 1 : 0);
        o.setWrite_triangle_uvs(writeTriangleUvs ? 1 : 0);
        return o;
    }
}
