// A Java program whose class path holds only o3d's jar: the jar unpacks and loads its own native library.
import org.o3d.Library;
import org.o3d.O3dException;
import org.o3d.PointCloud;

public class Main {
    public static void main(String[] args) {
        double[] grid = new double[3000];  // a 10 x 10 x 10 grid with spacing 1
        for (int i = 0; i < 1000; ++i) {
            grid[3 * i] = i % 10;
            grid[3 * i + 1] = (i / 10) % 10;
            grid[3 * i + 2] = i / 100;
        }
        try (PointCloud cloud = new PointCloud()) {
            cloud.setArray(Library.POINTCLOUD_POINTS, grid);
            try (PointCloud down = cloud.voxelDownSample(2.0)) {
                System.out.printf("o3d (Java): %d points -> %d after voxel_down_sample(2)%n", cloud.size(), down.size());
                try {
                    cloud.voxelDownSample(-1.0).close();  // bad input is an exception, not a crash
                    System.exit(1);
                } catch (O3dException e) {
                    System.out.println("error as expected: " + e.getMessage());
                }
                // As Open3D, voxels start half a voxel below the minimum: 0 | 1 2 | ... | 9 gives 6 per axis.
                System.exit(down.size() == 216 ? 0 : 1);
            }
        }
    }
}
