// SPDX-License-Identifier: MIT
package org.o3d;

/** The int32 arrays of a mesh (for the borrowed views). */
public enum MeshIndexArray {
    TRIANGLES(O3dNativeConstants.O3D_MESH_TRIANGLES),
    TRIANGLE_MATERIAL_IDS(O3dNativeConstants.O3D_MESH_TRIANGLE_MATERIAL_IDS);

    private final int code;

    MeshIndexArray(int code) {
        this.code = code;
    }

    /** The C constant. */
    public int code() {
        return code;
    }
}
