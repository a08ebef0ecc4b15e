// SPDX-License-Identifier: MIT
// Ported tests (2/2): meshes, images, cameras, RGB-D, shapes, features and the registration pipeline.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using O3d;

static partial class Test
{
    static Image Floats(int w, int h, float[] px) { return Image.FromArray(w, h, 1, px); }
    static double Det3(double[] m, int o)
    {
        return m[o] * (m[o + 4] * m[o + 8] - m[o + 5] * m[o + 7]) - m[o + 1] * (m[o + 3] * m[o + 8] - m[o + 5] * m[o + 6]) +
               m[o + 2] * (m[o + 3] * m[o + 7] - m[o + 4] * m[o + 6]);
    }

    static void MeshImageTests()
    {
        Run("image: CreatePyramid halves each level and keeps a constant", () =>
        {
            using (var img = Floats(8, 4, Enumerable.Repeat(0.5f, 32).ToArray()))
            {
                Image[] levels = img.CreatePyramid(3);
                Check(levels.Length == 3 && levels[1].Width() == 4 && levels[2].Width() == 2 && levels[2].Height() == 1, "sizes");
                foreach (var level in levels) { foreach (float v in level.ToFloatArray()) Check(v == 0.5f, "constant kept"); level.Dispose(); }
            }
            using (var ramp = Floats(4, 2, new float[] { 0, 1, 2, 3, 0, 1, 2, 3 }))
            {
                Image[] plain = ramp.CreatePyramid(2, false);
                float[] half = plain[1].ToFloatArray();
                Check(half.Length == 2 && half[0] == 0.5f && half[1] == 2.5f, "2x2 means");
                foreach (var level in plain) level.Dispose();
            }
        });

        Run("mesh: create_mobius through the generated classes only", () =>
        {
            using (var opts = new MobiusOptions())
            {
                Check(opts.LengthSplit == 70 && opts.Twists == 1, "defaults from o3d_mobius_options_init");
                for (int twists = 1; twists <= 2; twists++)
                {
                    opts.Twists = twists;
                    using (var m = TriangleMesh.CreateMobius(opts))
                        Check(m.NumVertices() == 70 * 15 && m.NumTriangles() == 2 * 70 * 14 &&
                              m.EulerPoincareCharacteristic() == 0 && m.IsOrientable() == (twists % 2 == 0), "mobius " + twists);
                }
                opts.Twists = -1;
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => TriangleMesh.CreateMobius(opts), "negative twists");
            }
        });

