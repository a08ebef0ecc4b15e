// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.util.Objects;

/**
 * I/O (o3d.io): point clouds ("ply", "pcd", "xyz", "xyzn", "xyzrgb", "pts"), triangle meshes ("ply",
 * "obj", "stl", "off", "gltf", "glb"), images ("png", "jpg", "ppm", "pgm") and camera models (JSON,
 * trajectories also ".log"). A null/""/"auto" format means: from the file extension. Failures throw
 * O3dException (IO: missing file; PARSE: bad data; UNSUPPORTED: unknown format).
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

    // ---- triangle meshes -------------------------------------------------------------------------

    public static TriangleMesh readTriangleMesh(String path, String format, MeshReadOptions options) {
        Objects.requireNonNull(path, "path");
        long[] h = new long[1];
        o3d_mesh_read_options_t o = (options != null ? options : new MeshReadOptions()).toNative();
        try {
            O3dNative.o3d_io_read_triangle_mesh(h, path, format, o);
        } finally {
            o.delete();
        }
        return new TriangleMesh(h[0]);
    }

    public static TriangleMesh readTriangleMesh(String path) { return readTriangleMesh(path, null, null); }

    public static void writeTriangleMesh(String path, TriangleMesh mesh, String format, MeshWriteOptions options) {
        Objects.requireNonNull(path, "path");
        o3d_mesh_write_options_t o = (options != null ? options : new MeshWriteOptions()).toNative();
        try {
            O3dNative.o3d_io_write_triangle_mesh(path, mesh.handle(), format, o);
        } finally {
            o.delete();
        }
        Reference.reachabilityFence(mesh);
    }

    public static void writeTriangleMesh(String path, TriangleMesh mesh) { writeTriangleMesh(path, mesh, null, null); }

    /** Decode a mesh from bytes: "ply", "stl", "off", "obj" (no materials) or "glb". */
    public static TriangleMesh readTriangleMeshFromMemory(byte[] data, String format, MeshReadOptions options) {
        Objects.requireNonNull(data, "data");
        long[] h = new long[1];
        o3d_mesh_read_options_t o = (options != null ? options : new MeshReadOptions()).toNative();
        try {
            O3dNative.o3d_io_read_triangle_mesh_from_memory(h, data, data.length, format, o);
        } finally {
            o.delete();
        }
        return new TriangleMesh(h[0]);
    }

    public static TriangleMesh readTriangleMeshFromMemory(byte[] data, String format) {
        return readTriangleMeshFromMemory(data, format, null);
    }

    public static NativeBuffer writeTriangleMeshToNativeBuffer(TriangleMesh mesh, String format, MeshWriteOptions options) {
        long[] b = new long[1];
        o3d_mesh_write_options_t o = (options != null ? options : new MeshWriteOptions()).toNative();
        try {
            O3dNative.o3d_io_write_triangle_mesh_to_memory(b, mesh.handle(), format, o);
        } finally {
            o.delete();
        }
        Reference.reachabilityFence(mesh);
        return new NativeBuffer(b[0]);
    }

    public static byte[] writeTriangleMeshToMemory(TriangleMesh mesh, String format, MeshWriteOptions options) {
        try (NativeBuffer b = writeTriangleMeshToNativeBuffer(mesh, format, options)) {
            return b.toByteArray();
        }
    }

    public static byte[] writeTriangleMeshToMemory(TriangleMesh mesh, String format) {
        return writeTriangleMeshToMemory(mesh, format, null);
    }

    // ---- images --------------------------------------------------------------------------------------

    public static Image readImage(String path, String format) {
        Objects.requireNonNull(path, "path");
        long[] h = new long[1];
        O3dNative.o3d_io_read_image(h, path, format);
        return new Image(h[0]);
    }

    public static Image readImage(String path) { return readImage(path, null); }

    /** Write an image; {@code quality} is JPEG quality 1..100, or -1 for the default (90). */
    public static void writeImage(String path, Image image, String format, int quality) {
        Objects.requireNonNull(path, "path");
        O3dNative.o3d_io_write_image(path, image.handle(), format, quality);
        Reference.reachabilityFence(image);
    }

    public static void writeImage(String path, Image image) { writeImage(path, image, null, -1); }

    public static Image readImageFromMemory(byte[] data, String format) {
        Objects.requireNonNull(data, "data");
        long[] h = new long[1];
        O3dNative.o3d_io_read_image_from_memory(h, data, data.length, format);
        return new Image(h[0]);
    }

    public static NativeBuffer writeImageToNativeBuffer(Image image, String format, int quality) {
        long[] b = new long[1];
        O3dNative.o3d_io_write_image_to_memory(b, image.handle(), format, quality);
        Reference.reachabilityFence(image);
        return new NativeBuffer(b[0]);
    }

    public static byte[] writeImageToMemory(Image image, String format, int quality) {
        try (NativeBuffer b = writeImageToNativeBuffer(image, format, quality)) {
            return b.toByteArray();
        }
    }

    public static byte[] writeImageToMemory(Image image, String format) { return writeImageToMemory(image, format, -1); }

    // ---- camera models ---------------------------------------------------------------------------

    public static PinholeCameraIntrinsic readPinholeCameraIntrinsic(String path) {
        Objects.requireNonNull(path, "path");
        o3d_pinhole_intrinsic_t n = new o3d_pinhole_intrinsic_t();
        try {
            O3dNative.o3d_io_read_pinhole_camera_intrinsic(n, path);
            return PinholeCameraIntrinsic.fromNative(n);
        } finally {
            n.delete();
        }
    }

    public static void writePinholeCameraIntrinsic(String path, PinholeCameraIntrinsic intrinsic) {
        Objects.requireNonNull(path, "path");
        o3d_pinhole_intrinsic_t n = intrinsic.toNative();
        try {
            O3dNative.o3d_io_write_pinhole_camera_intrinsic(path, n);
        } finally {
            n.delete();
        }
    }

    public static PinholeCameraParameters readPinholeCameraParameters(String path) {
        Objects.requireNonNull(path, "path");
        double[] extrinsic = new double[16];
        o3d_pinhole_intrinsic_t n = new o3d_pinhole_intrinsic_t();
        try {
            O3dNative.o3d_io_read_pinhole_camera_parameters(n, extrinsic, path);
            return new PinholeCameraParameters(PinholeCameraIntrinsic.fromNative(n), extrinsic);
        } finally {
            n.delete();
        }
    }

    public static void writePinholeCameraParameters(String path, PinholeCameraParameters parameters) {
        Objects.requireNonNull(path, "path");
        o3d_pinhole_intrinsic_t n = parameters.intrinsic().toNative();
        try {
            O3dNative.o3d_io_write_pinhole_camera_parameters(path, n, parameters.extrinsic());
        } finally {
            n.delete();
        }
    }

    /** Read a trajectory: "json" or "log" (null/"auto": from the extension). */
    public static PinholeCameraTrajectory readPinholeCameraTrajectory(String path, String format) {
        Objects.requireNonNull(path, "path");
        long[] h = new long[1];
        O3dNative.o3d_io_read_pinhole_camera_trajectory(h, path, format);
        return new PinholeCameraTrajectory(h[0]);
    }

    public static PinholeCameraTrajectory readPinholeCameraTrajectory(String path) {
        return readPinholeCameraTrajectory(path, null);
    }

    public static void writePinholeCameraTrajectory(String path, PinholeCameraTrajectory trajectory, String format) {
        Objects.requireNonNull(path, "path");
        O3dNative.o3d_io_write_pinhole_camera_trajectory(path, trajectory.handle(), format);
        Reference.reachabilityFence(trajectory);
    }

    public static void writePinholeCameraTrajectory(String path, PinholeCameraTrajectory trajectory) {
        writePinholeCameraTrajectory(path, trajectory, null);
    }

    // ---- features and pose graphs ---------------------------------------------------------------

    /** Read Open3D's binary feature file (int32 dimension, int32 num, num x dimension float64); bad files throw PARSE. */
    public static Feature readFeature(String path) {
        Objects.requireNonNull(path, "path");
        long[] h = new long[1];
        O3dNative.o3d_io_read_feature(h, path);
        return new Feature(h[0]);
    }

    /** Write {@code feature} in the layout readFeature reads. */
    public static void writeFeature(String path, Feature feature) {
        Objects.requireNonNull(path, "path");
        O3dNative.o3d_io_write_feature(path, feature.handle());
        Reference.reachabilityFence(feature);
    }

    /** Read Open3D's JSON pose graph. */
    public static PoseGraph readPoseGraph(String path) {
        Objects.requireNonNull(path, "path");
        long[] h = new long[1];
        O3dNative.o3d_io_read_pose_graph(h, path);
        return new PoseGraph(h[0]);
    }

    /** Write {@code graph} in Open3D's JSON layout. */
    public static void writePoseGraph(String path, PoseGraph graph) {
        Objects.requireNonNull(path, "path");
        O3dNative.o3d_io_write_pose_graph(path, graph.handle());
        Reference.reachabilityFence(graph);
    }
}
