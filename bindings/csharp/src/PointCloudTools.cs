// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>
    /// Result of <see cref="PointCloud.RemoveStatisticalOutlier"/> / <see cref="PointCloud.RemoveRadiusOutlier"/>
    /// (Open3D's <c>(cloud, ind)</c> tuple): the kept points as a new cloud and their indices (ascending) in
    /// the input. Disposing it disposes <see cref="Cloud"/>.
    /// </summary>
    public sealed class OutlierRemovalResult : IDisposable
    {
        internal OutlierRemovalResult(PointCloud cloud, int[] indices) { Cloud = cloud; Indices = indices; }

        /// <summary>The kept points (with their normals and colors); owned by the caller.</summary>
        public PointCloud Cloud { get; private set; }
        /// <summary>Indices of the kept points in the input cloud, ascending.</summary>
        public int[] Indices { get; private set; }

        public void Dispose() { Cloud.Dispose(); }
    }

    /// <summary>Result of <see cref="PointCloud.SegmentPlane"/> (Open3D's <c>(plane_model, inliers)</c>).</summary>
    public sealed class PlaneSegmentationResult
    {
        internal PlaneSegmentationResult(double[] plane, int[] inliers) { Plane = plane; Inliers = inliers; }

        /// <summary>(a, b, c, d) with a x + b y + c z + d = 0 and |(a, b, c)| = 1.</summary>
        public double[] Plane { get; private set; }
        /// <summary>Indices of the inlier points, ascending.</summary>
        public int[] Inliers { get; private set; }
    }

    /// <summary>Result of <see cref="PointCloud.ComputeMeanAndCovariance"/>.</summary>
    public sealed class MeanAndCovariance
    {
        internal MeanAndCovariance(double[] mean, double[] covariance) { Mean = mean; Covariance = covariance; }

        /// <summary>Mean point (3 values).</summary>
        public double[] Mean { get; private set; }
        /// <summary>Covariance, row-major 3x3 (9 values), divided by N.</summary>
        public double[] Covariance { get; private set; }
    }
}
