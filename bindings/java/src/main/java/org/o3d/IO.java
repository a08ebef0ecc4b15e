// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.util.Objects;

/**
 * Point-cloud I/O (o3d.io): "ply", "pcd", "xyz", "xyzn", "xyzrgb", "pts". A null/""/"auto" format
 * means: from the file extension. Failures throw O3dException (IO: missing file; PARSE: bad data).
 */
public final class IO {
    private IO() {}

    public static PointCloud readPointCloud(String path, String format, ReadOptions options) {
        Objects.requireNonNull(path, "path");
        long[] h = new long[1];
        o3d_read_options_t o = (options != null ? options : new ReadOptions()).toNative();
        try {
            O3dNative.o3d_io_read_point_cloud(h, path, format, o);
        } finally {
            o.delete();
        }
        return new PointCloud(h[0]);
    }

    public static PointCloud readPointCloud(String path) { return readPointCloud(path, null, null); }

    public static void writePointCloud(String path, PointCloud cloud, String format, WriteOptions options) {
        Objects.requireNonNull(path, "path");
        o3d_write_options_t o = (options != null ? options : new WriteOptions()).toNative();
        try {
            O3dNative.o3d_io_write_point_cloud(path, cloud.handle(), format, o);
        } finally {
            o.delete();
        }
        Reference.reachabilityFence(cloud);
    }

    public static void writePointCloud(String path, PointCloud cloud) { writePointCloud(path, cloud, null, null); }

    /** Decode a cloud from bytes; {@code format} is required. */
    public static PointCloud readPointCloudFromMemory(byte[] data, String format, ReadOptions options) {
        Objects.requireNonNull(data, "data");
        long[] h = new long[1];
        o3d_read_options_t o = (options != null ? options : new ReadOptions()).toNative();
        try {
            O3dNative.o3d_io_read_point_cloud_from_memory(h, data, data.length, format, o);
        } finally {
            o.delete();
        }
        return new PointCloud(h[0]);
    }

    public static PointCloud readPointCloudFromMemory(byte[] data, String format) {
        return readPointCloudFromMemory(data, format, null);
    }

    /** Encode a cloud into a native buffer (zero-copy view available); close it. */
    public static NativeBuffer writePointCloudToNativeBuffer(PointCloud cloud, String format, WriteOptions options) {
        long[] b = new long[1];
        o3d_write_options_t o = (options != null ? options : new WriteOptions()).toNative();
        try {
            O3dNative.o3d_io_write_point_cloud_to_memory(b, cloud.handle(), format, o);
        } finally {
            o.delete();
        }
        Reference.reachabilityFence(cloud);
        return new NativeBuffer(b[0]);
    }

    /** Encode a cloud into a byte array. */
    public static byte[] writePointCloudToMemory(PointCloud cloud, String format, WriteOptions options) {
        try (NativeBuffer b = writePointCloudToNativeBuffer(cloud, format, options)) {
            return b.toByteArray();
        }
    }

    public static byte[] writePointCloudToMemory(PointCloud cloud, String format) {
        return writePointCloudToMemory(cloud, format, null);
    }
}
