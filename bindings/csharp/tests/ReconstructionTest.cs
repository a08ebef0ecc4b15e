// SPDX-License-Identifier: MIT
// The reconstruction system from C#: a stage run on a dataset written here (three frames of a textured plane 1 m
// away, the camera sliding 1 cm a frame), progress rising to 1, cancelling, and errors naming the stage to run
// first. (The known-trajectory run is tests/capi/test_reconstruction.c; the living-room run is the Python test.)
using System;
using System.IO;
using O3d;

static partial class Test
{
    // A dataset below `folder` in Open3D's layout and the config that reconstructs it into `folder`/out.
    static string WritePlaneDataset(string folder)
    {
        const int w = 96, h = 72;
        if (Directory.Exists(folder)) Directory.Delete(folder, true);
        Directory.CreateDirectory(Path.Combine(folder, "data", "color"));
        Directory.CreateDirectory(Path.Combine(folder, "data", "depth"));
        for (int k = 0; k < 3; k++)
        {
            var rgb = new byte[3 * w * h];
            var depth = new ushort[w * h];
            for (int v = 0; v < h; v++)
                for (int u = 0; u < w; u++)
                {
                    double x = (u - w / 2.0) / 80.0 + 0.01 * k, y = (v - h / 2.0) / 80.0;
                    for (int c = 0; c < 3; c++)
                        rgb[3 * (v * w + u) + c] = (byte)(128 + 100 * Math.Sin(9.0 * x + 2.0 * c) * Math.Cos(7.0 * y - c));
                    depth[v * w + u] = 1000;
                }
            var name = string.Format("{0:D5}.png", k);
            using (var color = Image.FromArray(w, h, 3, rgb)) Library.IoWriteImage(Path.Combine(folder, "data", "color", name), color, "", -1);
            using (var d = Image.FromArray(w, h, 1, depth)) Library.IoWriteImage(Path.Combine(folder, "data", "depth", name), d, "", -1);
        }
        Library.IoWritePinholeCameraIntrinsic(Path.Combine(folder, "intrinsic.json"), Intrinsic(w, h, 80, 80, 47.5, 35.5));
        var config = Path.Combine(folder, "config.json");
        File.WriteAllText(config, "{\"path_dataset\": \"" + folder + "/data\", \"path_intrinsic\": \"" + folder +
            "/intrinsic.json\", \"path_output\": \"" + folder + "/out\", \"n_frames_per_fragment\": 3, " +
            "\"n_keyframes_per_n_frame\": 1, \"tsdf_cubic_size\": 4.0}");
        return config;
    }

    static void ReconstructionTests()
    {
        Run("reconstruction: a stage runs, reports progress, cancels, names the stage to run first", () =>
        {
            var folder = Path.Combine(Path.GetTempPath(), "o3d_csharp_reconstruction");
            var config = WritePlaneDataset(folder);
            using (var o = new ReconstructionOptions())
            {
                Check(o.Resume == 1 && o.NumThreads == 0, "defaults from o3d_reconstruction_options_init");
                double last = -1;
                bool rising = true;
                o.SetProgress(f => { rising &= f >= last; last = f; return true; });
                Library.ReconstructionRunStage(config, Library.RECONSTRUCTION_STAGE_MAKE_FRAGMENTS, o);
                Check(last == 1.0 && rising, "progress rises to 1: " + last);
                var fragment = Path.Combine(folder, "out", "fragments", "fragment_000.ply");
                Check(File.Exists(fragment), "fragment cloud written");
                o.Resume = 0;
                o.SetProgress(f => false);
                ThrowsStatus(Library.ERROR_CANCELLED,
                    () => Library.ReconstructionRunStage(config, Library.RECONSTRUCTION_STAGE_MAKE_FRAGMENTS, o), "cancel");
                Check(File.Exists(fragment), "finished outputs stay");
            }
            var e = Throws<O3dException>(() => Library.ReconstructionRunStage(config, Library.RECONSTRUCTION_STAGE_INTEGRATE_SCENE, null), "integrate first");
            Check(e.Status == Library.ERROR_IO && e.Message.Contains("run the \"refine registration\" stage first"), e.Message);
            Directory.Delete(folder, true);
        });
    }
}
