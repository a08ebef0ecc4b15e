// SPDX-License-Identifier: MIT
// SelectionPolygonVolume and the editing viewer's crop from C#, the scenarios of tests/capi/test_selection.c:
// a unit square across z crops a 30 x 30 grid to its 100 inner points, Open3D's crop of its fragment keeps
// 29873 points (recorded from the open3d 0.20 wheel), and K / drag / C crops the viewer's cloud.
using System;
using O3d;

static partial class Test
{
    // 30 x 30 points of step 0.1 from -0.95 at height z: exactly 100 inside [0, 1]^2, none on its edges.
    static PointCloud Grid(double z)
    {
        var p = new double[900 * 3];
        for (int i = 0; i < 30; i++)
            for (int j = 0; j < 30; j++)
            {
                int k = 3 * (30 * i + j);
                p[k] = -0.95 + 0.1 * i;
                p[k + 1] = -0.95 + 0.1 * j;
                p[k + 2] = z;
            }
        return Cloud(p);
    }

    static void SelectionTests()
    {
        Run("selection: a unit square crops the grid", () =>
        {
            using (var v = new SelectionPolygonVolume())
            using (var inside = Grid(0.5))
            using (var above = Grid(1.5))
            {
                v.SetBoundingPolygon(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 });
                v.SetOrthogonalAxis(Library.AXIS_Z);
                v.SetAxisMin(0);
                v.SetAxisMax(1);
                Check(v.GetOrthogonalAxis() == Library.AXIS_Z, "axis");
                var corners = v.GetBoundingPolygon();
                Check(corners.Length == 12 && corners[3] == 1 && corners[7] == 1 && corners[10] == 1, "the corners back");
                using (var kept = v.CropPointCloud(inside))
                    Check(kept.GetArray(Library.POINTCLOUD_POINTS).Length == 300, "100 points inside");
                using (var none = v.CropPointCloud(above))
                    Check(none.GetArray(Library.POINTCLOUD_POINTS).Length == 0, "none above the range");
                var indices = v.CropInPolygon(inside);
                Check(indices.Length == 100 && indices[0] == 10 * 30 + 10, "indices");
                v.SetAxisMin(2);
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => v.CropPointCloud(inside), "axis_min > axis_max");
            }
        });
        Run("selection: Open3D's crop of its fragment", () =>
        {
            using (var v = SelectionPolygonVolume.ReadJson(DataFile("open3d/Crop/cropped.json")))
            using (var pc = Library.IoReadPointCloud(DataFile("open3d/fragment.pcd"), null, null))
            using (var chair = v.CropPointCloud(pc))
                Check(chair.GetArray(Library.POINTCLOUD_POINTS).Length == 29873 * 3, "29873 points, as Open3D");
        });
        Run("selection: the editing viewer crops a dragged rectangle", () =>
        {
            using (var v = Visualizer.Create(1))
            using (var pc = Grid(0))
            {
                v.CreateWindow("crop", 160, 120, -1, -1, 0);
                v.AddPointcloud("grid", pc, 1);
                Check(v.GetCroppedPointcloud() == null, "nothing cropped yet");
                v.SendKey('K', Library.KEY_ACTION_PRESS, 0);
                Check(v.IsSelecting(), "selecting");
                v.SendMouseMove(50, 40);
                v.SendMouseButton(Library.MOUSE_BUTTON_LEFT, Library.KEY_ACTION_PRESS, 0);
                v.SendMouseMove(110, 80);
                v.SendMouseButton(Library.MOUSE_BUTTON_LEFT, Library.KEY_ACTION_RELEASE, 0);
                v.SendKey('C', Library.KEY_ACTION_PRESS, 0);
                Check(!v.IsSelecting(), "left selecting");
                using (var cropped = v.GetCroppedPointcloud())
                {
                    int n = cropped.GetArray(Library.POINTCLOUD_POINTS).Length / 3;
                    Check(n > 20 && n < 900, "kept " + n);
                }
            }
        });
    }
}