        Run("mesh: primitives (counts recorded from Open3D 0.20)", () =>
        {
            Action<TriangleMesh, long, long, string> counts = (m, nv, nt, what) =>
            {
                using (m) Check(m.NumVertices() == nv && m.NumTriangles() == nt, what + ": " + m.NumVertices() + "/" + m.NumTriangles());
            };
            using (var m = TriangleMesh.CreateSphere(1, 20))
            {
                Check(m.NumVertices() == 762 && m.NumTriangles() == 1520 && m.IsWatertight(), "sphere");
                var v = m.Vertices;
                for (int i = 0; i < v.Length / 3; i++) Near(Math.Sqrt(v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2]), 1, 1e-12, "on the unit sphere");
            }
            counts(TriangleMesh.CreateCylinder(1, 2, 20, 4), 102, 200, "cylinder");
            counts(TriangleMesh.CreateCone(1, 2, 20, 1), 22, 40, "cone");
            using (var m = TriangleMesh.CreateTorus(1, 0.5, 30, 20)) Check(m.NumVertices() == 600 && m.EulerPoincareCharacteristic() == 0, "torus");
            counts(TriangleMesh.CreateArrow(1, 1.5, 5, 4, 20, 4, 1), 124, 240, "arrow");
            using (var m = TriangleMesh.CreateCoordinateFrame(1, new double[] { 0, 0, 0 }))
                Check(m.NumVertices() == 1134 && m.NumTriangles() == 2240 && m.HasArray(Library.MESH_VERTEX_COLORS), "frame");
            using (var m = TriangleMesh.CreateTetrahedron(1))
            {
                double a = Math.Sqrt(8.0 / 3);
                Near(m.GetSurfaceArea(), Math.Sqrt(3) * a * a, 1e-9, "tetrahedron area");
                Near(m.GetVolume(), a * a * a / (6 * Math.Sqrt(2)), 1e-9, "tetrahedron volume");
            }
            using (var m = TriangleMesh.CreateOctahedron(1)) Near(m.GetVolume(), 4.0 / 3, 1e-9, "octahedron volume");
            counts(TriangleMesh.CreateIcosahedron(1), 12, 20, "icosahedron");
            using (var opts = new MobiusOptions())
            using (var m = TriangleMesh.CreateMobius(opts)) Check(m.NumTriangles() > 0, "mobius");
        });

        Run("mesh: arrays, views, normals, append, clusters", () =>
        {
            var verts = new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
            using (var m = new TriangleMesh(verts, new[] { 0, 1, 2 }))
            {
                AllNear(m.Vertices, verts, 0, "vertices round trip");
                Check(m.Triangles.SequenceEqual(new[] { 0, 1, 2 }), "triangles round trip");
                m.ComputeVertexNormals(1);
                AllNear(m.GetArray(Library.MESH_VERTEX_NORMALS), new double[] { 0, 0, 1, 0, 0, 1, 0, 0, 1 }, 1e-12, "vertex normals +z");
                m.ComputeTriangleNormals(0);
                AllNear(m.GetArray(Library.MESH_TRIANGLE_NORMALS), new double[] { 0, 0, 1 }, 1e-12, "unnormalized normal");
                m.SetArray(Library.MESH_TRIANGLE_UVS, new double[] { 0, 0, 1, 0, 0, 1 });
                Check(m.GetArray(Library.MESH_TRIANGLE_UVS).Length == 6, "uvs");
                m.SetIndexArray(Library.MESH_TRIANGLE_MATERIAL_IDS, new[] { 0 });
                Check(m.HasArray(Library.MESH_TRIANGLE_MATERIAL_IDS), "material ids");
                var view = m.ArrayView(Library.MESH_VERTICES);
                Check(view.Rows == 3 && Copy<double>(view, 9).SequenceEqual(verts), "vertex view");
                var iview = m.IndexArrayView(Library.MESH_TRIANGLES);
                Check(iview.Rows == 1 && iview.Bytes == 12 && Copy<int>(iview, 3).SequenceEqual(new[] { 0, 1, 2 }), "triangle view");
                Marshal.Copy(new double[] { 2 }, 0, m.ArrayMutableView(Library.MESH_VERTICES).Data + 3 * sizeof(double), 1);
                Near(m.Vertices[3], 2, 0, "write through the mutable view");
                Check(m.IndexArrayMutableView(Library.MESH_TRIANGLES).Rows == 1, "mutable index view");
                Near(m.GetSurfaceArea(), 1, 1e-12, "area after moving a vertex");
                using (var copy = m.Clone()) { copy.Translate(new double[] { 0, 0, 1 }, 1); m.Append(copy); }
                Check(m.Triangles.SequenceEqual(new[] { 0, 1, 2, 3, 4, 5 }), "appended triangles re-indexed");
                using (var cl = m.ClusterConnectedTriangles())
                {
                    Check(cl.TriangleClusters().SequenceEqual(new[] { 0, 1 }) && cl.ClusterNTriangles().SequenceEqual(new[] { 1, 1 }), "two clusters");
                    AllNear(cl.ClusterArea(), new double[] { 1, 1 }, 1e-12, "cluster areas");
                }
                m.Clear();
                Check(m.NumVertices() == 0 && m.NumTriangles() == 0, "cleared");
            }
        });

        Run("mesh: clean-up, transforms, processing", () =>
        {
            using (var m = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 }, new[] { 0, 1, 2, 3, 4, 5, 0, 0, 1 }))
            {
                m.RemoveDegenerateTriangles();
                Check(m.NumTriangles() == 2, "degenerate removed");
                m.RemoveDuplicatedVertices();
                Check(m.NumVertices() == 4, "duplicates merged");
                m.RemoveDuplicatedTriangles(); m.RemoveUnreferencedVertices(); m.RemoveNonManifoldEdges(); m.MergeCloseVertices(1e-9);
                Check(m.NumVertices() == 4 && m.NumTriangles() == 2 && m.EulerPoincareCharacteristic() == 1, "a disc");
                Check(m.IsEdgeManifold(1) && !m.IsEdgeManifold(0) && !m.IsWatertight(), "open surface");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => m.GetVolume(), "volume of an open mesh");
            }
            using (var box = TriangleMesh.CreateBox(1, 1, 1))
            {
                box.Translate(new double[] { 1, 2, 3 }, 1);
                AllNear(box.GetMinBound(), new double[] { 1, 2, 3 }, 1e-12, "translated");
                box.Translate(new double[] { 0, 0, 0 }, 0);
                AllNear(box.GetCenter(), new double[] { 0, 0, 0 }, 1e-12, "centered");
                box.Scale(2, new double[] { 0, 0, 0 });
                Near(box.GetSurfaceArea(), 24, 1e-9, "scaled area");
                box.Rotate(new double[] { 0, -1, 0, 1, 0, 0, 0, 0, 1 }, box.GetCenter());
                Near(box.GetVolume(), 8, 1e-9, "rotated volume");
                box.Transform(new double[] { 1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1 });
                using (var bb = box.GetAxisAlignedBoundingBox())
                { AllNear(bb.Min(), new double[] { 0, 0, 0 }, 1e-9, "aabb min"); AllNear(bb.Max(), new double[] { 2, 2, 2 }, 1e-9, "aabb max"); }
                box.PaintUniformColor(new double[] { 0.25, 0.5, 1 });
                AllNear(box.GetArray(Library.MESH_VERTEX_COLORS).Take(3).ToArray(), new double[] { 0.25, 0.5, 1 }, 0, "painted");
            }
            using (var box = TriangleMesh.CreateBox(1, 1, 1))
            {
                using (var sub = box.SubdivideMidpoint(1)) Check(sub.NumVertices() == 26 && sub.NumTriangles() == 48, "midpoint counts");
                using (var loop = box.SubdivideLoop(1)) Check(loop.NumTriangles() == 48 && loop.GetSurfaceArea() < 6, "loop");
                using (var crop = box.CropAabb(new double[] { -0.1, -0.1, -0.1 }, new double[] { 1.1, 1.1, 0.5 }))
                    Check(crop.NumTriangles() == 2 && crop.NumVertices() == 4, "crop keeps the z = 0 face");
                using (var a = box.SamplePointsUniformly(500, 0, 7))
                using (var b = box.SamplePointsUniformly(500, 0, 7)) Check(a.Size() == 500 && a.Points.SequenceEqual(b.Points), "same seed, same samples");
                using (var pd = box.SamplePointsPoissonDisk(100, 5, 0, 3)) Check(pd.Size() == 100, "poisson disk count");
                using (var s = box.FilterSmoothSimple(1, Library.FILTER_SCOPE_ALL)) Check(s.NumTriangles() == 12, "smooth simple");
                using (var s = box.FilterSmoothLaplacian(2, 0.5, Library.FILTER_SCOPE_ALL)) Check(s.NumVertices() == 8, "laplacian");
                using (var s = box.FilterSmoothTaubin(2, 0.5, -0.53, Library.FILTER_SCOPE_ALL)) Check(s.NumVertices() == 8, "taubin");
                using (var s = box.SimplifyVertexClustering(10, Library.SIMPLIFICATION_AVERAGE)) Check(s.NumTriangles() < 12, "one voxel");
            }
            using (var sphere = TriangleMesh.CreateSphere(1, 20))
            using (var dec = sphere.SimplifyQuadricDecimation(100, double.PositiveInfinity, 1))
                Check(dec.NumTriangles() <= 100 && dec.NumTriangles() > 0, "decimated");
        });

        Run("mesh: written then read back equal (PLY/OFF in memory, PLY/OBJ files)", () =>
        {
            using (var box = TriangleMesh.CreateBox(1, 1, 1))
            {
                var colors = Enumerable.Range(0, 24).Select(i => (i * 10 % 256) / 255.0).ToArray();
                box.SetArray(Library.MESH_VERTEX_COLORS, colors);
                foreach (var fmt in new[] { "ply", "off" })
                    using (var buf = Library.IoWriteTriangleMeshToMemory(box, fmt, null))
                    using (var back = Library.IoReadTriangleMeshFromMemory(buf.GetData(), fmt, null))
                    {
                        AllNear(back.Vertices, box.Vertices, 1e-6, fmt + " vertices");
                        Check(back.Triangles.SequenceEqual(box.Triangles), fmt + " triangles");
                        if (fmt == "ply") AllNear(back.GetArray(Library.MESH_VERTEX_COLORS), colors, 1e-9, "ply colors");
                    }
                string dir = TempDir();
                try
                {
                    string ply = Path.Combine(dir, "box.ply");
                    using (var w = new MeshWriteOptions { WriteAscii = 1, WriteVertexColors = 0 })
                    using (var r = new MeshReadOptions { EnablePostProcessing = 0 })
                    {
                        Library.IoWriteTriangleMesh(ply, box, null, w);
                        Check(File.ReadAllText(ply).Contains("format ascii"), "ascii ply");
                        using (var back = Library.IoReadTriangleMesh(ply, null, r))
                            Check(back.NumVertices() == 8 && back.NumTriangles() == 12 && !back.HasArray(Library.MESH_VERTEX_COLORS), "ply file, no colors");
                    }
                    string obj = Path.Combine(dir, "box.obj");
                    Library.IoWriteTriangleMesh(obj, box, null, null);
                    using (var back = Library.IoReadTriangleMesh(obj, null, null)) Near(back.GetSurfaceArea(), 6, 1e-9, "obj area");
                }
                finally { Directory.Delete(dir, true); }
            }
        });

        Run("image: PNG round trip in memory and on disk, views, typed pixels", () =>
        {
            var px = Enumerable.Range(0, 60).Select(i => (byte)(i * 7)).ToArray();
            using (var img = Image.CreateFromData(5, 4, 3, 1, px))
            {
                Check(img.Width() == 5 && img.Height() == 4 && img.NumChannels() == 3 && img.BytesPerChannel() == 1, "shape");
                using (var png = Library.IoWriteImageToMemory(img, "png", -1))
                {
                    var bytes = png.GetData();
                    Check(bytes[0] == 0x89 && bytes[1] == (byte)'P', "PNG signature");
                    using (var back = Library.IoReadImageFromMemory(bytes, "png")) Check(back.GetArray(Library.IMAGE_DATA).SequenceEqual(px), "png pixels equal");
                }
                string dir = TempDir();
                try
                {
                    foreach (var ext in new[] { "png", "ppm" })
                    {
                        string path = Path.Combine(dir, "img." + ext);
                        Library.IoWriteImage(path, img, null, -1);
                        using (var back = Library.IoReadImage(path, null)) Check(back.GetArray(Library.IMAGE_DATA).SequenceEqual(px), ext + " file pixels equal");
                    }
                }
                finally { Directory.Delete(dir, true); }
                var v = img.ArrayView(Library.IMAGE_DATA);
                Check(v.Bytes == px.Length && Copy<byte>(v, px.Length).SequenceEqual(px), "data view");
                Marshal.WriteByte(img.ArrayMutableView(Library.IMAGE_DATA).Data, 0, 200);
                Check(img.GetArray(Library.IMAGE_DATA)[0] == 200, "write through the mutable view");
            }
            var depth = new ushort[] { 0, 1, 1000, 65535, 300, 42 };
            using (var d16 = Image.FromArray(3, 2, 1, depth))
            using (var buf = Library.IoWriteImageToMemory(d16, "png", -1))
            using (var back = Library.IoReadImageFromMemory(buf.GetData(), "png"))
                Check(back.BytesPerChannel() == 2 && back.ToUInt16Array().SequenceEqual(depth), "16-bit png round trip");
            using (var gray = Image.CreateFromData(8, 8, 1, 1, Enumerable.Repeat((byte)128, 64).ToArray()))
            using (var buf = Library.IoWriteImageToMemory(gray, "jpg", 95))
            using (var back = Library.IoReadImageFromMemory(buf.GetData(), "jpg"))
                foreach (var b in back.GetArray(Library.IMAGE_DATA)) Check(Math.Abs(b - 128) <= 2, "jpeg of a flat image stays flat");
        });

        Run("image: flips, float conversion, depth conversion, filters", () =>
        {
            using (var row = Image.CreateFromData(3, 1, 1, 1, new byte[] { 1, 2, 3 }))
            using (var flipped = row.FlipHorizontal())
                Check(flipped.GetArray(Library.IMAGE_DATA).SequenceEqual(new byte[] { 3, 2, 1 }), "flip horizontal");
            using (var col = Image.CreateFromData(1, 3, 1, 1, new byte[] { 1, 2, 3 }))
            using (var flipped = col.FlipVertical())
                Check(flipped.GetArray(Library.IMAGE_DATA).SequenceEqual(new byte[] { 3, 2, 1 }), "flip vertical");
            using (var g = Image.CreateFromData(3, 1, 1, 1, new byte[] { 0, 255, 51 }))
            using (var f = g.CreateFloatImage(Library.IMAGE_CONVERT_WEIGHTED))
                AllNear(F2D(f.ToFloatArray()), new[] { 0, 1, 0.2 }, 1e-6, "8-bit / 255");
            using (var rgb = Image.CreateFromData(1, 1, 3, 1, new byte[] { 255, 0, 0 }))
            using (var w = rgb.CreateFloatImage(Library.IMAGE_CONVERT_WEIGHTED))
            using (var e = rgb.CreateFloatImage(Library.IMAGE_CONVERT_EQUAL))
            { Near(w.ToFloatArray()[0], 0.299, 1e-6, "weighted gray"); Near(e.ToFloatArray()[0], 1.0 / 3, 1e-6, "equal gray"); }
            using (var raw = Image.FromArray(3, 1, 1, new ushort[] { 500, 4000, 1500 }))
            using (var m = raw.ConvertDepthToFloat(1000, 3.0))
                AllNear(F2D(m.ToFloatArray()), new[] { 0.5, 0, 1.5 }, 1e-6, "depth in metres, truncated");
            using (var flat = Floats(5, 4, Enumerable.Repeat(0.5f, 20).ToArray()))
            {
                foreach (int t in new[] { Library.IMAGE_FILTER_GAUSSIAN3, Library.IMAGE_FILTER_GAUSSIAN5, Library.IMAGE_FILTER_GAUSSIAN7 })
                    using (var f = flat.Filter(t)) foreach (var x in f.ToFloatArray()) Near(x, 0.5, 1e-6, "gaussian of a flat image");
                foreach (int t in new[] { Library.IMAGE_FILTER_SOBEL3_DX, Library.IMAGE_FILTER_SOBEL3_DY })
                    using (var f = flat.Filter(t)) foreach (var x in f.ToFloatArray()) Near(x, 0, 1e-6, "sobel of a flat image");
            }
            using (var img = Floats(4, 2, new float[] { 1, 3, 5, 7, 1, 3, 5, 7 }))
            using (var half = img.Downsample())
                AllNear(F2D(half.ToFloatArray()), new double[] { 2, 6 }, 1e-6, "2x2 means");
        });

        Run("image, mesh: errors for bad input and misuse, Dispose", () =>
        {
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => Image.Create(0, 0, 1, 1), "empty image");
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => Image.Create(2, 2, 2, 1), "2 channels");
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => Image.CreateFromData(2, 2, 1, 1, new byte[3]), "data size mismatch");
            ThrowsStatus(Library.ERROR_PARSE, () => Library.IoReadImageFromMemory(new byte[] { 0x89, (byte)'P', (byte)'N', (byte)'G', 1, 2, 3 }, "png"), "truncated png");
            ThrowsStatus(Library.ERROR_IO, () => Library.IoReadImage("/nonexistent/dir/none.png", null), "missing image");
            using (var img = Image.Create(2, 2, 1, 1)) ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => img.Filter(Library.IMAGE_FILTER_GAUSSIAN3), "filter needs float");
            using (var f = Floats(2, 2, new float[4])) Throws<O3dException>(() => Library.IoWriteImageToMemory(f, "png", -1), "float images are not written");
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => TriangleMesh.CreateBox(-1, 1, 1), "negative box");
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => TriangleMesh.CreateSphere(1, 0), "sphere resolution 0");
            using (var m = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new[] { 0, 1, 5 }))
            {
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => m.ComputeVertexNormals(1), "triangle index out of range");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => m.GetSurfaceArea(), "area with a bad index");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => m.MergeCloseVertices(double.NaN), "NaN eps");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => m.GetTexture(0), "no texture 0");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => m.Vertices = new double[] { 1, 2 }, "length not a multiple of 3");
            }
            ThrowsStatus(Library.ERROR_IO, () => Library.IoReadTriangleMesh("/nonexistent/dir/none.ply", null, null), "missing mesh file");
            using (var box = TriangleMesh.CreateBox(1, 1, 1))
                ThrowsStatus(Library.ERROR_UNSUPPORTED, () => Library.IoWriteTriangleMeshToMemory(box, "nope", null), "unknown mesh format");
            var mesh = TriangleMesh.CreateBox(1, 1, 1);
            var tex = Image.Create(1, 1, 3, 1);
            mesh.AddTexture(tex);
            tex.Dispose();
            Check(mesh.TextureCount() == 1, "texture copied in");
            using (var t = mesh.GetTexture(0)) Check(t.Width() == 1 && t.NumChannels() == 3, "texture back");
            mesh.ClearTextures();
            Check(mesh.TextureCount() == 0, "textures cleared");
            mesh.Dispose(); mesh.Dispose();
            Throws<ObjectDisposedException>(() => mesh.NumVertices(), "mesh after Dispose");
            for (int i = 0; i < 50; i++) { Image.Create(4, 4, 1, 1); TriangleMesh.CreateBox(1, 1, 1); }
            GC.Collect(); GC.WaitForPendingFinalizers();
        });

        ShapeTests();
    }

    static void ShapeTests()
    {
        Run("convex hull of a cube, hidden point removal", () =>
        {
            var p = new List<double>();
            for (int c = 0; c < 8; c++) { p.Add(c & 1); p.Add((c >> 1) & 1); p.Add((c >> 2) & 1); }
            p.AddRange(new double[] { 0.5, 0.5, 0.5, 0.2, 0.3, 0.4, 0.9, 0.1, 0.5 });
            using (var pc = new PointCloud(p.ToArray()))
            using (var hull = pc.ComputeConvexHull(0))
            using (var mesh = hull.Mesh())
            {
                Check(mesh.NumVertices() == 8 && mesh.NumTriangles() == 12 && mesh.IsWatertight(), "8 vertices, 12 triangles");
                Near(mesh.GetVolume(), 1, 1e-12, "volume");
                var idx = hull.PointIndices();
                Check(idx.Length == 8 && idx.All(k => k >= 0 && k < 8) && idx.Distinct().Count() == 8, "corners");
            }
            using (var three = new PointCloud(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }))
                Throws<O3dException>(() => three.ComputeConvexHull(1), "3 points");
            using (var pc = new PointCloud(RandomPoints(200, 3, 2, 2, 2).Select(x => x - 1).ToArray()))
            using (var res = pc.HiddenPointRemoval(new double[] { 0, 0, 5 }, 500))
            {
                Check(res.PointIndices().Length > 0 && res.PointIndices().All(i => i >= 0 && i < 200), "visible indices");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.HiddenPointRemoval(new double[] { 0, 0, 5 }, -1), "negative radius");
            }
        });

        Run("oriented bounding box, crop by it", () =>
        {
            using (var aabb = OrientedBoundingBox.CreateFromAxisAlignedBoundingBox(new double[] { 0, 0, 0 }, new double[] { 1, 2, 3 }))
            {
                AllNear(aabb.GetCenter(), new[] { 0.5, 1, 1.5 }, 1e-15, "center");
                AllNear(aabb.GetExtent(), new double[] { 1, 2, 3 }, 1e-15, "extent");
                AllNear(aabb.GetBoxPoints(), new double[] { 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3, 1, 2, 3, 0, 2, 3, 1, 0, 3, 1, 2, 0 }, 1e-12, "box points");
                Check(aabb.GetPointIndicesWithin(new double[] { 0.5, 0.5, 0.5, 2, 0, 0, 1, 2, 3, -0.1, 1, 1 }).SequenceEqual(new[] { 0, 2 }), "indices within");
                using (var pc = new PointCloud(new double[] { 0.5, 0.5, 0.5, 2, 0, 0 }))
                using (var inside = pc.CropObb(aabb, 0)) AllNear(inside.Points, new[] { 0.5, 0.5, 0.5 }, 0, "crop");
                using (var ls = LineSet.CreateFromOrientedBoundingBox(aabb)) AllNear(ls.GetArray(Library.LINESET_POINTS), aabb.GetBoxPoints(), 1e-12, "line set of the box");
            }
            using (var mesh = TriangleMesh.CreateBox(2, 3, 4))
            using (var obb = mesh.GetOrientedBoundingBox(0))
            {
                var e = obb.GetExtent(); Array.Sort(e);
                AllNear(e, new double[] { 2, 3, 4 }, 1e-9, "PCA extents");
            }
            // PCA box of a 2 x 3 x 4 block (corners + 2 inner points): volume 24, extents {2, 3, 4}, orthonormal R.
            var pts = new List<double>();
            for (int c = 0; c < 8; c++) { pts.Add(2 * (c & 1)); pts.Add(3 * ((c >> 1) & 1)); pts.Add(4 * ((c >> 2) & 1)); }
            pts.AddRange(new double[] { 1, 1.5, 2, 0.5, 0.5, 0.5 });
            using (var obb = OrientedBoundingBox.CreateFromPoints(pts.ToArray(), 0))
            {
                Near(obb.GetExtent().Aggregate(1.0, (a, b) => a * b), 24, 1e-9, "PCA volume");
                var e = obb.GetExtent(); Array.Sort(e);
                AllNear(e, new double[] { 2, 3, 4 }, 1e-9, "PCA extents of the block");
                AllNear(obb.GetCenter(), new[] { 1, 1.5, 2 }, 1e-9, "PCA center");
                var R = obb.GetR();
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++)
                        Near(R[i] * R[j] + R[3 + i] * R[3 + j] + R[6 + i] * R[6 + j], i == j ? 1 : 0, 1e-9, "R^T R");
                Func<double[], IEnumerable<string>> rows = a => Enumerable.Range(0, a.Length / 3)
                    .Select(i => string.Join(",", a.Skip(3 * i).Take(3).Select(x => Math.Round(x, 6).ToString("R")))).OrderBy(x => x);
                Check(rows(obb.GetBoxPoints()).SequenceEqual(rows(pts.Take(24).ToArray())), "PCA box corners are the block's");
            }
            Throws<O3dException>(() => OrientedBoundingBox.CreateFromPoints(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, 0), "3 points");
            using (var o = new OrientedBoundingBox()) ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => o.SetR(new double[8]), "R of 8 values");
        });

        Run("line sets", () =>
        {
            using (var ls = LineSet.CreateFromAxisAlignedBoundingBox(new double[] { 0, 0, 0 }, new double[] { 1, 2, 3 }))
            {
                Check(ls.NumPoints() == 8 && ls.NumLines() == 12, "8 points, 12 lines");
                ls.PaintUniformColor(new[] { 1, 0.5, 0 });
                Check(ls.GetArray(Library.LINESET_COLORS).Length == 36, "colors per line");
                var v = ls.IndexArrayView(Library.LINESET_LINES);
                Check(v.Rows == 12 && Copy<int>(v, 24).SequenceEqual(ls.GetIndexArray(Library.LINESET_LINES)), "lines view == copy");
                using (var c = ls.Clone()) { ls.SetIndexArray(Library.LINESET_LINES, new int[0]); Check(c.NumLines() == 12 && ls.NumLines() == 0, "deep clone"); }
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => ls.SetIndexArray(Library.LINESET_LINES, new[] { 0, 1, 2 }), "odd line array");
            }
            using (var box = TriangleMesh.CreateBox(1, 1, 1))
            using (var edges = LineSet.CreateFromTriangleMesh(box)) Check(edges.NumLines() == 18, "box mesh edges");
            using (var a = new PointCloud(new double[] { 0, 0, 0, 1, 0, 0 }))
            using (var b = new PointCloud(new double[] { 0, 1, 0, 1, 1, 0, 2, 1, 0 }))
            {
                using (var corr = LineSet.CreateFromPointCloudCorrespondences(a, b, new[] { 0, 2, 1, 0 }))
                    Check(corr.NumPoints() == 5 && corr.GetIndexArray(Library.LINESET_LINES).SequenceEqual(new[] { 0, 4, 1, 2 }), "lines offset into cloud1");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => LineSet.CreateFromPointCloudCorrespondences(a, b, new[] { 0, 3 }), "pair out of range");
            }
        });

        Run("voxel grids", () =>
        {
            using (var pc = new PointCloud(new double[] { 0, 0, 0, 0.05, 0.05, 0.05, 1, 0, 0, 0, 0, 1 }))
            {
                pc.Colors = new double[] { 1, 0, 0, 0, 0, 1, 0, 1, 0, 1, 1, 1 };
                using (var grid = VoxelGrid.CreateFromPointCloud(pc, 0.5))
                {
                    Near(grid.GetVoxelSize(), 0.5, 0, "voxel size");
                    AllNear(grid.GetOrigin(), new[] { -0.25, -0.25, -0.25 }, 1e-15, "origin");
                    Check(grid.NumVoxels() == 3 && grid.GetIndexArray(Library.VOXELGRID_GRID_INDEX).SequenceEqual(new[] { 0, 0, 0, 0, 0, 2, 2, 0, 0 }), "grid indices");
                    AllNear(grid.GetArray(Library.VOXELGRID_COLORS), new double[] { 0.5, 0, 0.5, 1, 1, 1, 0, 1, 0 }, 1e-12, "mean colors");
                    Check(grid.GetVoxel(new double[] { 1, 0, 0 }).SequenceEqual(new[] { 2, 0, 0 }), "get voxel");
                    Check(grid.CheckIfIncluded(new double[] { 1, 0, 0, 0.5, 0.5, 0.5 }).SequenceEqual(new[] { 1, 0 }), "included");
                }
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => VoxelGrid.CreateFromPointCloud(pc, 0), "voxel size 0");
            }
            using (var box = TriangleMesh.CreateBox(1, 1, 1))
            using (var grid = VoxelGrid.CreateFromTriangleMesh(box, 0.5)) Check(grid.NumVoxels() == 26, "surface voxels");
        });

        Run("octree", () =>
        {
            using (var pc = new PointCloud(new double[] { 0, 0, 0, 1, 1, 1, 0.1, 0.1, 0.1, 0.9, 0.9, 0.9, 0.2, 0.1, 0.1 }))
            using (var tree = Octree.Create(2))
            {
                pc.Colors = new double[] { 0.3, 0, 0, 1, 1, 1, 0.6, 0, 0, 0, 0, 0, 0, 0.9, 0 };
                tree.ConvertFromPointCloud(pc, 0.01);
                using (var root = tree.GetRoot()) { Near(root.Size(), 1.01, 1e-12, "root size"); Check(root.MaxDepth() == 2, "depth"); }
                Check(tree.NumLeafNodes() == 2, "2 leaves");
                using (var leaf = tree.LocateLeafNode(new[] { 0.05, 0.05, 0.05 }))
                using (var info = leaf.Info())
                {
                    Check(leaf.Found() && leaf.Indices().SequenceEqual(new[] { 0, 2, 4 }), "leaf indices");
                    AllNear(leaf.Color(), new[] { 0.3, 0.3, 0 }, 1e-12, "mean color");
                    AllNear(info.GetOrigin(), new double[] { 0, 0, 0 }, 0, "leaf origin");
                    Near(info.Size, 0.2525, 1e-12, "leaf size");
                    Check(info.Depth == 2 && info.ChildIndex == 0, "depth / child");
                }
                using (var leaf = tree.LocateLeafNode(new[] { 0.95, 0.95, 0.95 }))
                using (var info = leaf.Info())
                {
                    Check(leaf.Found() && leaf.Indices().SequenceEqual(new[] { 1, 3 }) && info.ChildIndex == 7, "far leaf");
                    AllNear(info.GetOrigin(), new[] { 0.7575, 0.7575, 0.7575 }, 1e-12, "far leaf origin");
                }
                using (var leaf = tree.LocateLeafNode(new[] { 0.5, 0.5, 0.5 })) Check(!leaf.Found(), "empty cell");
                using (var leaf = tree.LocateLeafNode(new double[] { 5, 5, 5 })) Check(!leaf.Found(), "outside the root");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => tree.LocateLeafNode(new[] { double.NaN, 0, 0 }), "NaN point");
            }
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => Octree.Create(0), "max depth 0");
        });

        Run("covariances", () =>
        {
            using (var pc = new PointCloud(GridWithOutliers().Take(300).ToArray()))
            {
                pc.EstimateCovariances(Knn(10));
                var cov = pc.Covariances;
                Check(cov.Length == 900, "9 per point");
                for (int i = 0; i < 100; i++) { Near(Det3(cov, 9 * i), 0, 1e-15, "det " + i); Near(cov[9 * i + 1], cov[9 * i + 3], 1e-15, "symmetric"); }
                var v = pc.ArrayView(Library.POINTCLOUD_COVARIANCES);
                Check(v.Rows == 100 && Copy<double>(v, 900).SequenceEqual(cov), "view == copy");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.Covariances = new double[10], "not a multiple of 9");
            }
        });

        Run("feature: data, view, select, file round trip", () =>
        {
            var values = Enumerable.Range(0, 12).Select(i => (double)i).ToArray();
            using (var f = Feature.CreateFromData(values, 4, 3))
            {
                Check(f.Dimension() == 4 && f.Num() == 3 && f.GetArray(Library.FEATURE_DATA).SequenceEqual(values), "data");
                Check(Copy<double>(f.ArrayView(Library.FEATURE_DATA), 12).SequenceEqual(values), "view");
                using (var picked = f.SelectByIndex(new long[] { 2, 0 }, 0))
                    Check(picked.GetArray(Library.FEATURE_DATA).SequenceEqual(new double[] { 8, 9, 10, 11, 0, 1, 2, 3 }), "select");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => f.SelectByIndex(new long[] { 5 }, 0), "index out of range");
                string dir = TempDir();
                try
                {
                    string path = Path.Combine(dir, "f.bin");
                    Library.IoWriteFeature(path, f);
                    using (var back = Library.IoReadFeature(path)) Check(back.GetArray(Library.FEATURE_DATA).SequenceEqual(values), "round trip");
                }
                finally { Directory.Delete(dir, true); }
            }
        });

        Run("robust kernel weights", () =>
        {
            Near(RobustKernel.L2Loss().Weight(3), 1, 0, "L2");
            Near(RobustKernel.L1Loss().Weight(-2), 0.5, 1e-15, "L1");
            Near(RobustKernel.HuberLoss(1).Weight(4), 0.25, 1e-15, "Huber");
            Near(RobustKernel.CauchyLoss(2).Weight(2), 0.5, 1e-15, "Cauchy");
            Near(RobustKernel.GMLoss(1).Weight(1), 0.25, 1e-15, "GM");
            Near(RobustKernel.TukeyLoss(1).Weight(0.5), 0.5625, 1e-15, "Tukey");
            using (var opts = new IcpOptions())
            {
                Check(opts.RobustKernel.Kind == Library.KERNEL_L2 && opts.LambdaGeometric == 0.968, "ICP defaults");
                opts.RobustKernel = RobustKernel.TukeyLoss(2);
                Check(opts.Kernel == Library.KERNEL_TUKEY && opts.KernelK == 2, "set kernel");
            }
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => RobustKernel.HuberLoss(-1).Weight(1), "k <= 0");
        });

        Run("pose graph and global optimization (cancel, prune)", () =>
        {
            Func<double, double[]> tx = x => new double[] { 1, 0, 0, x, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
            var info = Enumerable.Range(0, 36).Select(i => i % 7 == 0 ? 1000.0 : 0.0).ToArray();
            using (var g = new PoseGraph())
            {
                for (int i = 0; i < 5; i++) g.AddNode(tx(i));
                g.SetNode(2, tx(2.05));
                Action<int, int, double[], int> edge = (s, t, T, unc) =>
                {
                    using (var e = new PoseGraphEdge { SourceNodeId = s, TargetNodeId = t, Uncertain = unc })
                    { e.SetTransformation(T); e.SetInformation(info); g.AddEdge(e); }
                };
                for (int i = 0; i < 4; i++) edge(i, i + 1, tx(-1), 0);
                edge(0, 3, tx(-3), 1);
                edge(1, 4, tx(-3), 1);
                double c30 = Math.Cos(Math.PI / 6), s30 = Math.Sin(Math.PI / 6);
                edge(0, 4, new double[] { c30, -s30, 0, -1, s30, c30, 0, 2, 0, 0, 1, 0, 0, 0, 0, 1 }, 1);
                using (var cancel = new GlobalOptimizationOptions())
                {
                    cancel.SetProgress(f => false);
                    ThrowsStatus(Library.ERROR_CANCELLED, () => Library.GlobalOptimization(g, cancel), "cancel");
                    AllNear(g.GetNode(2), tx(2.05), 0, "cancel leaves the nodes");
                }
                int calls = 0;
                using (var opts = new GlobalOptimizationOptions())
                {
                    opts.SetProgress(f => { calls++; return true; });
                    Check(opts.Method == Library.GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT && opts.ReferenceNode == -1, "defaults");
                    using (var s = Library.GlobalOptimization(g, opts))
                        Check(s.PrunedEdges == 1 && g.NumEdges() == 6 && s.FinalResidual < s.InitialResidual, "one edge pruned");
                }
                Check(calls > 0, "progress called");
                for (int i = 0; i < 5; i++) AllNear(g.GetNode(i), tx(i), 1e-3, "node " + i);
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => g.GetNode(9), "node index out of range");
                var scaled = tx(0); scaled[0] = 2;
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => g.AddNode(scaled), "not rigid");
            }
        });
    }
}
