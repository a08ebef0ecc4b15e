// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** TriangleMesh and mesh I/O: the same scenarios as bindings/csharp/tests/Test.cs (GeometryTests). */
class MeshTest {
    @TempDir
    Path tmp;

    static final int V = Library.MESH_VERTICES, TRI = Library.MESH_TRIANGLES, VN = Library.MESH_VERTEX_NORMALS,
            VC = Library.MESH_VERTEX_COLORS, TN = Library.MESH_TRIANGLE_NORMALS, UV = Library.MESH_TRIANGLE_UVS,
            MAT = Library.MESH_TRIANGLE_MATERIAL_IDS, ALL = Library.FILTER_SCOPE_ALL;

    static double dist(double[] p, int i, double x, double y, double z) {
        double dx = p[3 * i] - x, dy = p[3 * i + 1] - y, dz = p[3 * i + 2] - z;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** Every point lies on the surface of the box [0,w]x[0,h]x[0,d]. */
    static void assertOnBoxSurface(double[] p, double w, double h, double d) {
        for (int i = 0; i < p.length / 3; i++) {
            double x = p[3 * i], y = p[3 * i + 1], z = p[3 * i + 2];
            assertTrue(x >= -1e-9 && x <= w + 1e-9 && y >= -1e-9 && y <= h + 1e-9 && z >= -1e-9 && z <= d + 1e-9, "inside " + i);
            double face = Math.min(Math.min(Math.min(Math.abs(x), Math.abs(w - x)), Math.min(Math.abs(y), Math.abs(h - y))),
                    Math.min(Math.abs(z), Math.abs(d - z)));
            assertTrue(face < 1e-9, "on a face " + i);
        }
    }

    static byte[] write(TriangleMesh m, String fmt, MeshWriteOptions o) {
        try (Buffer b = Library.ioWriteTriangleMeshToMemory(m, fmt, o)) {
            return b.getData();
        }
    }

    /** create_mobius reaches Java through the generated classes only (no hand-written Java for it). */
    @Test
    void mobiusStripFromGeneratedOptions() {
        try (MobiusOptions opts = new MobiusOptions()) {
            assertEquals(70, opts.getLengthSplit());  // defaults from o3d_mobius_options_init
            assertEquals(1, opts.getTwists());
            for (int twists = 1; twists <= 2; twists++) {
                opts.setTwists(twists);
                try (TriangleMesh m = TriangleMesh.createMobius(opts)) {
                    assertEquals(70 * 15, m.numVertices());
                    assertEquals(2 * 70 * 14, m.numTriangles());
                    assertEquals(0, m.eulerPoincareCharacteristic());
                    assertEquals(twists % 2 == 0, m.isOrientable());
                }
            }
            opts.setTwists(-1);
            O3dException e = assertThrows(O3dException.class, () -> TriangleMesh.createMobius(opts));
            assertEquals(Library.ERROR_INVALID_ARGUMENT, e.getStatus());
        }
    }

    @Test
    void boxAreaVolumeCounts() {
        try (TriangleMesh box = box()) {
            assertEquals(8, box.numVertices());
            assertEquals(12, box.numTriangles());
            assertTrue(box.hasArray(V) && box.hasArray(TRI) && box.textureCount() == 0);
            assertEquals(6, box.getSurfaceArea(), 1e-12);
            assertEquals(1, box.getVolume(), 1e-12);
            assertTrue(box.isWatertight() && box.isOrientable() && box.isEdgeManifold(0) && box.isVertexManifold());
            assertFalse(box.isSelfIntersecting());
            assertEquals(2, box.eulerPoincareCharacteristic());
            assertArrayEquals(new double[] {0, 0, 0}, box.getMinBound(), 0);
            assertArrayEquals(new double[] {1, 1, 1}, box.getMaxBound(), 0);
            assertArrayEquals(new double[] {0.5, 0.5, 0.5}, box.getCenter(), 1e-12);
            double[] v = box.getArray(V);
            for (int c = 0; c < 8; c++) {
                double x = c & 1, y = (c >> 1) & 1, z = (c >> 2) & 1;
                boolean found = false;
                for (int i = 0; i < 8; i++) found |= dist(v, i, x, y, z) == 0;
                assertTrue(found, "corner " + x + "," + y + "," + z);
            }
            for (int t : box.getIndexArray(TRI)) assertTrue(t >= 0 && t < 8);
        }
        try (TriangleMesh box = TriangleMesh.createBox(2, 3, 4)) {
            assertEquals(2 * (2 * 3 + 3 * 4 + 2 * 4), box.getSurfaceArea(), 1e-12);
            assertEquals(24, box.getVolume(), 1e-12);
        }
    }

    /** Counts recorded from Open3D 0.20 (default arguments): tools/reference/record_primitives.py. */
    @Test
    void primitives() {
        try (TriangleMesh m = TriangleMesh.createSphere(1, 20)) {
            assertEquals(762, m.numVertices());
            assertEquals(1520, m.numTriangles());
            assertEquals(2, m.eulerPoincareCharacteristic());
            double[] v = m.getArray(V);
            for (int i = 0; i < v.length / 3; i++) assertEquals(1, dist(v, i, 0, 0, 0), 1e-12);
        }
        long[][] expect = {{102, 200}, {22, 40}, {600, 1200}, {124, 240}, {1134, 2240}, {4, 4}, {6, 8}, {12, 20}};
        TriangleMesh[] made = {TriangleMesh.createCylinder(1, 2, 20, 4), TriangleMesh.createCone(1, 2, 20, 1),
            TriangleMesh.createTorus(1, 0.5, 30, 20), TriangleMesh.createArrow(1, 1.5, 5, 4, 20, 4, 1),
            TriangleMesh.createCoordinateFrame(1, null), TriangleMesh.createTetrahedron(1), TriangleMesh.createOctahedron(1),
            TriangleMesh.createIcosahedron(1)};
        try {
            for (int i = 0; i < made.length; i++) {
                assertEquals(expect[i][0], made[i].numVertices(), "vertices of primitive " + i);
                assertEquals(expect[i][1], made[i].numTriangles(), "triangles of primitive " + i);
            }
            assertEquals(0, made[2].eulerPoincareCharacteristic(), "torus");
            assertTrue(made[4].hasArray(VC), "frame colored");
            double a = Math.sqrt(8.0 / 3); // regular tetrahedron with circumradius 1
            assertEquals(Math.sqrt(3) * a * a, made[5].getSurfaceArea(), 1e-9);
            assertEquals(a * a * a / (6 * Math.sqrt(2)), made[5].getVolume(), 1e-9);
            assertEquals(4.0 / 3, made[6].getVolume(), 1e-9, "octahedron 4/3 r^3");
        } finally {
            for (TriangleMesh m : made) m.close();
        }
        try (MobiusOptions o = new MobiusOptions(); TriangleMesh m = TriangleMesh.createMobius(o)) {
            assertTrue(m.numTriangles() > 0);
        }
    }

    @Test
    void bulkArraysNormalsAppendClusters() {
        double[] verts = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        try (TriangleMesh m = mesh(verts, new int[] {0, 1, 2})) {
            assertArrayEquals(verts, m.getArray(V), 0);
            assertArrayEquals(new int[] {0, 1, 2}, m.getIndexArray(TRI));
            assertFalse(m.hasArray(VN) || m.hasArray(TN));
            m.computeVertexNormals(1);
            assertTrue(m.hasArray(VN) && m.hasArray(TN));
            assertArrayEquals(new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1}, m.getArray(VN), 1e-12);
            m.computeTriangleNormals(0);
            assertArrayEquals(new double[] {0, 0, 1}, m.getArray(TN), 1e-12);
            m.setArray(VC, new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1});
            assertTrue(m.hasArray(VC));
            m.setArray(UV, new double[] {0, 0, 1, 0, 0, 1});
            assertTrue(m.hasArray(UV));
            assertEquals(6, m.getArray(UV).length);
            m.setIndexArray(MAT, new int[] {0});
            assertTrue(m.hasArray(MAT));
            assertArrayEquals(new int[] {0}, m.getIndexArray(MAT));
            m.setArray(VN, new float[] {0, 0, 1, 0, 0, 1, 0, 0, 1});
            m.setArray(TN, new double[] {0, 0, 1});
            try (TrianglemeshArrayShapeResult s = m.arrayShape(UV)) {
                assertEquals(3, s.rows());
                assertEquals(2, s.cols());
            }
            java.nio.DoubleBuffer view = m.arrayView(V).asDoubleBuffer();
            double[] viewed = new double[view.remaining()];
            view.get(viewed);
            assertArrayEquals(verts, viewed, 0);
            java.nio.ByteBuffer iv = m.indexArrayView(TRI);
            assertEquals(3 * Integer.BYTES, iv.capacity());
            assertEquals(2, iv.asIntBuffer().get(2));
            assertTrue(m.arrayView(V).isReadOnly());
            m.arrayMutableView(V).asDoubleBuffer().put(3, 2.0);
            assertEquals(3 * Integer.BYTES, m.indexArrayMutableView(TRI).capacity());
            assertEquals(2.0, m.getArray(V)[3], 0);
            assertEquals(1, m.getSurfaceArea(), 1e-12);

            try (TriangleMesh copy = m.clone()) {
                copy.translate(new double[] {0, 0, 1}, 1);
                m.append(copy);
            }
            assertEquals(6, m.numVertices());
            assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5}, m.getIndexArray(TRI));
            try (ClusterConnectedTrianglesResult cl = m.clusterConnectedTriangles()) {
                assertArrayEquals(new int[] {0, 1}, cl.triangleClusters());
                assertArrayEquals(new int[] {1, 1}, cl.clusterNTriangles());
                assertArrayEquals(new double[] {1, 1}, cl.clusterArea(), 1e-12);
            }
            m.clear();
            assertEquals(0, m.numVertices());
        }
    }

    @Test
    void cleanupTransformsProcessing() {
        try (TriangleMesh m = mesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0},
                new int[] {0, 1, 2, 3, 4, 5, 0, 0, 1})) {
            m.removeDegenerateTriangles();
            assertEquals(2, m.numTriangles());
            m.removeDuplicatedVertices();
            assertEquals(4, m.numVertices());
            assertEquals(1, m.getSurfaceArea(), 1e-12);
            try (ClusterConnectedTrianglesResult cl = m.clusterConnectedTriangles()) {
                assertEquals(1, cl.clusterNTriangles().length);
            }
            m.removeDuplicatedTriangles();
            m.removeUnreferencedVertices();
            m.removeNonManifoldEdges();
            m.mergeCloseVertices(1e-9);
            assertEquals(4, m.numVertices());
            assertEquals(1, m.eulerPoincareCharacteristic(), "a disc: 4 - 5 + 2");
            assertTrue(m.isEdgeManifold(1) && !m.isEdgeManifold(0) && !m.isWatertight());
            assertInvalid(m::getVolume);
        }
        try (TriangleMesh box = box()) {
            box.translate(new double[] {1, 2, 3}, 1);
            assertArrayEquals(new double[] {1, 2, 3}, box.getMinBound(), 1e-12);
            box.translate(new double[] {0, 0, 0}, 0);
            assertArrayEquals(new double[] {0, 0, 0}, box.getCenter(), 1e-12);
            box.scale(2, new double[] {0, 0, 0});
            assertEquals(24, box.getSurfaceArea(), 1e-9);
            box.rotate(new double[] {0, -1, 0, 1, 0, 0, 0, 0, 1}, null);
            assertEquals(8, box.getVolume(), 1e-9);
            box.transform(new double[] {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1});
            try (TrianglemeshGetAxisAlignedBoundingBoxResult bb = box.getAxisAlignedBoundingBox()) {
                assertArrayEquals(new double[] {0, 0, 0}, bb.min(), 1e-9);
                assertArrayEquals(new double[] {2, 2, 2}, bb.max(), 1e-9);
            }
            box.paintUniformColor(new double[] {0.25, 0.5, 1});
            assertArrayEquals(new double[] {0.25, 0.5, 1}, java.util.Arrays.copyOf(box.getArray(VC), 3), 0);
            box.normalizeNormals();
        }
        try (TriangleMesh box = box()) {
            try (TriangleMesh sub = box.subdivideMidpoint(1)) {
                assertEquals(26, sub.numVertices(), "8 corners + 18 edge midpoints");
                assertEquals(48, sub.numTriangles());
                assertEquals(6, sub.getSurfaceArea(), 1e-12);
            }
            try (TriangleMesh loop = box.subdivideLoop(1)) {
                assertEquals(48, loop.numTriangles());
                assertTrue(loop.isWatertight());
                assertTrue(loop.getSurfaceArea() < 6);
            }
            try (TriangleMesh crop = box.cropAabb(new double[] {-0.1, -0.1, -0.1}, new double[] {1.1, 1.1, 0.5})) {
                assertEquals(2, crop.numTriangles());
                assertEquals(4, crop.numVertices());
            }
            try (PointCloud a = box.samplePointsUniformly(500, 0, 7); PointCloud b = box.samplePointsUniformly(500, 0, 7)) {
                assertEquals(500, a.size());
                assertArrayEquals(points(a), points(b), 0, "same seed, same samples");
                assertOnBoxSurface(points(a), 1, 1, 1);
            }
            try (PointCloud pd = box.samplePointsPoissonDisk(100, 5, 0, 3)) {
                assertEquals(100, pd.size());
                assertOnBoxSurface(points(pd), 1, 1, 1);
            }
            try (TriangleMesh s = box.filterSmoothSimple(1, ALL)) {
                assertEquals(8, s.numVertices());
                assertEquals(12, s.numTriangles());
            }
            try (TriangleMesh s = box.filterSmoothLaplacian(2, 0.5, ALL)) {
                assertEquals(8, s.numVertices());
            }
            try (TriangleMesh s = box.filterSmoothTaubin(2, 0.5, -0.53, ALL)) {
                assertEquals(8, s.numVertices());
            }
            try (TriangleMesh s = box.simplifyVertexClustering(10, Library.SIMPLIFICATION_AVERAGE)) {
                assertTrue(s.numTriangles() < 12);
            }
        }
        try (TriangleMesh sphere = TriangleMesh.createSphere(1, 20);
             TriangleMesh dec = sphere.simplifyQuadricDecimation(100, Double.POSITIVE_INFINITY, 1.0)) {
            assertTrue(dec.numTriangles() <= 100 && dec.numTriangles() > 0, "decimated to " + dec.numTriangles());
        }
    }

    @Test
    void writtenThenReadBackEqual() {
        try (TriangleMesh box = box()) {
            double[] colors = new double[24];
            for (int i = 0; i < 24; i++) colors[i] = (i * 10 % 256) / 255.0; // exact in 8 bits
            box.setArray(VC, colors);
            for (String fmt : new String[] {"ply", "off"}) {
                try (TriangleMesh back = Library.ioReadTriangleMeshFromMemory(write(box, fmt, null), fmt, null)) {
                    assertArrayEquals(box.getArray(V), back.getArray(V), 1e-6, fmt);
                    assertArrayEquals(box.getIndexArray(TRI), back.getIndexArray(TRI), fmt);
                    if (fmt.equals("ply")) assertArrayEquals(colors, back.getArray(VC), 1e-9);
                }
            }
            try (MeshWriteOptions ascii = new MeshWriteOptions(); MeshReadOptions raw = new MeshReadOptions()) {
                assertEquals(0, ascii.getWriteAscii(), "defaults from o3d_mesh_write_options_init");
                assertEquals(1, ascii.getWriteVertexColors());
                ascii.setWriteAscii(1);
                assertTrue(new String(write(box, "ply", ascii), StandardCharsets.US_ASCII).contains("format ascii"));
                ascii.setWriteVertexColors(0);
                String ply = tmp.resolve("box.ply").toString();
                Library.ioWriteTriangleMesh(ply, box, null, ascii);
                raw.setEnablePostProcessing(0);
                try (TriangleMesh back = Library.ioReadTriangleMesh(ply, null, raw)) {
                    assertEquals(8, back.numVertices());
                    assertEquals(12, back.numTriangles());
                    assertFalse(back.hasArray(VC));
                    assertArrayEquals(box.getArray(V), back.getArray(V), 1e-6);
                }
            }
            String obj = tmp.resolve("box.obj").toString();
            Library.ioWriteTriangleMesh(obj, box, null, null);
            try (TriangleMesh back = Library.ioReadTriangleMesh(obj, null, null)) {
                assertEquals(12, back.numTriangles());
                assertEquals(6, back.getSurfaceArea(), 1e-9);
            }
        }
    }

    @Test
    void errorsForBadInputAndMisuse() {
        assertInvalid(() -> TriangleMesh.createBox(-1, 1, 1));
        assertInvalid(() -> TriangleMesh.createSphere(1, 0));
        try (TriangleMesh m = mesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 5})) {
            assertInvalid(() -> m.computeVertexNormals(1));
            assertInvalid(m::getSurfaceArea);
            assertInvalid(() -> m.samplePointsUniformly(10, 0, 0));
            assertInvalid(() -> m.mergeCloseVertices(Double.NaN));
            assertInvalid(() -> m.getTexture(0));
            assertInvalid(() -> m.setArray(V, new double[] {1, 2}));
            assertInvalid(() -> m.setIndexArray(TRI, new int[] {1, 2}));
            assertInvalid(() -> m.append(null));
        }
        assertStatus(Library.ERROR_IO, () -> Library.ioReadTriangleMesh("/nonexistent/dir/none.ply", null, null));
        assertStatus(Library.ERROR_PARSE, () -> Library.ioReadTriangleMeshFromMemory(
                "ply\nformat garbage\n".getBytes(StandardCharsets.US_ASCII), "ply", null));
        try (TriangleMesh box = box()) {
            assertStatus(Library.ERROR_UNSUPPORTED, () -> write(box, "nope", null));
        }

        TriangleMesh mesh = box();
        try (Image tex = Image.create(1, 1, 3, 1)) {
            mesh.addTexture(tex);
        }
        assertEquals(1, mesh.textureCount());
        try (Image t = mesh.getTexture(0)) {
            assertEquals(1, t.width());
            assertEquals(3, t.numChannels());
        }
        mesh.clearTextures();
        assertEquals(0, mesh.textureCount());
        mesh.close();
        mesh.close(); // idempotent
        assertEquals(0, TriangleMesh.getCPtr(mesh), "closed");
        assertThrows(IllegalStateException.class, mesh::numVertices);
        for (int i = 0; i < 50; i++) box(); // the garbage collector frees these
        System.gc();
    }
}
