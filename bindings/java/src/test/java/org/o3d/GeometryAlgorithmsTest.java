// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The geometry algorithms of issue 22's second half through the generated classes only, the same scenarios as
 * bindings/csharp/tests/GeometryAlgorithmsTest.cs: mesh analysis, ARAP, bounding volumes and their meshes,
 * point-cloud smoothing, static covariances, planar patches, traced down-sampling and half-edge meshes, each against
 * an analytic answer, with bad input throwing O3dException.
 */
class GeometryAlgorithmsTest {
    static int[][] listsOf(IndexLists lists) {
        long[] off = lists.getOffsets();
        int[] val = lists.getValues();
        int[][] out = new int[off.length - 1][];
        for (int i = 0; i + 1 < off.length; i++) out[i] = Arrays.copyOfRange(val, (int) off[i], (int) off[i + 1]);
        return out;
    }

    static double meanAbsZ(double[] p) {
        double s = 0;
        for (int i = 0; i < p.length / 3; i++) s += Math.abs(p[3 * i + 2]);
        return s / (p.length / 3);
    }

    static final double[] FIN_VERTICES = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
    static final int[] FIN = {0, 1, 2, 1, 0, 3, 0, 1, 4};

    @Test
    void adjacencyAndNonManifoldElements() {
        try (TriangleMesh strip = mesh(new double[15], new int[] {0, 1, 2, 2, 1, 3});
                IndexLists adj = strip.computeAdjacencyList()) {
            int[][] lists = listsOf(adj);
            assertEquals(5, lists.length);
            assertArrayEquals(new int[] {0, 2, 3}, lists[1]);
            assertEquals(0, lists[4].length);
        }
        try (TriangleMesh fin = mesh(FIN_VERTICES, FIN)) {
            assertArrayEquals(new int[] {0, 1}, fin.getNonManifoldEdges(1));
            assertEquals(2 * 7, fin.getNonManifoldEdges(0).length);
            assertFalse(fin.orientTriangles());
            assertArrayEquals(FIN, fin.getIndexArray(Library.MESH_TRIANGLES), "left unchanged");
        }
        try (TriangleMesh bowtie = mesh(new double[15], new int[] {0, 1, 2, 0, 3, 4})) {
            assertArrayEquals(new int[] {0}, bowtie.getNonManifoldVertices());
        }
    }

