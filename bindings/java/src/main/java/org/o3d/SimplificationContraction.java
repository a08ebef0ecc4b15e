// SPDX-License-Identifier: MIT
package org.o3d;

/** Vertex-clustering contraction (Open3D's SimplificationContraction). */
public enum SimplificationContraction {
    AVERAGE(O3dNativeConstants.O3D_SIMPLIFICATION_AVERAGE),
    QUADRIC(O3dNativeConstants.O3D_SIMPLIFICATION_QUADRIC);

    private final int code;

    SimplificationContraction(int code) {
        this.code = code;
    }

    /** The C constant. */
    public int code() {
        return code;
    }
}
