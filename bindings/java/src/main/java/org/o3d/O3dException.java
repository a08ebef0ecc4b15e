// SPDX-License-Identifier: MIT
package org.o3d;

/** A failed o3d call: the C status and o3d_last_error_message() of that call. */
public class O3dException extends RuntimeException {
    private static final long serialVersionUID = 1L;
    private final int code;

    /** Called from the JNI wrapper (bindings/java/o3d_java.i) for every non-OK status. */
    public O3dException(int code, String message) {
        super(O3dNative.o3d_status_string(code) + ": " + message);
        this.code = code;
    }

    /** The raw o3d_status (negative). */
    public int getCode() {
        return code;
    }

    public Status getStatus() {
        return Status.fromCode(code);
    }
}
