// SPDX-License-Identifier: MIT
package org.o3d;

/** Status codes of the C API (o3d_status). */
public enum Status {
    OK(O3dNativeConstants.O3D_OK),
    INVALID_ARGUMENT(O3dNativeConstants.O3D_ERROR_INVALID_ARGUMENT),
    OUT_OF_MEMORY(O3dNativeConstants.O3D_ERROR_OUT_OF_MEMORY),
    IO(O3dNativeConstants.O3D_ERROR_IO),
    PARSE(O3dNativeConstants.O3D_ERROR_PARSE),
    UNSUPPORTED(O3dNativeConstants.O3D_ERROR_UNSUPPORTED),
    BUFFER_TOO_SMALL(O3dNativeConstants.O3D_ERROR_BUFFER_TOO_SMALL),
    NOT_CONVERGED(O3dNativeConstants.O3D_ERROR_NOT_CONVERGED),
    CANCELLED(O3dNativeConstants.O3D_ERROR_CANCELLED),
    INTERNAL(O3dNativeConstants.O3D_ERROR_INTERNAL);

    private final int code;

    Status(int code) {
        this.code = code;
    }

    public int code() {
        return code;
    }

    public static Status fromCode(int code) {
        for (Status s : values()) {
            if (s.code == code) return s;
        }
        return INTERNAL;
    }

    /** The C name ("O3D_ERROR_IO", ...). */
    public String cName() {
        return O3dNative.o3d_status_string(code);
    }
}
