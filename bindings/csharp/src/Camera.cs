// SPDX-License-Identifier: MIT
using System;
using System.Collections.Generic;

namespace O3d
{
    /// <summary>Open3D's PinholeCameraIntrinsicParameters presets.</summary>
    public enum PinholeCameraIntrinsicParameters
    {
        /// <summary>640x480, fx = fy = 525, cx = 319.5, cy = 239.5.</summary>
        PrimeSenseDefault = O3dNative.O3D_INTRINSIC_PRIMESENSE_DEFAULT,
        Kinect2DepthCameraDefault = O3dNative.O3D_INTRINSIC_KINECT2_DEPTH_DEFAULT,
        Kinect2ColorCameraDefault = O3dNative.O3D_INTRINSIC_KINECT2_COLOR_DEFAULT,
    }

    /// <summary>
    /// o3d.camera.PinholeCameraIntrinsic as an immutable value: image size, focal lengths and principal
    /// point in pixels. Compared by value.
    /// </summary>
    public sealed class PinholeCameraIntrinsic : IEquatable<PinholeCameraIntrinsic>
    {
        public int Width { get; private set; }
        public int Height { get; private set; }
        public double Fx { get; private set; }
        public double Fy { get; private set; }
        public double Cx { get; private set; }
        public double Cy { get; private set; }

        public PinholeCameraIntrinsic(int width, int height, double fx, double fy, double cx, double cy)
        {
            Width = width; Height = height; Fx = fx; Fy = fy; Cx = cx; Cy = cy;
        }

        /// <summary>One of Open3D's presets.</summary>
        public static PinholeCameraIntrinsic FromPreset(PinholeCameraIntrinsicParameters preset)
        {
            using (var n = new o3d_pinhole_intrinsic_t())
            {
                O3dNative.o3d_pinhole_intrinsic_set_preset(n, (int)preset);
                return FromNative(n);
            }
        }

        /// <summary>Row-major 3x3 [[fx, 0, cx], [0, fy, cy], [0, 0, 1]].</summary>
        public double[] IntrinsicMatrix
        {
            get { return new[] { Fx, 0, Cx, 0, Fy, Cy, 0, 0, 1.0 }; }
        }

        internal o3d_pinhole_intrinsic_t ToNative()
        {
            var n = new o3d_pinhole_intrinsic_t();
            n.width = Width; n.height = Height; n.fx = Fx; n.fy = Fy; n.cx = Cx; n.cy = Cy;
            return n;
        }

        internal static PinholeCameraIntrinsic FromNative(o3d_pinhole_intrinsic_t n)
        {
            return new PinholeCameraIntrinsic(n.width, n.height, n.fx, n.fy, n.cx, n.cy);
        }

        public bool Equals(PinholeCameraIntrinsic o)
        {
            return o != null && Width == o.Width && Height == o.Height && Fx.Equals(o.Fx) && Fy.Equals(o.Fy) &&
                   Cx.Equals(o.Cx) && Cy.Equals(o.Cy);
        }

        public override bool Equals(object obj) { return Equals(obj as PinholeCameraIntrinsic); }

        public override int GetHashCode()
        {
            int h = Width * 31 + Height;
            h = h * 31 + Fx.GetHashCode(); h = h * 31 + Fy.GetHashCode();
            h = h * 31 + Cx.GetHashCode(); return h * 31 + Cy.GetHashCode();
        }

        public override string ToString()
        {
            return string.Format("PinholeCameraIntrinsic({0}x{1}, fx={2}, fy={3}, cx={4}, cy={5})", Width, Height, Fx, Fy, Cx, Cy);
        }
    }

    /// <summary>o3d.camera.PinholeCameraParameters: an intrinsic and a row-major 4x4 world-to-camera extrinsic.</summary>
    public sealed class PinholeCameraParameters
    {
        public PinholeCameraIntrinsic Intrinsic { get; private set; }
        /// <summary>Row-major 4x4 (16 values; a copy is kept).</summary>
        public double[] Extrinsic { get { return (double[])extrinsic.Clone(); } }
        readonly double[] extrinsic;

        public PinholeCameraParameters(PinholeCameraIntrinsic intrinsic, double[] extrinsic)
        {
            if (intrinsic == null) throw new ArgumentNullException("intrinsic");
            Intrinsic = intrinsic;
            this.extrinsic = (double[])Checks.Fixed(extrinsic, 16, "extrinsic", false).Clone();
        }
    }

    /// <summary>o3d.camera.PinholeCameraTrajectory: a list of camera poses. Dispose it.</summary>
    public sealed class PinholeCameraTrajectory : NativeHandle
    {
        internal PinholeCameraTrajectory(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_camera_trajectory_destroy(handle); }

        static IntPtr Create()
        {
            IntPtr h;
            O3dNative.o3d_camera_trajectory_create(out h);
            return h;
        }

        /// <summary>An empty trajectory.</summary>
        public PinholeCameraTrajectory() : base(Create()) { }

        /// <summary>Number of poses.</summary>
        public long Count
        {
            get { ulong n; O3dNative.o3d_camera_trajectory_size(out n, Handle); GC.KeepAlive(this); return (long)n; }
        }

        /// <summary>Pose <paramref name="index"/> (out of range: O3dException InvalidArgument).</summary>
        public PinholeCameraParameters this[long index]
        {
            get
            {
                if (index < 0) throw new ArgumentOutOfRangeException("index");
                var extrinsic = new double[16];
                using (var n = new o3d_pinhole_intrinsic_t())
                {
                    O3dNative.o3d_camera_trajectory_get(n, extrinsic, Handle, (ulong)index);
                    GC.KeepAlive(this);
                    return new PinholeCameraParameters(PinholeCameraIntrinsic.FromNative(n), extrinsic);
                }
            }
        }

        /// <summary>All poses (Open3D's <c>parameters</c>), copied.</summary>
        public List<PinholeCameraParameters> Parameters
        {
            get
            {
                long count = Count;
                var list = new List<PinholeCameraParameters>((int)count);
                for (long i = 0; i < count; i++) list.Add(this[i]);
                return list;
            }
        }

        /// <summary>Append a pose; the extrinsic's last row must be (0, 0, 0, 1).</summary>
        public void Append(PinholeCameraIntrinsic intrinsic, double[] extrinsic)
        {
            if (intrinsic == null) throw new ArgumentNullException("intrinsic");
            using (var n = intrinsic.ToNative())
                O3dNative.o3d_camera_trajectory_append(Handle, n, Checks.Fixed(extrinsic, 16, "extrinsic", false));
            GC.KeepAlive(this);
        }

        public void Append(PinholeCameraParameters parameters)
        {
            if (parameters == null) throw new ArgumentNullException("parameters");
            Append(parameters.Intrinsic, parameters.Extrinsic);
        }

        public void Clear() { O3dNative.o3d_camera_trajectory_clear(Handle); GC.KeepAlive(this); }
    }
}
