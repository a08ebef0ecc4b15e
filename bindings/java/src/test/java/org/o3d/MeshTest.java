// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.ByteBuffer;
import java.nio.DoubleBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** TriangleMesh and mesh I/O: the same scenarios as bindings/csharp/tests/Test.cs (GeometryTests). */
class MeshTest {
    @TempDir
    Path tmp;

    static O3dException assertStatus(Status s, org.junit.jupiter.api.function.Executable e) {
        O3dException ex = assertThrows(O3dException.class, e);
        assertEquals(s, ex.getStatus(), ex.getMessage());
        assertFalse(ex.getMessage().isEmpty());
        return ex;
    }

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

    @Test
    void boxAreaVolumeCounts() {
        try (TriangleMesh box = TriangleMesh.createBox()) {
            assertEquals(8, box.numVertices());
            assertEquals(12, box.numTriangles());
            assertTrue(box.hasVertices() && box.hasTriangles() && !box.hasTextures());
            assertEquals(6, box.getSurfaceArea(), 1e-12);
            assertEquals(1, box.getVolume(), 1e-12);
            assertTrue(box.isWatertight() && box.isOrientable() && box.isEdgeManifold(false) && box.isVertexManifold());
            assertFalse(box.isSelfIntersecting());
            assertEquals(2, box.eulerPoincareCharacteristic());
            assertArrayEquals(new double[] {0, 0, 0}, box.getMinBound(), 0);
            assertArrayEquals(new double[] {1, 1, 1}, box.getMaxBound(), 0);
            assertArrayEquals(new double[] {0.5, 0.5, 0.5}, box.getCenter(), 1e-12);
            double[] v = box.getVertices();
            for (int c = 0; c < 8; c++) {
                double x = c & 1, y = (c >> 1) & 1, z = (c >> 2) & 1;
                boolean found = false;
                for (int i = 0; i < 8; i++) found |= dist(v, i, x, y, z) == 0;
                assertTrue(found, "corner " + x + "," + y + "," + z);
            }
            for (int t : box.getTriangles()) assertTrue(t >= 0 && t < 8);
        }
        try (TriangleMesh box = TriangleMesh.createBox(2, 3, 4)) {
            assertEquals(2 * (2 * 3 + 3 * 4 + 2 * 4), box.getSurfaceArea(), 1e-12);
            assertEquals(24, box.getVolume(), 1e-12);
        }
    }

    /** Counts recorded from Open3D 0.20: tools/reference/record_primitives.py. */
    @Test
    void primitives() {
        try (TriangleMesh m = TriangleMesh.createSphere()) {
            assertEquals(762, m.numVertices());
            assertEquals(1520, m.numTriangles());
            assertEquals(2, m.eulerPoincareCharacteristic());
            double[] v = m.getVertices();
            for (int i = 0; i < v.length / 3; i++) assertEquals(1, dist(v, i, 0, 0, 0), 1e-12);
        }
        long[][] expect = {{102, 200}, {22, 40}, {600, 1200}, {124, 240}, {1134, 2240}, {4, 4}, {6, 8}, {12, 20}};
        TriangleMesh[] made = {TriangleMesh.createCylinder(), TriangleMesh.createCone(), TriangleMesh.createTorus(),
            TriangleMesh.createArrow(), TriangleMesh.createCoordinateFrame(), TriangleMesh.createTetrahedron(1),
            TriangleMesh.createOctahedron(1), TriangleMesh.createIcosahedron(1)};
        try {
            for (int i = 0; i < made.length; i++) {
                assertEquals(expect[i][0], made[i].numVertices(), "vertices of primitive " + i);
                assertEquals(expect[i][1], made[i].numTriangles(), "triangles of primitive " + i);
            }
            assertEquals(0, made[2].eulerPoincareCharacteristic(), "torus");
            assertTrue(made[4].hasVertexColors(), "frame colored");
            double a = Math.sqrt(8.0 / 3); // regular tetrahedron with circumradius 1
            assertEquals(Math.sqrt(3) * a * a, made[5].getSurfaceArea(), 1e-9);
            assertEquals(a * a * a / (6 * Math.sqrt(2)), made[5].getVolume(), 1e-9);
            assertEquals(4.0 / 3, made[6].getVolume(), 1e-9, "octahedron 4/3 r^3");
        } finally {
            for (TriangleMesh m : made) m.close();
        }
    }

