// A C# program built with Mono's mcs against the installed O3d.dll; the native plugin files sit beside it.
using System;
using O3d;

static class Program
{
    static int Main()
    {
        var grid = new double[3000];  // a 10 x 10 x 10 grid with spacing 1
        for (int i = 0; i < 1000; ++i)
        {
            grid[3 * i] = i % 10;
            grid[3 * i + 1] = (i / 10) % 10;
            grid[3 * i + 2] = i / 100;
        }
        using (var cloud = new PointCloud(grid))
        using (var down = cloud.VoxelDownSample(2.0))
        {
            Console.WriteLine("o3d (C#): {0} points -> {1} after voxel_down_sample(2)", cloud.Size(), down.Size());
            try
            {
                cloud.VoxelDownSample(-1.0).Dispose();  // bad input is an exception, not a crash
                return 1;
            }
            catch (O3dException e)
            {
                Console.WriteLine("error as expected: {0}", e.Message);
            }
            // As Open3D, voxels start half a voxel below the minimum: 0 | 1 2 | ... | 9 gives 6 per axis.
            return down.Size() == 216 ? 0 : 1;
        }
    }
}
