// SPDX-License-Identifier: MIT
package org.o3d;

/** The float64 arrays of a mesh (for the borrowed views). */
public enum MeshArray {
    VERTICES(O3dNativeConstants.O3D_MESH_VERTICES),
    VERTEX_NORMALS(O3dNativeConstants.O3D_MESH_VERTEX_NORMALS),
    VERTEX_COLORS(O3dNativeConstants.O3D_MESH_VERTEX_COLORS),
    TRIANGLE_NORMALS(O3dNativeConstants.O3D_MESH_TRIANGLE_NORMALS),
    TRIANGLE_UVS(O3dNativeConstants.O3D_MESH_TRIANGLE_UVS);

    private final int code;

    MeshArray(int code) {
        this.code = code;
    }

    /** The C constant. */
    public int code() {
        return code;
    }
}
