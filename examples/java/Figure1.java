// SPDX-License-Identifier: MIT
// Figure 1 in Java: read a cloud, voxel-down-sample it (0.05), estimate normals (hybrid 0.1 / 30), write it.
//
// Build and run (from the build dir of bindings/swig, e.g. build-swig/bindings/swig, which holds o3d.jar
// and libo3d_java.so; CMake builds it into java_examples/ and ctest runs it as `java_figure1`):
//   javac -d java_examples -cp o3d.jar ../../../examples/java/Figure1.java
//   java -cp o3d.jar:java_examples Figure1 ../../../../shared/data/open3d/Feature/cloud_bin_0.pcd /tmp/down.ply
// (o3d.jar finds libo3d_java.so through -Do3d.native.dir, java.library.path, or the build dir baked in.)
import org.o3d.Library;
import org.o3d.O3dException;
import org.o3d.PointCloud;
import org.o3d.SearchParam;

public final class Figure1 {
    public static void main(String[] args) {
        if (args.length != 2) {
            System.err.println("usage: java -cp o3d.jar:. Figure1 <input cloud> <output cloud>");
            System.exit(2);
        }
        try (PointCloud pcd = Library.ioReadPointCloud(args[0], null, null);
             PointCloud down = pcd.voxelDownSample(0.05);
             SearchParam hybrid = new SearchParam()) {
            hybrid.setKind(Library.SEARCH_HYBRID);
            hybrid.setRadius(0.1);
            hybrid.setKnn(30);
            down.estimateNormals(hybrid, 0);
            Library.ioWritePointCloud(args[1], down, null, null);
            System.out.printf("read %d points from %s%n", pcd.size(), args[0]);
            System.out.printf("voxel_down_sample(0.05) -> %d points%n", down.size());
            System.out.printf("estimate_normals(hybrid radius 0.1, max_nn 30) -> has normals: %b%n", down.hasArray(Library.POINTCLOUD_NORMALS));
            System.out.printf("wrote %s%n", args[1]);
        } catch (O3dException e) {
            System.err.printf("o3d error (%s): %s%n", e.getStatus(), e.getMessage());
            System.exit(1);
        }
    }
}
