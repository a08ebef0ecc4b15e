// SPDX-License-Identifier: MIT
// Visualizer from C# in a hidden window (EGL: no display needed), the scenarios of tests/capi/test_visualizer.c
// and VisualizerTest.java: the default view against Open3D's ViewControl model, a key callback by its effect
// on the captured image, an animation callback turning the view, a callback's exception coming out of Run,
// and a call without a window.
using System;
using O3d;

static partial class Test
{
    const int VW = 160, VH = 120;

    // A hidden visualizer showing a unit cube centred at the origin; lights off so that its pixels have exactly
    // its colour.
    static Visualizer CubeViewer(double[] color)
    {
        var v = Visualizer.Create(0);
        v.CreateWindow("test", VW, VH, -1, -1, 0);
        using (var cube = TriangleMesh.CreateBox(1, 1, 1))
        {
            cube.Translate(new double[] { -0.5, -0.5, -0.5 }, 1);
            cube.PaintUniformColor(color);
            v.AddTrianglemesh("cube", cube, 1);
        }
        using (var o = v.GetRenderOption())
        {
            o.LightOn = 0;
            v.SetRenderOption(o);
        }
        return v;
    }

    static double[] ScreenAt(Visualizer v, int u, int y)
    {
        using (var img = v.CaptureScreenFloatBuffer(1))
        {
            var f = img.ToFloatArray();
            int i = 3 * (y * VW + u);
            return new double[] { f[i], f[i + 1], f[i + 2] };
        }
    }

    static void VisualizerTests()
    {
        Run("visualizer: default view depth, view status text, picked points", () =>
        {
            using (var v = CubeViewer(new double[] { 1, 0, 0 }))
            {
                AllNear(ScreenAt(v, 0, 0), new double[] { 1, 1, 1 }, 0, "white background");
                AllNear(ScreenAt(v, VW / 2, VH / 2), new double[] { 1, 0, 0 }, 0, "the cube's colour");
                // Open3D's default view: the eye on +z at zoom * extent / tan(30 deg) from the centre; the front
                // face (z = 0.5) is 0.5 nearer.
                double expected = 0.7 / Math.Tan(Math.PI / 6) - 0.5;
                using (var depth = v.CaptureDepthFloatBuffer(1))
                    Near(depth.ToFloatArray()[VH / 2 * VW + VW / 2], expected, 1e-3 * expected, "depth at the centre");
                Near(v.ViewGetFieldOfView(), 60, 1e-12, "field of view");
                string status = v.GetViewStatus();
                Check(status.Contains("ViewTrajectory") && status.Contains("field_of_view"), "view status JSON: " + status);
                v.ViewRotate(100, 0);
                v.SetViewStatus(status); // back to the default view
                using (var g = v.ViewGet()) AllNear(g.Front(), new double[] { 0, 0, 1 }, 1e-9, "front from the status");
                Check(v.GetPickedPoints().Length == 0 && v.PollEvents(), "no picks, window open");
            }
        });

        Run("visualizer: trajectory playback with captures and progress", () =>
        {
            // two key views, two frames between: four frames, each captured
            const string View = "{\"boundingbox_max\": [0.5, 0.5, 0.5], \"boundingbox_min\": [-0.5, -0.5, -0.5], \"field_of_view\": 60.0, \"front\": [F], \"lookat\": [0, 0, 0], \"up\": [0, 1, 0], \"zoom\": 0.7}";
            string dir = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "o3d_cs_traj_" + Guid.NewGuid().ToString("N"));
            System.IO.Directory.CreateDirectory(dir);
            try
            {
                string path = System.IO.Path.Combine(dir, "trajectory.json");
                System.IO.File.WriteAllText(path, "{\"class_name\": \"ViewTrajectory\", \"interval\": 2, \"is_loop\": false, \"trajectory\": ["
                    + View.Replace("F", "0, 0, 1") + ", " + View.Replace("F", "1, 0, 0") + "]}");
                using (var v = CubeViewer(new double[] { 1, 0, 0 }))
                {
                    var fractions = new System.Collections.Generic.List<double>();
                    v.PlayViewTrajectory(path, dir, true, f => { fractions.Add(f); return true; });
                    Check(fractions.Count == 4 && fractions[3] == 1.0, "four progress calls ending at 1");
                    using (var g = v.ViewGet()) AllNear(g.Front(), new double[] { 1, 0, 0 }, 1e-12, "ends on the last key view");
                    Check(System.IO.File.Exists(System.IO.Path.Combine(dir, "image_000003.png")) && System.IO.File.Exists(System.IO.Path.Combine(dir, "depth_000003.png")), "captures");
                    ThrowsStatus(Library.ERROR_CANCELLED, () => v.PlayViewTrajectory(path, null, false, f => false), "progress cancels");
                }
            }
            finally { System.IO.Directory.Delete(dir, true); }
        });

