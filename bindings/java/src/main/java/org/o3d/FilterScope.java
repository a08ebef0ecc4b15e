// SPDX-License-Identifier: MIT
package org.o3d;

/** What the mesh smoothing filters change (Open3D's FilterScope). */
public enum FilterScope {
    ALL(O3dNativeConstants.O3D_FILTER_SCOPE_ALL),
    COLOR(O3dNativeConstants.O3D_FILTER_SCOPE_COLOR),
    NORMAL(O3dNativeConstants.O3D_FILTER_SCOPE_NORMAL),
    VERTEX(O3dNativeConstants.O3D_FILTER_SCOPE_VERTEX);

    private final int code;

    FilterScope(int code) {
        this.code = code;
    }

    /** The C constant. */
    public int code() {
        return code;
    }
}
