// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>An owned native byte buffer (o3d_buffer_t), e.g. an encoded cloud.</summary>
    public sealed class NativeBuffer : NativeHandle
    {
        internal NativeBuffer(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_buffer_destroy(handle); }

        /// <summary>Borrowed address of the bytes (valid until Dispose); <paramref name="size"/> gets their count.</summary>
        public IntPtr View(out long size)
        {
            IntPtr data;
            ulong n;
            O3dNative.o3d_buffer_view(out data, out n, Handle);
            GC.KeepAlive(this);
            size = (long)n;
            return data;
        }

        /// <summary>A managed copy of the bytes.</summary>
        public byte[] ToArray()
        {
            IntPtr h = Handle;
            ulong n;
            O3dNative.o3d_buffer_get_data(null, 0, out n, h);
            var bytes = new byte[n];
            O3dNative.o3d_buffer_get_data(bytes, n, out n, h);
            GC.KeepAlive(this);
            return bytes;
        }
    }

    /// <summary>Read options (o3d.io.read_point_cloud keyword arguments).</summary>
    public sealed class ReadOptions
    {
        public bool RemoveNanPoints { get; set; }
        public bool RemoveInfinitePoints { get; set; }

        internal o3d_read_options_t ToNative()
        {
            var o = new o3d_read_options_t();
            O3dNative.o3d_read_options_init(o, O3dNative.o3dx_sizeof_read_options());
            o.remove_nan_points = RemoveNanPoints ? 1 : 0;
            o.remove_infinite_points = RemoveInfinitePoints ? 1 : 0;
            return o;
        }
    }

    /// <summary>Write options (o3d.io.write_point_cloud keyword arguments).</summary>
    public sealed class WriteOptions
    {
        /// <summary>PLY/PCD: text instead of binary.</summary>
        public bool WriteAscii { get; set; }
        /// <summary>PCD: binary_compressed (LZF).</summary>
        public bool Compressed { get; set; }

        internal o3d_write_options_t ToNative()
        {
            var o = new o3d_write_options_t();
            O3dNative.o3d_write_options_init(o, O3dNative.o3dx_sizeof_write_options());
            o.write_ascii = WriteAscii ? 1 : 0;
            o.compressed = Compressed ? 1 : 0;
            return o;
        }
    }

    /// <summary>
    /// Point-cloud I/O (o3d.io): "ply", "pcd", "xyz", "xyzn", "xyzrgb", "pts". A null/""/"auto" format
    /// means: from the file extension. Failures throw O3dException (IO: missing file; Parse: bad data).
    /// </summary>
    public static partial class IO
    {
        public static PointCloud ReadPointCloud(string path, string format = null, ReadOptions options = null)
        {
            if (path == null) throw new ArgumentNullException("path");
            IntPtr h;
            using (var o = (options ?? new ReadOptions()).ToNative())
                O3dNative.o3d_io_read_point_cloud(out h, path, format, o);
            return new PointCloud(h);
        }

        public static void WritePointCloud(string path, PointCloud cloud, string format = null, WriteOptions options = null)
        {
            if (path == null) throw new ArgumentNullException("path");
            if (cloud == null) throw new ArgumentNullException("cloud");
            using (var o = (options ?? new WriteOptions()).ToNative())
                O3dNative.o3d_io_write_point_cloud(path, cloud.Handle, format, o);
            GC.KeepAlive(cloud);
        }

        /// <summary>Decode a cloud from bytes; <paramref name="format"/> is required.</summary>
        public static PointCloud ReadPointCloudFromMemory(byte[] data, string format, ReadOptions options = null)
        {
            if (data == null) throw new ArgumentNullException("data");
            IntPtr h;
            using (var o = (options ?? new ReadOptions()).ToNative())
                O3dNative.o3d_io_read_point_cloud_from_memory(out h, data, (ulong)data.Length, format, o);
            return new PointCloud(h);
        }

        /// <summary>Encode a cloud; the bytes are returned as a native buffer (zero-copy view available).</summary>
        public static NativeBuffer WritePointCloudToNativeBuffer(PointCloud cloud, string format, WriteOptions options = null)
        {
            if (cloud == null) throw new ArgumentNullException("cloud");
            IntPtr b;
            using (var o = (options ?? new WriteOptions()).ToNative())
                O3dNative.o3d_io_write_point_cloud_to_memory(out b, cloud.Handle, format, o);
            GC.KeepAlive(cloud);
            return new NativeBuffer(b);
        }

        /// <summary>Encode a cloud into a managed byte array.</summary>
        public static byte[] WritePointCloudToMemory(PointCloud cloud, string format, WriteOptions options = null)
        {
            using (var b = WritePointCloudToNativeBuffer(cloud, format, options)) return b.ToArray();
        }
    }
}