    @Test
    void bulkArraysNormalsAppendClusters() {
        double[] verts = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        try (TriangleMesh m = new TriangleMesh(verts, new int[] {0, 1, 2})) {
            assertArrayEquals(verts, m.getVertices(), 0);
            assertArrayEquals(new int[] {0, 1, 2}, m.getTriangles());
            assertFalse(m.hasVertexNormals() || m.hasTriangleNormals());
            m.computeVertexNormals();
            assertTrue(m.hasVertexNormals() && m.hasTriangleNormals());
            assertArrayEquals(new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1}, m.getVertexNormals(), 1e-12);
            m.computeTriangleNormals(false);
            assertArrayEquals(new double[] {0, 0, 1}, m.getTriangleNormals(), 1e-12);
            m.setVertexColors(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1});
            assertTrue(m.hasVertexColors());
            m.setTriangleUvs(new double[] {0, 0, 1, 0, 0, 1});
            assertTrue(m.hasTriangleUvs());
            assertEquals(6, m.getTriangleUvs().length);
            m.setTriangleMaterialIds(new int[] {0});
            assertTrue(m.hasTriangleMaterialIds());
            assertArrayEquals(new int[] {0}, m.getTriangleMaterialIds());
            m.setVertexNormals(new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1});
            m.setTriangleNormals(new double[] {0, 0, 1});

            DoubleBuffer view = m.arrayView(MeshArray.VERTICES).asDoubleBuffer();
            double[] viewed = new double[view.remaining()];
            view.get(viewed);
            assertArrayEquals(verts, viewed, 0);
            ByteBuffer iv = m.indexArrayView(MeshIndexArray.TRIANGLES);
            assertEquals(3 * Integer.BYTES, iv.capacity());
            assertEquals(2, iv.asIntBuffer().get(2));
            assertTrue(m.arrayView(MeshArray.VERTICES).isReadOnly());
            m.arrayMutableView(MeshArray.VERTICES).asDoubleBuffer().put(3, 2.0);
            assertEquals(2.0, m.getVertices()[3], 0);
            assertEquals(3 * Integer.BYTES, m.indexArrayMutableView(MeshIndexArray.TRIANGLES).capacity());
            assertEquals(1, m.getSurfaceArea(), 1e-12);

            try (TriangleMesh copy = m.copy()) {
                copy.translate(new double[] {0, 0, 1});
                m.append(copy);
            }
            assertEquals(6, m.numVertices());
            assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5}, m.getTriangles());
            TriangleClusters cl = m.clusterConnectedTriangles();
            assertArrayEquals(new int[] {0, 1}, cl.triangleClusters);
            assertArrayEquals(new int[] {1, 1}, cl.clusterNTriangles);
            assertArrayEquals(new double[] {1, 1}, cl.clusterArea, 1e-12);
            m.clear();
            assertEquals(0, m.numVertices());
        }
    }

    @Test
    void cleanupTransformsProcessing() {
        try (TriangleMesh m = new TriangleMesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0},
                new int[] {0, 1, 2, 3, 4, 5, 0, 0, 1})) {
            m.removeDegenerateTriangles();
            assertEquals(2, m.numTriangles());
            m.removeDuplicatedVertices();
            assertEquals(4, m.numVertices());
            assertEquals(1, m.getSurfaceArea(), 1e-12);
            assertEquals(1, m.clusterConnectedTriangles().clusterNTriangles.length);
            m.removeDuplicatedTriangles().removeUnreferencedVertices().removeNonManifoldEdges().mergeCloseVertices(1e-9);
            assertEquals(4, m.numVertices());
            assertEquals(1, m.eulerPoincareCharacteristic(), "a disc: 4 - 5 + 2");
            assertTrue(m.isEdgeManifold() && !m.isEdgeManifold(false) && !m.isWatertight());
            assertStatus(Status.INVALID_ARGUMENT, m::getVolume);
        }
        try (TriangleMesh box = TriangleMesh.createBox()) {
            box.translate(new double[] {1, 2, 3});
            assertArrayEquals(new double[] {1, 2, 3}, box.getMinBound(), 1e-12);
            box.translate(new double[] {0, 0, 0}, false);
            assertArrayEquals(new double[] {0, 0, 0}, box.getCenter(), 1e-12);
            box.scale(2, new double[] {0, 0, 0});
            assertEquals(24, box.getSurfaceArea(), 1e-9);
            box.rotate(new double[] {0, -1, 0, 1, 0, 0, 0, 0, 1}, null);
            assertEquals(8, box.getVolume(), 1e-9);
            box.transform(new double[] {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1});
            double[][] bb = box.getAxisAlignedBoundingBox();
            assertArrayEquals(new double[] {0, 0, 0}, bb[0], 1e-9);
            assertArrayEquals(new double[] {2, 2, 2}, bb[1], 1e-9);
            box.paintUniformColor(new double[] {0.25, 0.5, 1});
            assertArrayEquals(new double[] {0.25, 0.5, 1}, java.util.Arrays.copyOf(box.getVertexColors(), 3), 0);
            box.normalizeNormals();
        }
        try (TriangleMesh box = TriangleMesh.createBox()) {
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
            try (TriangleMesh crop = box.crop(new double[] {-0.1, -0.1, -0.1}, new double[] {1.1, 1.1, 0.5})) {
                assertEquals(2, crop.numTriangles());
                assertEquals(4, crop.numVertices());
            }
            try (PointCloud a = box.samplePointsUniformly(500, false, 7); PointCloud b = box.samplePointsUniformly(500, false, 7)) {
                assertEquals(500, a.size());
                assertArrayEquals(a.getPoints(), b.getPoints(), 0, "same seed, same samples");
                assertOnBoxSurface(a.getPoints(), 1, 1, 1);
            }
            try (PointCloud pd = box.samplePointsPoissonDisk(100, 5, false, 3)) {
                assertEquals(100, pd.size());
                assertOnBoxSurface(pd.getPoints(), 1, 1, 1);
            }
            try (TriangleMesh s = box.filterSmoothSimple(1)) {
                assertEquals(8, s.numVertices());
                assertEquals(12, s.numTriangles());
            }
            try (TriangleMesh s = box.filterSmoothLaplacian(2)) {
                assertEquals(8, s.numVertices());
            }
            try (TriangleMesh s = box.filterSmoothTaubin(2)) {
                assertEquals(8, s.numVertices());
            }
            try (TriangleMesh s = box.simplifyVertexClustering(10)) {
                assertTrue(s.numTriangles() < 12);
            }
        }
        try (TriangleMesh sphere = TriangleMesh.createSphere(); TriangleMesh dec = sphere.simplifyQuadricDecimation(100)) {
            assertTrue(dec.numTriangles() <= 100 && dec.numTriangles() > 0, "decimated to " + dec.numTriangles());
        }
    }

    @Test
    void writtenThenReadBackEqual() {
        try (TriangleMesh box = TriangleMesh.createBox()) {
            double[] colors = new double[24];
            for (int i = 0; i < 24; i++) colors[i] = (i * 10 % 256) / 255.0; // exact in 8 bits
            box.setVertexColors(colors);
            for (String fmt : new String[] {"ply", "off"}) {
                byte[] bytes = IO.writeTriangleMeshToMemory(box, fmt);
                try (TriangleMesh back = IO.readTriangleMeshFromMemory(bytes, fmt)) {
                    assertArrayEquals(box.getVertices(), back.getVertices(), 1e-6, fmt);
                    assertArrayEquals(box.getTriangles(), back.getTriangles(), fmt);
                    if (fmt.equals("ply")) assertArrayEquals(colors, back.getVertexColors(), 1e-9);
                }
            }
            MeshWriteOptions ascii = new MeshWriteOptions();
            ascii.writeAscii = true;
            try (NativeBuffer nb = IO.writeTriangleMeshToNativeBuffer(box, "ply", ascii)) {
                assertTrue(new String(nb.toByteArray(), StandardCharsets.US_ASCII).contains("format ascii"));
            }
            ascii.writeVertexColors = false;
            String ply = tmp.resolve("box.ply").toString();
            IO.writeTriangleMesh(ply, box, null, ascii);
            try (TriangleMesh back = IO.readTriangleMesh(ply, null, new MeshReadOptions(false))) {
                assertEquals(8, back.numVertices());
                assertEquals(12, back.numTriangles());
                assertFalse(back.hasVertexColors());
                assertArrayEquals(box.getVertices(), back.getVertices(), 1e-6);
            }
            String obj = tmp.resolve("box.obj").toString();
            IO.writeTriangleMesh(obj, box);
            try (TriangleMesh back = IO.readTriangleMesh(obj)) {
                assertEquals(12, back.numTriangles());
                assertEquals(6, back.getSurfaceArea(), 1e-9);
            }
        }
    }

    @Test
    void errorsForBadInputAndMisuse() {
        assertStatus(Status.INVALID_ARGUMENT, () -> TriangleMesh.createBox(-1, 1, 1));
        assertStatus(Status.INVALID_ARGUMENT, () -> TriangleMesh.createSphere(1, 0));
        try (TriangleMesh m = new TriangleMesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 5})) {
            assertStatus(Status.INVALID_ARGUMENT, m::computeVertexNormals);
            assertStatus(Status.INVALID_ARGUMENT, m::getSurfaceArea);
            assertStatus(Status.INVALID_ARGUMENT, () -> m.samplePointsUniformly(10));
            assertStatus(Status.INVALID_ARGUMENT, () -> m.mergeCloseVertices(Double.NaN));
            assertStatus(Status.INVALID_ARGUMENT, () -> m.getTexture(0));
            assertThrows(IllegalArgumentException.class, () -> m.setVertices(new double[] {1, 2}));
            assertThrows(NullPointerException.class, () -> m.setTriangles(null));
            assertThrows(NullPointerException.class, () -> m.append(null));
        }
        assertStatus(Status.IO, () -> IO.readTriangleMesh("/nonexistent/dir/none.ply"));
        assertStatus(Status.PARSE,
                () -> IO.readTriangleMeshFromMemory("ply\nformat garbage\n".getBytes(StandardCharsets.US_ASCII), "ply"));
        try (TriangleMesh box = TriangleMesh.createBox()) {
            assertStatus(Status.UNSUPPORTED, () -> IO.writeTriangleMeshToMemory(box, "nope"));
        }
        // NULL handles straight into the raw layer: an error, never a crash
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_trianglemesh_get_volume(new double[1], 0));
        assertThrows(IllegalArgumentException.class, () -> O3dNative.o3d_trianglemesh_create_box(null, 1, 1, 1));

        TriangleMesh mesh = TriangleMesh.createBox();
        try (Image tex = new Image(1, 1, 3, 1)) {
            mesh.addTexture(tex);
        }
        assertEquals(1, mesh.textureCount());
        assertTrue(mesh.hasTextures());
        try (Image t = mesh.getTexture(0)) {
            assertEquals(1, t.width());
            assertEquals(3, t.numChannels());
        }
        mesh.clearTextures();
        assertEquals(0, mesh.textureCount());
        mesh.close();
        mesh.close(); // idempotent
        assertTrue(mesh.isClosed());
        assertThrows(IllegalStateException.class, mesh::numVertices);
        for (int i = 0; i < 50; i++) TriangleMesh.createBox(); // the Cleaner collects these
        System.gc();
    }
}
