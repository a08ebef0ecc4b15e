// SPDX-License-Identifier: MIT
// TSDF volumes from C#, the scenarios of tests/capi/test_integration.c: a fronto-parallel plane comes back at its
// depth, one vertex per voxel column, and the volume's array and errors.
using System;
using O3d;

static partial class Test
{
    static void IntegrationTests()
    {
        Run("integration: a plane comes back at its depth", () =>
        {
            const int w = 160, h = 120;
            var color = new byte[3 * w * h];
            for (int i = 0; i < w * h; i++) { color[3 * i] = 200; color[3 * i + 1] = 100; color[3 * i + 2] = 50; }
            var depth = new float[w * h];
            for (int i = 0; i < w * h; i++) depth[i] = 1.0f;
            var identity = new double[] { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
            using (var c = Image.FromArray(w, h, 3, color))
            using (var d = Image.FromArray(w, h, 1, depth))
            using (var o = new RgbdOptions { DepthScale = 1.0, ConvertRgbToIntensity = 0 })
            using (var frame = RGBDImage.CreateFromColorAndDepth(c, d, o))
            using (var volume = TSDFVolume.CreateUniform(1.0, 64, 0.04, Library.TSDF_VOLUME_COLOR_TYPE_RGB8, new[] { -0.5, -0.5, 0.5 }))
            {
                volume.Integrate(frame, Intrinsic(w, h, 100, 100, 79.5, 59.5), identity);
                using (var mesh = volume.ExtractTriangleMesh())
                {
                    var v = mesh.Vertices;
                    Check(v.Length == 3 * 64 * 64, "one vertex per voxel column: " + v.Length / 3);
                    for (int i = 2; i < v.Length; i += 3) Near(v[i], 1.0, 1e-4, "vertex depth");
                }
                var tsdf = volume.ExtractVolumeTsdf();
                Check(tsdf.Length == 2 * 64 * 64 * 64, "tsdf rows");
                Near(tsdf[2 * ((32 * 64 + 32) * 64 + 30)], (1.0 - (0.5 + 30.5 / 64)) / 0.04, 1e-4, "voxel tsdf");
                Check(!volume.IsScalable() && volume.GetResolution() == 64, "uniform, 64");
            }
            using (var scalable = TSDFVolume.CreateScalable(0.01, 0.04, Library.TSDF_VOLUME_COLOR_TYPE_RGB8, 16, 4))
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => scalable.ExtractVolumeTsdf(), "a scalable volume has no dense array");
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => TSDFVolume.CreateScalable(0.0, 0.04, Library.TSDF_VOLUME_COLOR_TYPE_NO_COLOR, 16, 4), "voxel_length 0");
        });
    }
}
