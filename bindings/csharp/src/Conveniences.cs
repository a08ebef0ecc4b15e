// SPDX-License-Identifier: MIT
// Hand-written conveniences over the SWIG classes (partial classes; SWIG cannot derive these).
using System;

namespace O3d
{
    public partial class PointCloud
    {
        /// <summary>A cloud holding <paramref name="points"/> (x, y, z per point).</summary>
        public PointCloud(double[] points) : this() { SetArray(Library.POINTCLOUD_POINTS, points); }
        /// <summary>Open3D-style array properties (copies in and out).</summary>
        public double[] Points { get { return GetArray(Library.POINTCLOUD_POINTS); } set { SetArray(Library.POINTCLOUD_POINTS, value); } }
        public double[] Normals { get { return GetArray(Library.POINTCLOUD_NORMALS); } set { SetArray(Library.POINTCLOUD_NORMALS, value); } }
        public double[] Colors { get { return GetArray(Library.POINTCLOUD_COLORS); } set { SetArray(Library.POINTCLOUD_COLORS, value); } }
        public double[] Covariances { get { return GetArray(Library.POINTCLOUD_COVARIANCES); } set { SetArray(Library.POINTCLOUD_COVARIANCES, value); } }
    }

    public partial class TriangleMesh
    {
        /// <summary>A mesh of <paramref name="vertices"/> (x, y, z) and <paramref name="triangles"/> (3 indices each).</summary>
        public TriangleMesh(double[] vertices, int[] triangles) : this()
        {
            SetArray(Library.MESH_VERTICES, vertices);
            SetIndexArray(Library.MESH_TRIANGLES, triangles);
        }
        public double[] Vertices { get { return GetArray(Library.MESH_VERTICES); } set { SetArray(Library.MESH_VERTICES, value); } }
        public int[] Triangles { get { return GetIndexArray(Library.MESH_TRIANGLES); } set { SetIndexArray(Library.MESH_TRIANGLES, value); } }
    }

    public partial class Image
    {
        /// <summary>Open3D's CreatePyramid: level 0 a copy, each next level (Gaussian3-filtered unless
        /// <paramref name="withGaussianFilter"/> is false, then) downsampled by 2. Float images only.</summary>
        public Image[] CreatePyramid(int levels, bool withGaussianFilter = true)
        {
            if (levels < 1) throw new ArgumentOutOfRangeException("levels");
            var pyramid = new Image[levels];
            try
            {
                pyramid[0] = Clone();
                for (int i = 1; i < levels; i++)
                {
                    if (!withGaussianFilter) { pyramid[i] = pyramid[i - 1].Downsample(); continue; }
                    using (var blurred = pyramid[i - 1].Filter(Library.IMAGE_FILTER_GAUSSIAN3)) pyramid[i] = blurred.Downsample();
                }
                return pyramid;
            }
            catch { foreach (var level in pyramid) if (level != null) level.Dispose(); throw; }
        }
        /// <summary>The pixels as float32 (4-byte channels), a copy.</summary>
        public float[] ToFloatArray() { return Reinterpret<float>(4); }
        /// <summary>The pixels as uint16 (2-byte channels), a copy.</summary>
        public ushort[] ToUInt16Array() { return Reinterpret<ushort>(2); }
        T[] Reinterpret<T>(int bytes) where T : struct
        {
            if (BytesPerChannel() != bytes) throw new InvalidOperationException("the image has " + BytesPerChannel() + "-byte channels");
            byte[] raw = GetArray(Library.IMAGE_DATA);
            var a = new T[raw.Length / bytes];
            System.Buffer.BlockCopy(raw, 0, a, 0, raw.Length);
            return a;
        }
        /// <summary>An image of float32 or uint16 pixels (row-major, channels interleaved).</summary>
        public static Image FromArray<T>(int width, int height, int channels, T[] pixels) where T : struct
        {
            int bytes = System.Runtime.InteropServices.Marshal.SizeOf(typeof(T));
            var raw = new byte[pixels.Length * bytes];
            System.Buffer.BlockCopy(pixels, 0, raw, 0, raw.Length);
            return CreateFromData(width, height, channels, bytes, raw);
        }
    }

    /// <summary>A robust kernel (Library.KERNEL_* and its parameter k), as IcpOptions.Kernel / KernelK take it.</summary>
    public struct RobustKernel
    {
        public int Kind; public double K;
        public RobustKernel(int kind, double k = 1) { Kind = kind; K = k; }
        public static RobustKernel L2Loss() { return new RobustKernel(Library.KERNEL_L2); }
        public static RobustKernel L1Loss() { return new RobustKernel(Library.KERNEL_L1); }
        public static RobustKernel HuberLoss(double k) { return new RobustKernel(Library.KERNEL_HUBER, k); }
        public static RobustKernel CauchyLoss(double k) { return new RobustKernel(Library.KERNEL_CAUCHY, k); }
        public static RobustKernel GMLoss(double k) { return new RobustKernel(Library.KERNEL_GM, k); }
        public static RobustKernel TukeyLoss(double k) { return new RobustKernel(Library.KERNEL_TUKEY, k); }
        /// <summary>The weight w(residual) of the iteratively reweighted least squares.</summary>
        public double Weight(double residual) { return Library.RobustKernelWeight(Kind, K, residual); }
    }

    public partial class IcpOptions
    {
        /// <summary>Kernel and KernelK together.</summary>
        public RobustKernel RobustKernel { get { return new RobustKernel(Kernel, KernelK); } set { Kernel = value.Kind; KernelK = value.K; } }
    }
}
