// SPDX-License-Identifier: MIT
// Mesh, image and camera I/O (o3d.io.read_triangle_mesh, read_image, read_pinhole_camera_*, ...).
using System;

namespace O3d
{
    /// <summary>Mesh read options (o3d.io.read_triangle_mesh keyword arguments).</summary>
    public sealed class MeshReadOptions
    {
        /// <summary>Merge duplicated vertices and drop degenerate triangles.</summary>
        public bool EnablePostProcessing { get; set; }

        internal o3d_mesh_read_options_t ToNative()
        {
            var o = new o3d_mesh_read_options_t();
            O3dNative.o3d_mesh_read_options_init(o, O3dNative.o3dx_sizeof_mesh_read_options());
            o.enable_post_processing = EnablePostProcessing ? 1 : 0;
            return o;
        }
    }

    /// <summary>Mesh write options (o3d.io.write_triangle_mesh keyword arguments; Open3D's defaults).</summary>
    public sealed class MeshWriteOptions
    {
        public MeshWriteOptions() { WriteVertexNormals = true; WriteVertexColors = true; WriteTriangleUvs = true; }

        /// <summary>PLY/STL: text instead of binary.</summary>
        public bool WriteAscii { get; set; }
        /// <summary>Accepted for Open3D compatibility; no mesh format here compresses.</summary>
        public bool Compressed { get; set; }
        public bool WriteVertexNormals { get; set; }
        public bool WriteVertexColors { get; set; }
        public bool WriteTriangleUvs { get; set; }

        internal o3d_mesh_write_options_t ToNative()
        {
            var o = new o3d_mesh_write_options_t();
            O3dNative.o3d_mesh_write_options_init(o, O3dNative.o3dx_sizeof_mesh_write_options());
            o.write_ascii = WriteAscii ? 1 : 0;
            o.compressed = Compressed ? 1 : 0;
            o.write_vertex_normals = WriteVertexNormals ? 1 : 0;
            o.write_vertex_colors = WriteVertexColors ? 1 : 0;
            o.write_triangle_uvs = WriteTriangleUvs ? 1 : 0;
            return o;
        }
    }

    public static partial class IO
    {
        // ---- triangle meshes: "ply", "obj", "stl", "off", "gltf", "glb" ----

        public static TriangleMesh ReadTriangleMesh(string path, string format = null, MeshReadOptions options = null)
        {
            if (path == null) throw new ArgumentNullException("path");
            IntPtr h;
            using (var o = (options ?? new MeshReadOptions()).ToNative())
                O3dNative.o3d_io_read_triangle_mesh(out h, path, format, o);
            return new TriangleMesh(h);
        }

        public static void WriteTriangleMesh(string path, TriangleMesh mesh, string format = null, MeshWriteOptions options = null)
        {
            if (path == null) throw new ArgumentNullException("path");
            if (mesh == null) throw new ArgumentNullException("mesh");
            using (var o = (options ?? new MeshWriteOptions()).ToNative())
                O3dNative.o3d_io_write_triangle_mesh(path, mesh.Handle, format, o);
            GC.KeepAlive(mesh);
        }

        /// <summary>Decode a mesh from bytes: "ply", "stl", "off", "obj" (no materials) or "glb".</summary>
        public static TriangleMesh ReadTriangleMeshFromMemory(byte[] data, string format, MeshReadOptions options = null)
        {
            if (data == null) throw new ArgumentNullException("data");
            IntPtr h;
            using (var o = (options ?? new MeshReadOptions()).ToNative())
                O3dNative.o3d_io_read_triangle_mesh_from_memory(out h, data, (ulong)data.Length, format, o);
            return new TriangleMesh(h);
        }

        public static NativeBuffer WriteTriangleMeshToNativeBuffer(TriangleMesh mesh, string format, MeshWriteOptions options = null)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
            IntPtr b;
            using (var o = (options ?? new MeshWriteOptions()).ToNative())
                O3dNative.o3d_io_write_triangle_mesh_to_memory(out b, mesh.Handle, format, o);
            GC.KeepAlive(mesh);
            return new NativeBuffer(b);
        }

        public static byte[] WriteTriangleMeshToMemory(TriangleMesh mesh, string format, MeshWriteOptions options = null)
        {
            using (var b = WriteTriangleMeshToNativeBuffer(mesh, format, options)) return b.ToArray();
        }

