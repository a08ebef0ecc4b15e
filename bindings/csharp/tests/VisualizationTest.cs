// SPDX-License-Identifier: MIT
// OffscreenRenderer from C#: pixels against a known pinhole camera (the same scenarios as
// VisualizationTest.java). The scene is a unit box [-0.5, 0.5]^2 x [2.5, 3.5] seen from the origin along +z
// with fx = fy = 100 and the principal point at the image centre (79.5, 59.5) of a 160 x 120 image, so its
// front face (z = 2.5) covers the 40 x 40 pixels 60..99 x 40..79 and the depth along the axis there is 2.5.
using System;
using System.IO;
using System.Linq;
using O3d;

static partial class Test
{
    const int RW = 160, RH = 120;
    const int CU = 80, CV = 60; // a pixel on the box's front face, next to the optical axis
    static readonly double[] BoxColor = { 0.2, 0.4, 0.6 };
    static readonly double[] White = { 1, 1, 1 };
    static readonly double[] Identity4 = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };

    static PinholeCameraIntrinsic RenderCamera() { return Intrinsic(RW, RH, 100, 100, 79.5, 59.5); }

    static TriangleMesh UnitBox(double[] color)
    {
        var box = TriangleMesh.CreateBox(1, 1, 1);
        box.Translate(new double[] { -0.5, -0.5, 2.5 }, 1);
        box.PaintUniformColor(color);
        return box;
    }

    static RenderMaterial Unlit()
    {
        return new RenderMaterial { Shader = Library.SHADER_DEFAULT_UNLIT };
    }

    // A renderer looking through RenderCamera() from the origin.
    static OffscreenRenderer PinholeRenderer()
    {
        var r = OffscreenRenderer.Create(RW, RH, Library.RENDER_BACKEND_AUTO);
        r.SetupCamera(RenderCamera(), Identity4);
        return r;
    }

    static byte[] Pixel(byte[] rgb, int u, int v)
    {
        int i = (v * RW + u) * 3;
        return new[] { rgb[i], rgb[i + 1], rgb[i + 2] };
    }

    // `color` in [0, 1] as 8-bit, within one step (rounding or truncation).
    static void Rgb(byte[] got, double[] color, string what)
    {
        for (int c = 0; c < 3; c++) Near(got[c], 255 * color[c], 1, what + " channel " + c);
    }

    static void Corners(byte[] rgb, double[] color)
    {
        Rgb(Pixel(rgb, 0, 0), color, "corner (0, 0)");
        Rgb(Pixel(rgb, RW - 1, 0), color, "corner (w-1, 0)");
        Rgb(Pixel(rgb, 0, RH - 1), color, "corner (0, h-1)");
        Rgb(Pixel(rgb, RW - 1, RH - 1), color, "corner (w-1, h-1)");
    }

    // Pixels more than one step away from `background` in some channel.
    static int CountNot(byte[] rgb, double[] background)
    {
        int n = 0;
        for (int i = 0; i < rgb.Length; i += 3)
            if (Enumerable.Range(0, 3).Any(c => Math.Abs(rgb[i + c] - 255 * background[c]) > 1)) n++;
        return n;
    }

    static byte[] RenderRgb(OffscreenRenderer r)
    {
        using (var img = r.RenderToImage()) return img.GetArray(Library.IMAGE_DATA);
    }

    static float DepthAt(OffscreenRenderer r, bool zInViewSpace, int u, int v)
    {
        using (var img = r.RenderToDepthImage(zInViewSpace ? 1 : 0)) return img.ToFloatArray()[v * RW + u];
    }

    static void VisualizationTests()
    {
        Run("render option and material defaults are Open3D's", () =>
        {
            using (var o = new RenderOption())
            using (var m = new RenderMaterial())
            {
                AllNear(o.GetBackgroundColor(), White, 0, "background");
                Check(o.PointSize == 5 && o.LineWidth == 1 && o.LightOn == 1, "sizes and light_on");
                Check(o.PointColorOption == Library.COLOR_OPTION_DEFAULT && o.MeshColorOption == Library.COLOR_OPTION_COLOR, "color options");
                Check(o.MeshShadeOption == Library.MESH_SHADE_FLAT, "flat shading");
                AllNear(o.GetDefaultMeshColor(), new double[] { 0.7, 0.7, 0.7 }, 0, "default mesh color");
                AllNear(o.GetLightDiffusePower(), new double[] { 0.66, 0.66, 0.66, 0.66 }, 0, "diffuse power");
                Check(m.Shader == Library.SHADER_DEFAULT_LIT && m.PointSize == 0 && m.LineWidth == 0, "material");
                AllNear(m.GetBaseColor(), new double[] { 1, 1, 1, 1 }, 0, "base color");
            }
        });

        Run("render option JSON round trip", () =>
        {
            string path = Path.Combine(Path.GetTempPath(), "o3d_cs_renderoption_" + Guid.NewGuid().ToString("N") + ".json");
            try
            {
                using (var o = new RenderOption { PointSize = 7, MeshShowWireframe = 1, MeshColorOption = Library.COLOR_OPTION_Z })
                {
                    o.SetBackgroundColor(new double[] { 0.1, 0.2, 0.3 });
                    RenderOption.SaveJson(path, o);
                    using (var back = RenderOption.LoadJson(path))
                    {
                        AllNear(back.GetBackgroundColor(), new double[] { 0.1, 0.2, 0.3 }, 0, "background");
                        Check(back.PointSize == 7 && back.MeshShowWireframe == 1, "point size, wireframe");
                        Check(back.MeshColorOption == Library.COLOR_OPTION_Z, "mesh color option");
                    }
                }
            }
            finally { File.Delete(path); }
            ThrowsStatus(Library.ERROR_IO, () => RenderOption.LoadJson("/nonexistent/dir/option.json"), "missing file");
        });

        Run("render option from Open3D's renderoption.json", () =>
        {
            // Open3D's file differs from the defaults only in point_color_option (9, Normal).
            using (var file = RenderOption.LoadJson(DataFile("open3d/renderoption.json")))
            {
                Check(file.PointColorOption == Library.COLOR_OPTION_NORMAL, "point color option " + file.PointColorOption);
                AllNear(file.GetBackgroundColor(), White, 0, "file background");
            }
        });

        Run("unlit box: colour, depth and silhouette under a pinhole camera", () =>
        {
            using (var r = PinholeRenderer())
            using (var box = UnitBox(BoxColor))
            using (var unlit = Unlit())
            {
                int backend = r.GetBackend();
                Check(backend == Library.RENDER_BACKEND_EGL || backend == Library.RENDER_BACKEND_GLFW, "backend " + backend);
                using (var size = r.GetSize()) Check(size.Width() == RW && size.Height() == RH, "size");
                r.AddTrianglemesh("box", box, unlit);
                using (var img = r.RenderToImage())
                    Check(img.Width() == RW && img.Height() == RH && img.NumChannels() == 3 && img.BytesPerChannel() == 1, "RGB u8");
                var rgb = RenderRgb(r);
                Corners(rgb, White);
                Rgb(Pixel(rgb, CU, CV), BoxColor, "box centre");
                Rgb(Pixel(rgb, 61, 41), BoxColor, "inside the face's top-left corner");
                Rgb(Pixel(rgb, 58, CV), White, "left of the face");
                Rgb(Pixel(rgb, CU, 81), White, "below the face");
                Near(CountNot(rgb, White), 1600, 0.02 * 1600, "silhouette: the 40 x 40 front face");

                Near(DepthAt(r, true, CU, CV), 2.5, 1e-3, "depth at the centre");
                Near(DepthAt(r, true, 61, 41), 2.5, 1e-3, "depth near the face's corner");
                Check(DepthAt(r, true, 0, 0) == 0, "no depth in the background");
                float buffer = DepthAt(r, false, CU, CV);
                Check(buffer > 0 && buffer < 1, "depth buffer " + buffer);
                Check(DepthAt(r, false, RW - 1, RH - 1) == 1, "depth buffer background 1");

                using (var cam = r.GetCamera())
                {
                    SameIntrinsic(RenderCamera(), cam.Intrinsic(), "camera intrinsic");
                    AllNear(cam.Extrinsic(), Identity4, 1e-12, "camera extrinsic");
                }
            }
        });

        Run("background, material tint and ambient-only light", () =>
        {
            using (var r = PinholeRenderer())
            using (var o = new RenderOption())
            using (var box = UnitBox(BoxColor))
            using (var tinted = Unlit())
            {
                o.SetBackgroundColor(new double[] { 0.1, 0.2, 0.3 });
                r.SetRenderOption(o);
                using (var got = r.GetRenderOption()) AllNear(got.GetBackgroundColor(), new double[] { 0.1, 0.2, 0.3 }, 0, "option read back");
                tinted.SetBaseColor(new double[] { 0.5, 1, 1, 1 });
                r.AddTrianglemesh("box", box, tinted);
                var rgb = RenderRgb(r);
                Corners(rgb, new double[] { 0.1, 0.2, 0.3 });
                Rgb(Pixel(rgb, CU, CV), new double[] { 0.1, 0.4, 0.6 }, "tinted box");

                // Lit with only ambient light: color * ambient (the header's formula, every light at power 0).
                o.LightOn = 1;
                o.SetLightAmbientColor(new double[] { 0.5, 0.5, 0.5 });
                o.SetLightDiffusePower(new double[4]);
                o.SetLightSpecularPower(new double[4]);
                r.SetRenderOption(o);
                r.ClearGeometries();
                using (var lit = new RenderMaterial()) r.AddTrianglemesh("box", box, lit);
                Rgb(Pixel(RenderRgb(r), CU, CV), new double[] { 0.1, 0.2, 0.3 }, "ambient-lit box");
            }
        });

        Run("scene: add, has, remove, clear; geometries are copied", () =>
        {
            using (var r = PinholeRenderer())
            using (var box = UnitBox(BoxColor))
            using (var unlit = Unlit())
            {
                Check(!r.HasGeometry("box"), "empty scene");
                r.AddTrianglemesh("box", box, unlit);
                Check(r.HasGeometry("box"), "added");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.AddTrianglemesh("box", box, unlit), "name taken");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.AddTrianglemesh("", box, unlit), "empty name");
                r.RemoveGeometry("box");
                Check(!r.HasGeometry("box"), "removed");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.RemoveGeometry("box"), "remove twice");
                Rgb(Pixel(RenderRgb(r), CU, CV), White, "removed box");

                r.AddTrianglemesh("a", box, unlit);
                box.PaintUniformColor(new double[] { 1, 0, 0 });
                Rgb(Pixel(RenderRgb(r), CU, CV), BoxColor, "the copy added");
                r.AddTrianglemesh("b", box, null); // NULL material: the defaults
                r.ClearGeometries();
                Check(!r.HasGeometry("a") && !r.HasGeometry("b"), "cleared");
                Check(CountNot(RenderRgb(r), White) == 0, "cleared image is background");
            }
        });

        Run("point cloud, line set and voxel grid on the axis", () =>
        {
            using (var r = PinholeRenderer())
            using (var cloud = Cloud(new double[] { 0, 0, 2.5 }))
            using (var big = Unlit())
            {
                cloud.PaintUniformColor(new double[] { 1, 0, 0 });
                big.PointSize = 9;
                r.AddPointcloud("cloud", cloud, big);
                var rgb = RenderRgb(r);
                Rgb(Pixel(rgb, CU, CV), new double[] { 1, 0, 0 }, "point");
                Rgb(Pixel(rgb, CU + 10, CV), White, "beside the point");
            }
            using (var r = PinholeRenderer())
            using (var line = new LineSet())
            using (var wide = Unlit())
            {
                // A horizontal line through the axis, 5 pixels wide.
                line.SetArray(Library.LINESET_POINTS, new double[] { -1, 0, 2.5, 1, 0, 2.5 });
                line.SetIndexArray(Library.LINESET_LINES, new[] { 0, 1 });
                line.PaintUniformColor(new double[] { 0, 1, 0 });
                wide.LineWidth = 5;
                r.AddLineset("line", line, wide);
                var rgb = RenderRgb(r);
                Rgb(Pixel(rgb, CU, CV), new double[] { 0, 1, 0 }, "line");
                Rgb(Pixel(rgb, CU + 30, CV), new double[] { 0, 1, 0 }, "line, 30 pixels along");
                Rgb(Pixel(rgb, CU, CV + 10), White, "below the line");
            }
            using (var r = PinholeRenderer())
            using (var centre = Cloud(new double[] { 0, 0, 3 }))
            using (var unlit = Unlit())
            {
                // One voxel of edge 1 around (0, 0, 3): the unit box again.
                centre.PaintUniformColor(new double[] { 0, 0, 1 });
                using (var grid = VoxelGrid.CreateFromPointCloud(centre, 1.0)) r.AddVoxelgrid("grid", grid, unlit);
                var rgb = RenderRgb(r);
                Rgb(Pixel(rgb, CU, CV), new double[] { 0, 0, 1 }, "voxel");
                Near(CountNot(rgb, White), 1600, 0.02 * 1600, "voxel silhouette");
                Near(DepthAt(r, true, CU, CV), 2.5, 1e-3, "voxel depth");
            }
        });

        Run("field-of-view and lookat cameras look at the box", () =>
        {
            using (var r = OffscreenRenderer.Create(RW, RH, Library.RENDER_BACKEND_AUTO))
            using (var box = UnitBox(BoxColor))
            using (var unlit = Unlit())
            {
                r.AddTrianglemesh("box", box, unlit);
                // From the origin towards +z with image-down = world +y: the pinhole camera, as a field of view.
                double fov = 2 * Math.Atan(60.0 / 100.0) * 180 / Math.PI; // fy = (H / 2) / tan(fov / 2) = 100
                r.SetupCameraFov(fov, new double[] { 0, 0, 3 }, new double[] { 0, 0, 0 }, new double[] { 0, -1, 0 });
                using (var cam = r.GetCamera())
                {
                    Near(cam.Intrinsic().Fx, 100, 1e-6, "fx");
                    Near(cam.Intrinsic().Fy, 100, 1e-6, "fy");
                    AllNear(cam.Extrinsic(), Identity4, 1e-9, "fov extrinsic");
                }
                Near(DepthAt(r, true, CU, CV), 2.5, 1e-3, "fov depth");

                // Open3D's view, looking at a point off the box's centre from -z (zoom 2 keeps the box inside the
                // image): that point projects on the optical axis, in front of the camera.
                var at = new double[] { 0.2, 0.1, 3 };
                r.SetupCameraLookat(at, new double[] { 0, 0, -1 }, new double[] { 0, -1, 0 }, 2.0);
                using (var cam = r.GetCamera())
                {
                    var p = ApplyTransform(cam.Extrinsic(), at);
                    Near(p[0], 0, 1e-9, "lookat x");
                    Near(p[1], 0, 1e-9, "lookat y");
                    Check(p[2] > 1, "lookat in front: " + p[2]);
                    var rgb = RenderRgb(r);
                    Rgb(Pixel(rgb, RW / 2, RH / 2), BoxColor, "lookat centre");
                    Corners(rgb, White);

                    // SetupCamera(GetCamera()) reproduces the image (the box is off-centre, so a flip would show).
                    using (var again = OffscreenRenderer.Create(RW, RH, Library.RENDER_BACKEND_AUTO))
                    {
                        again.AddTrianglemesh("box", box, unlit);
                        again.SetupCamera(cam.Intrinsic(), cam.Extrinsic());
                        var other = RenderRgb(again);
                        int differ = 0;
                        for (int i = 0; i < rgb.Length; i += 3)
                            if (rgb[i] != other[i] || rgb[i + 1] != other[i + 1] || rgb[i + 2] != other[i + 2]) differ++;
                        Check(differ <= 20, differ + " pixels differ");
                    }
                }
            }
        });

        Run("render to PNG writes the image", () =>
        {
            string path = Path.Combine(Path.GetTempPath(), "o3d_cs_render_" + Guid.NewGuid().ToString("N") + ".png");
            using (var r = PinholeRenderer())
            using (var box = UnitBox(BoxColor))
            using (var unlit = Unlit())
            {
                r.AddTrianglemesh("box", box, unlit);
                try
                {
                    r.RenderToPng(path);
                    using (var png = Library.IoReadImage(path, null))
                        Check(png.GetArray(Library.IMAGE_DATA).SequenceEqual(RenderRgb(r)), "PNG pixels equal the rendered image");
                }
                finally { File.Delete(path); }
                ThrowsStatus(Library.ERROR_IO, () => r.RenderToPng("/nonexistent/dir/box.png"), "unwritable path");
            }
        });

        Run("renderer: bad arguments throw", () =>
        {
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => OffscreenRenderer.Create(0, 10, Library.RENDER_BACKEND_AUTO), "zero width");
            using (var r = OffscreenRenderer.Create(RW, RH, Library.RENDER_BACKEND_AUTO))
            {
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.SetupCamera(Intrinsic(RW + 1, RH, 100, 100, 80, 60), Identity4), "intrinsic size");
                var scaled = (double[])Identity4.Clone();
                scaled[0] = 2;
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.SetupCamera(RenderCamera(), scaled), "not rigid");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.SetupCamera(RenderCamera(), new double[12]), "extrinsic length");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.SetupCameraLookat(new double[3], new double[] { 0, 0, 1 }, new double[] { 0, 0, 1 }, 0.7), "parallel up");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.SetupCameraLookat(new double[3], new double[] { 0, 0, 1 }, new double[] { 0, 1, 0 }, 5), "zoom");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.SetupCameraFov(0, new double[] { 0, 0, 1 }, new double[3], new double[] { 0, 1, 0 }), "fov 0");
                using (var o = new RenderOption { PointSize = 100 })
                    ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.SetRenderOption(o), "point size out of range");
            }
        });
    }
}
