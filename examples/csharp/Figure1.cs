// SPDX-License-Identifier: MIT
// Figure 1 in C#: read a cloud, voxel-down-sample it (0.05), estimate normals (hybrid 0.1 / 30), write it.
//
// Build and run (from the build dir of bindings/swig, e.g. build-swig/bindings/swig, which holds O3d.dll
// and libo3d_csharp.so; CMake builds it as Figure1.exe and ctest runs it as `csharp_figure1`):
//   mcs -target:exe -out:Figure1.exe -r:O3d.dll ../../../examples/csharp/Figure1.cs
//   mono Figure1.exe ../../../../shared/data/open3d/Feature/cloud_bin_0.pcd /tmp/down.ply
using System;
using O3d;

static class Figure1
{
    static int Main(string[] args)
    {
        if (args.Length != 2)
        {
            Console.Error.WriteLine("usage: mono Figure1.exe <input cloud> <output cloud>");
            return 2;
        }
        try
        {
            using (var pcd = Library.IoReadPointCloud(args[0], null, null))
            using (var down = pcd.VoxelDownSample(0.05))
            using (var hybrid = new SearchParam { Kind = Library.SEARCH_HYBRID, Radius = 0.1, Knn = 30 })
            {
                down.EstimateNormals(hybrid, 0);
                Library.IoWritePointCloud(args[1], down, null, null);
                Console.WriteLine("read {0} points from {1}", pcd.Size(), args[0]);
                Console.WriteLine("voxel_down_sample(0.05) -> {0} points", down.Size());
                Console.WriteLine("estimate_normals(hybrid radius 0.1, max_nn 30) -> has normals: {0}",
                                  down.HasArray(Library.POINTCLOUD_NORMALS));
                Console.WriteLine("wrote {0}", args[1]);
            }
            return 0;
        }
        catch (O3dException e)
        {
            Console.Error.WriteLine("o3d error ({0}): {1}", e.Status, e.Message);
            return 1;
        }
    }
}