        Run("visualizer: a key callback paints the background", () =>
        {
            using (var v = CubeViewer(new double[] { 1, 0, 0 }))
            {
                int calls = 0;
                v.RegisterKeyCallback('K', vis =>
                {
                    calls++;
                    using (var o = vis.GetRenderOption())
                    {
                        o.SetBackgroundColor(new double[] { 0, 0, 0 });
                        vis.SetRenderOption(o);
                    }
                    return true;
                });
                v.SendKey('K', Library.KEY_ACTION_RELEASE, 0);
                Check(calls == 0, "not on release");
                v.SendKey('K', Library.KEY_ACTION_PRESS, 0);
                Check(calls == 1, "called on press");
                AllNear(ScreenAt(v, 0, 0), new double[] { 0, 0, 0 }, 0, "black background");
                var actions = new System.Collections.Generic.List<int>();
                v.RegisterKeyActionCallback('K', (vis, action, mods) => { actions.Add(action * 10 + mods); return false; });
                v.SendKey('K', Library.KEY_ACTION_RELEASE, Library.KEY_MOD_SHIFT);
                Check(actions.Count == 1 && actions[0] == Library.KEY_ACTION_RELEASE * 10 + Library.KEY_MOD_SHIFT, "action callback on release");
                v.RegisterKeyCallback('K', null); // removed: K does nothing now
                v.SendKey('K', Library.KEY_ACTION_PRESS, 0);
                Check(calls == 1 && actions.Count == 1, "no callback after removal");
            }
        });

        Run("visualizer: an animation callback turns the view, then closes", () =>
        {
            using (var v = CubeViewer(new double[] { 0, 0, 1 }))
            {
                int frames = 0;
                v.RegisterAnimationCallback(vis =>
                {
                    vis.ViewRotate(10, 0);
                    if (++frames == 5) vis.Close();
                    return true;
                });
                v.Run();
                Check(frames == 5, "five frames, got " + frames);
                // five turns of 10 px at 0.003 rad per pixel about the up axis: 0.15 rad in all
                using (var g = v.ViewGet()) AllNear(g.Front(), new double[] { -Math.Sin(0.15), 0, Math.Cos(0.15) }, 1e-9, "front");
            }
        });

        Run("visualizer: a callback's exception comes out of Run; no window throws", () =>
        {
            using (var v = CubeViewer(new double[] { 0, 1, 0 }))
            {
                var thrown = new InvalidOperationException("spin failed on purpose");
                int frames = 0;
                v.RegisterAnimationCallback(vis => { if (++frames == 2) throw thrown; return false; });
                var e = Throws<InvalidOperationException>(() => v.Run(), "Run with a throwing callback");
                Check(ReferenceEquals(e, thrown) && frames == 2, "the callback's own exception, at the second frame");
                v.RegisterAnimationCallback(null);
                v.Run(); // no callback: one frame, and the visualizer still works
                v.RegisterKeyCallback('E', vis => { throw new ArgumentException("key failed"); });
                Throws<ArgumentException>(() => v.SendKey('E', Library.KEY_ACTION_PRESS, 0), "SendKey with a throwing callback");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => v.RegisterKeyCallback(-1, vis => true), "negative key");
            }
            using (var v = Visualizer.Create(0))
            {
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => v.Run(), "Run without a window");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => v.CaptureScreenFloatBuffer(1), "capture without a window");
                v.Dispose();
                Throws<ObjectDisposedException>(() => v.Run(), "Run after Dispose");
            }
        });
    }
}