        // ---- images: "png", "jpg"/"jpeg", "ppm", "pgm" ----

        public static Image ReadImage(string path, string format = null)
        {
            if (path == null) throw new ArgumentNullException("path");
            IntPtr h;
            O3dNative.o3d_io_read_image(out h, path, format);
            return new Image(h);
        }

        /// <summary>Write an image; <paramref name="quality"/> is JPEG quality 1..100 (-1: 90).</summary>
        public static void WriteImage(string path, Image image, string format = null, int quality = -1)
        {
            if (path == null) throw new ArgumentNullException("path");
            if (image == null) throw new ArgumentNullException("image");
            O3dNative.o3d_io_write_image(path, image.Handle, format, quality);
            GC.KeepAlive(image);
        }

        public static Image ReadImageFromMemory(byte[] data, string format)
        {
            if (data == null) throw new ArgumentNullException("data");
            IntPtr h;
            O3dNative.o3d_io_read_image_from_memory(out h, data, (ulong)data.Length, format);
            return new Image(h);
        }

        public static NativeBuffer WriteImageToNativeBuffer(Image image, string format, int quality = -1)
        {
            if (image == null) throw new ArgumentNullException("image");
            IntPtr b;
            O3dNative.o3d_io_write_image_to_memory(out b, image.Handle, format, quality);
            GC.KeepAlive(image);
            return new NativeBuffer(b);
        }

        public static byte[] WriteImageToMemory(Image image, string format, int quality = -1)
        {
            using (var b = WriteImageToNativeBuffer(image, format, quality)) return b.ToArray();
        }

        // ---- camera models (Open3D's JSON layouts; trajectories also .log) ----

        public static PinholeCameraIntrinsic ReadPinholeCameraIntrinsic(string path)
        {
            if (path == null) throw new ArgumentNullException("path");
            using (var n = new o3d_pinhole_intrinsic_t())
            {
                O3dNative.o3d_io_read_pinhole_camera_intrinsic(n, path);
                return PinholeCameraIntrinsic.FromNative(n);
            }
        }

        public static void WritePinholeCameraIntrinsic(string path, PinholeCameraIntrinsic intrinsic)
        {
            if (path == null) throw new ArgumentNullException("path");
            if (intrinsic == null) throw new ArgumentNullException("intrinsic");
            using (var n = intrinsic.ToNative()) O3dNative.o3d_io_write_pinhole_camera_intrinsic(path, n);
        }

        public static PinholeCameraParameters ReadPinholeCameraParameters(string path)
        {
            if (path == null) throw new ArgumentNullException("path");
            var extrinsic = new double[16];
            using (var n = new o3d_pinhole_intrinsic_t())
            {
                O3dNative.o3d_io_read_pinhole_camera_parameters(n, extrinsic, path);
                return new PinholeCameraParameters(PinholeCameraIntrinsic.FromNative(n), extrinsic);
            }
        }

        public static void WritePinholeCameraParameters(string path, PinholeCameraParameters parameters)
        {
            if (path == null) throw new ArgumentNullException("path");
            if (parameters == null) throw new ArgumentNullException("parameters");
            using (var n = parameters.Intrinsic.ToNative())
                O3dNative.o3d_io_write_pinhole_camera_parameters(path, n, parameters.Extrinsic);
        }

        /// <summary>Read a trajectory: "json" or "log" (null/"auto": from the extension).</summary>
        public static PinholeCameraTrajectory ReadPinholeCameraTrajectory(string path, string format = null)
        {
            if (path == null) throw new ArgumentNullException("path");
            IntPtr h;
            O3dNative.o3d_io_read_pinhole_camera_trajectory(out h, path, format);
            return new PinholeCameraTrajectory(h);
        }

        public static void WritePinholeCameraTrajectory(string path, PinholeCameraTrajectory trajectory, string format = null)
        {
            if (path == null) throw new ArgumentNullException("path");
            if (trajectory == null) throw new ArgumentNullException("trajectory");
            O3dNative.o3d_io_write_pinhole_camera_trajectory(path, trajectory.Handle, format);
            GC.KeepAlive(trajectory);
        }
    }
}
