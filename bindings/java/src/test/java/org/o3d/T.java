// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;

import java.io.File;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Random;
import org.junit.jupiter.api.Assumptions;

/** Shared fixtures of the Java tests. */
final class T {
    private T() {}

    static final double[] IDENTITY = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    static O3dException assertStatus(int status, org.junit.jupiter.api.function.Executable e) {
        O3dException ex = assertThrows(O3dException.class, e);
        assertEquals(status, ex.getStatus(), ex.getMessage());
        assertFalse(ex.getMessage().isEmpty());
        return ex;
    }

    static O3dException assertInvalid(org.junit.jupiter.api.function.Executable e) {
        return assertStatus(Library.ERROR_INVALID_ARGUMENT, e);
    }

    static double[] randomPoints(int n, long seed, double sx, double sy, double sz) {
        Random r = new Random(seed);
        double[] p = new double[3 * n];
        for (int i = 0; i < n; i++) {
            p[3 * i] = r.nextDouble() * sx;
            p[3 * i + 1] = r.nextDouble() * sy;
            p[3 * i + 2] = r.nextDouble() * sz;
        }
        return p;
    }

    static double[] applyTransform(double[] t, double[] p) {
        double[] q = new double[p.length];
        for (int i = 0; i < p.length / 3; i++)
            for (int r = 0; r < 3; r++)
                q[3 * i + r] = t[4 * r] * p[3 * i] + t[4 * r + 1] * p[3 * i + 1] + t[4 * r + 2] * p[3 * i + 2] + t[4 * r + 3];
        return q;
    }

    static PointCloud cloud(double[] pts) {
        PointCloud pc = new PointCloud();
        pc.setArray(Library.POINTCLOUD_POINTS, pts);
        return pc;
    }

    static double[] points(PointCloud pc) {
        return pc.getArray(Library.POINTCLOUD_POINTS);
    }

    static TriangleMesh mesh(double[] vertices, int[] triangles) {
        TriangleMesh m = new TriangleMesh();
        m.setArray(Library.MESH_VERTICES, vertices);
        m.setIndexArray(Library.MESH_TRIANGLES, triangles);
        return m;
    }

    static TriangleMesh box() {
        return TriangleMesh.createBox(1, 1, 1);
    }

    static SearchParam knn(int k) {
        SearchParam p = new SearchParam();
        p.setKind(Library.SEARCH_KNN);
        p.setKnn(k);
        return p;
    }

    static SearchParam radius(double r) {
        SearchParam p = new SearchParam();
        p.setKind(Library.SEARCH_RADIUS);
        p.setRadius(r);
        return p;
    }

    static SearchParam hybrid(double r, int k) {
        SearchParam p = new SearchParam();
        p.setKind(Library.SEARCH_HYBRID);
        p.setRadius(r);
        p.setKnn(k);
        return p;
    }

    static int[] range(int start, int count) {
        return java.util.stream.IntStream.range(start, start + count).toArray();
    }

    static File dataFile(String rel) {
        String dir = System.getenv("O3D_TEST_DATA");
        if (dir == null || dir.isEmpty()) dir = System.getenv("O3D_TEST_DATA_DEFAULT");
        if (dir == null || dir.isEmpty()) dir = System.getProperty("o3d.test.data.default", "../shared/data");
        File f = new File(dir, rel);
        if (!f.isFile()) {
            if ("1".equals(System.getenv("O3D_REQUIRE_TEST_DATA")))
                fail("missing test data (O3D_REQUIRE_TEST_DATA=1): " + f);
            Assumptions.assumeTrue(false, "missing test data " + f);
        }
        return f;
    }

    static String data(String rel) {
        return dataFile(rel).getPath();
    }

    static PointCloud read(String path) {
        return Library.ioReadPointCloud(path, null, null);
    }

    static double[] toDouble(float[] f) {
        double[] d = new double[f.length];
        for (int i = 0; i < f.length; i++) d[i] = f[i];
        return d;
    }

    static ByteBuffer le(int bytes) {
        return ByteBuffer.allocate(bytes).order(ByteOrder.nativeOrder());
    }
}