    @Test
    void intersectionsOrientationSharpenEllipsoid() {
        try (TriangleMesh a = TriangleMesh.createSphere(1, 10);
                TriangleMesh b = TriangleMesh.createSphere(1, 10);
                TriangleMesh far = TriangleMesh.createSphere(1, 10)) {
            b.translate(new double[] {1.5, 0, 0}, 1);
            far.translate(new double[] {2.5, 0, 0}, 1);
            assertTrue(a.isIntersecting(b));
            assertFalse(a.isIntersecting(far));
            assertEquals(0, a.getSelfIntersectingTriangles().length);
        }
        try (TriangleMesh box = TriangleMesh.createBox(1, 2, 3)) {
            int[] t = box.getIndexArray(Library.MESH_TRIANGLES);
            for (int i = 0; i < t.length; i += 9) {
                int x = t[i + 1];
                t[i + 1] = t[i + 2];
                t[i + 2] = x;
            }
            box.setIndexArray(Library.MESH_TRIANGLES, t);
            assertTrue(box.orientTriangles());
            assertEquals(6.0, box.getVolume(), 1e-12);
            try (TriangleMesh same = box.filterSharpen(1, 0.0, Library.FILTER_SCOPE_ALL)) {
                assertArrayEquals(box.getArray(Library.MESH_VERTICES), same.getArray(Library.MESH_VERTICES));
            }
            assertInvalid(() -> box.filterSharpen(1, Double.NaN, Library.FILTER_SCOPE_ALL));
        }
        try (TriangleMesh e = TriangleMesh.createEllipsoid(1, 2, 0.5, 10, 0)) {
            double[] v = e.getArray(Library.MESH_VERTICES);
            for (int i = 0; i < v.length / 3; i++)
                assertEquals(1.0, v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] / 4 + v[3 * i + 2] * v[3 * i + 2] * 4, 1e-12);
        }
        assertInvalid(() -> TriangleMesh.createEllipsoid(-1, 1, 1, 10, 0));
    }

    @Test
    void boundingVolumesAndTheirMeshes() {
        double c = Math.cos(0.3), s = Math.sin(0.3);
        try (OrientedBoundingBox obb = new OrientedBoundingBox()) {
            obb.setCenter(new double[] {1, 2, 3});
            obb.setR(new double[] {c, -s, 0, s, c, 0, 0, 0, 1});
            obb.setExtent(new double[] {2, 4, 6});
            try (TriangleMesh m = TriangleMesh.createFromOrientedBoundingBox(obb, null, 0);
                    OrientedBoundingBox minimal = m.getMinimalOrientedBoundingBox(0);
                    OrientedBoundingEllipsoid fit =
                            OrientedBoundingEllipsoid.createFromPoints(m.getArray(Library.MESH_VERTICES), 0)) {
                assertEquals(48.0, m.getVolume(), 1e-9);
                double[] ext = minimal.getExtent();
                assertEquals(48.0, ext[0] * ext[1] * ext[2], 1e-6);
                double[] radii = fit.getRadii().clone();
                Arrays.sort(radii);
                for (int k = 0; k < 3; k++) assertEquals(Math.sqrt(3) * (k + 1), radii[k], 1e-3 * (k + 1));
                try (TriangleMesh em = TriangleMesh.createFromOrientedBoundingEllipsoid(fit, null, 12, 0)) {
                    assertEquals(2 + 11 * 24, em.numVertices());
                }
            }
        }
        assertInvalid(() -> OrientedBoundingEllipsoid.createFromPoints(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, 0));
    }

    @Test
    void cloudSmoothingCovariancesPatchesAndTrace() {
        Random rnd = new Random(5);
        double[] plane = new double[3 * 400];
        for (int i = 0; i < 400; i++) {
            plane[3 * i] = 0.01 * (i % 20);
            plane[3 * i + 1] = 0.01 * (i / 20);
            plane[3 * i + 2] = 0.002 * (rnd.nextDouble() - 0.5);
        }
        try (PointCloud pc = cloud(plane);
                PointCloud lap = pc.smoothLaplacian(10, 0.5, 8, 0);
                PointCloud tau = pc.smoothTaubin(10, 0.5, -0.53, 8, 0);
                SearchParam param = hybrid(0.035, 30);
                PointCloud mls = pc.smoothMls(param);
                PointCloud bil = pc.smoothBilateral(param, 0.02, 0.01)) {
            double before = meanAbsZ(plane);
            assertTrue(meanAbsZ(points(lap)) < 0.5 * before);
            assertTrue(meanAbsZ(points(mls)) < 0.5 * before);
            assertTrue(meanAbsZ(points(tau)) < before);
            assertTrue(meanAbsZ(points(bil)) < before);
            assertInvalid(() -> pc.smoothLaplacian(1, 0.5, 0, 0));
        }
        try (PointCloud five = cloud(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 1});
                SearchParam k5 = knn(5)) {
            double[] cov = five.estimatePointCovariances(k5, 0);
            assertEquals(45, cov.length);
            assertEquals(0.2, cov[0], 1e-12);
            assertEquals(0.2, cov[4], 1e-12);
            assertEquals(0.16, cov[8], 1e-12);
        }
        double[] pts = {0.2, 0.2, 0.2, 0.7, 0.2, 0.2, 0.3, 0.8, 0.9, 1.2, 0.1, 0.1, 1.9, 0.9, 0.9, 1.1, 0.1, 0.6};
        try (PointCloud pc = cloud(pts);
                VoxelDownSampleAndTraceResult res =
                        pc.voxelDownSampleAndTrace(1.0, new double[] {0, 0, 0}, new double[] {2, 1, 1}, 0);
                PointCloud down = res.cloud();
                IndexLists cubic = res.cubicIds();
                IndexLists traced = res.originalIndices()) {
            assertEquals(2, down.size());
            int[][] t = listsOf(traced);
            assertArrayEquals(new int[] {0, 1, 2}, t[0]);
            assertArrayEquals(new int[] {3, 4, 5}, t[1]);
            assertArrayEquals(new int[] {3, -1, -1, -1, 5, -1, -1, 4}, listsOf(cubic)[1]);
            assertInvalid(() -> pc.voxelDownSampleAndTrace(0.0, new double[] {0, 0, 0}, new double[] {2, 1, 1}, 0));
        }
        List<Double> p2 = new ArrayList<>(), n2 = new ArrayList<>();
        for (int wall = 0; wall < 2; wall++)
            for (int i = 0; i < 40; i++)
                for (int j = 0; j < 40; j++) {
                    double a = 0.05 * i + 0.01, b = 0.05 * j + 0.01, w = 0.001 * (rnd.nextDouble() - 0.5);
                    if (wall == 0) {
                        p2.addAll(Arrays.asList(a, b, w));
                        n2.addAll(Arrays.asList(0.0, 0.0, 1.0));
                    } else {
                        p2.addAll(Arrays.asList(w, a, b + 0.05));
                        n2.addAll(Arrays.asList(1.0, 0.0, 0.0));
                    }
                }
        try (PointCloud pc = cloud(p2.stream().mapToDouble(Double::doubleValue).toArray());
                PlanarPatchOptions opts = new PlanarPatchOptions()) {
            pc.setArray(Library.POINTCLOUD_NORMALS, n2.stream().mapToDouble(Double::doubleValue).toArray());
            assertEquals(60.0, opts.getNormalVarianceThresholdDeg());
            assertEquals(75.0, opts.getCoplanarityDeg());
            double[] boxes = pc.detectPlanarPatches(opts);
            assertEquals(2 * 15, boxes.length);
            double[] nz = {Math.abs(boxes[3 + 8]), Math.abs(boxes[15 + 3 + 8])};  // R[2][2] of each box
            Arrays.sort(nz);
            assertTrue(nz[0] < 1e-3 && nz[1] > 1 - 1e-3, "one normal along z, one across it");
        }
    }

    @Test
    void asRigidAsPossibleReproducesARigidMotion() {
        try (TriangleMesh sphere = TriangleMesh.createSphere(1, 8)) {
            double[] v = sphere.getArray(Library.MESH_VERTICES);
            double c = Math.cos(Math.PI / 6), s = Math.sin(Math.PI / 6);
            int n = v.length / 3;
            double[] moved = new double[3 * n];
            for (int i = 0; i < n; i++) {
                moved[3 * i] = c * v[3 * i] - s * v[3 * i + 1] + 0.5;
                moved[3 * i + 1] = s * v[3 * i] + c * v[3 * i + 1] - 0.25;
                moved[3 * i + 2] = v[3 * i + 2] + 2;
            }
            int[] ids = java.util.stream.IntStream.range(0, n).filter(i -> i % 3 == 0).toArray();
            double[] pos = new double[3 * ids.length];
            for (int k = 0; k < ids.length; k++) System.arraycopy(moved, 3 * ids[k], pos, 3 * k, 3);
            try (TriangleMesh out = sphere.deformAsRigidAsPossible(ids, pos, 50, Library.ARAP_ENERGY_SPOKES, 0.01)) {
                assertArrayEquals(moved, out.getArray(Library.MESH_VERTICES), 1e-5);
            }
            assertInvalid(() -> sphere.deformAsRigidAsPossible(new int[] {0, 0}, new double[6], 5, Library.ARAP_ENERGY_SPOKES, 0.01));
            assertInvalid(() -> sphere.deformAsRigidAsPossible(new int[] {0, 1}, new double[3], 5, Library.ARAP_ENERGY_SPOKES, 0.01));
        }
    }

    @Test
    void halfEdgeMeshes() {
        try (TriangleMesh ico = TriangleMesh.createIcosahedron(1);
                HalfEdgeTriangleMesh h = HalfEdgeTriangleMesh.createFromTriangleMesh(ico);
                IndexLists loops = h.getBoundaries()) {
            int[] he = h.getHalfEdges();
            assertEquals(60 * 5, he.length);
            for (int i = 0; i < 60; i++) {
                int twin = he[5 * i + 1];
                assertTrue(twin >= 0);
                assertEquals(he[5 * i + 3], he[5 * twin + 2]);
                assertEquals(he[5 * i + 2], he[5 * twin + 3]);
            }
            assertEquals(0, listsOf(loops).length);
        }
        try (TriangleMesh square = mesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, new int[] {0, 1, 3, 0, 3, 2});
                HalfEdgeTriangleMesh h = HalfEdgeTriangleMesh.createFromTriangleMesh(square)) {
            assertArrayEquals(new int[] {0, 1, 3, 2}, h.boundaryVerticesFromVertex(0));
            assertInvalid(() -> h.boundaryVerticesFromVertex(7));
        }
        try (TriangleMesh fin = mesh(FIN_VERTICES, FIN)) {
            assertInvalid(() -> HalfEdgeTriangleMesh.createFromTriangleMesh(fin));
        }
    }
}
