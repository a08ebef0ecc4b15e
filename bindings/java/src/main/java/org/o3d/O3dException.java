// SPDX-License-Identifier: MIT
package org.o3d;

/** A failed o3d call: the C status (Library.ERROR_*) and o3d_last_error_message() of that call. */
public class O3dException extends RuntimeException {
    private static final long serialVersionUID = 1L;
    private final int status;

    /** Called from the JNI wrapper (bindings/java/o3d_java.i) for every non-OK status. */
    public O3dException(int status, String message) {
        super(message);
        this.status = status;
    }

    /** The o3d_status (negative), one of Library.ERROR_*. */
    public int getStatus() {
        return status;
    }
}
