// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import org.junit.jupiter.api.Test;

/**
 * TSDF volumes, the scenarios of tests/capi/test_integration.c: a fronto-parallel plane comes back at its depth, one
 * vertex per voxel column, and the volume's array and errors.
 */
class IntegrationTest {
    static final int W = 160, H = 120;

    static RGBDImage planeFrame() {
        byte[] color = new byte[3 * W * H];
        float[] depth = new float[W * H];
        for (int i = 0; i < W * H; i++) {
            color[3 * i] = (byte) 200;
            color[3 * i + 1] = 100;
            color[3 * i + 2] = 50;
            depth[i] = 1.0f;
        }
        try (Image c = Image.createFromData(W, H, 3, 1, color); Image d = Images.fromFloat(W, H, 1, depth);
             RgbdOptions o = new RgbdOptions()) {
            o.setDepthScale(1.0);
            o.setConvertRgbToIntensity(0);
            return RGBDImage.createFromColorAndDepth(c, d, o);
        }
    }

    @Test
    void planeComesBackAtItsDepth() {
        PinholeCameraIntrinsic k = ImageCameraTest.intrinsic(W, H, 100, 100, 79.5, 59.5);
        try (RGBDImage frame = planeFrame();
             TSDFVolume volume = TSDFVolume.createUniform(1.0, 64, 0.04, Library.TSDF_VOLUME_COLOR_TYPE_RGB8,
                     new double[] {-0.5, -0.5, 0.5})) {
            volume.integrate(frame, k, IDENTITY);
            try (TriangleMesh mesh = volume.extractTriangleMesh()) {
                double[] v = mesh.getArray(Library.MESH_VERTICES);
                assertEquals(3 * 64 * 64, v.length);
                for (int i = 2; i < v.length; i += 3) assertEquals(1.0, v[i], 1e-4);
            }
            float[] tsdf = volume.extractVolumeTsdf();
            assertEquals(2 * 64 * 64 * 64, tsdf.length);
            assertEquals((1.0 - (0.5 + 30.5 / 64)) / 0.04, tsdf[2 * ((32 * 64 + 32) * 64 + 30)], 1e-4);
            assertFalse(volume.isScalable());
        }
        try (TSDFVolume scalable = TSDFVolume.createScalable(0.01, 0.04, Library.TSDF_VOLUME_COLOR_TYPE_RGB8, 16, 4)) {
            assertStatus(Library.ERROR_INVALID_ARGUMENT, scalable::extractVolumeTsdf);
        }
        assertStatus(Library.ERROR_INVALID_ARGUMENT,
                () -> TSDFVolume.createScalable(0.0, 0.04, Library.TSDF_VOLUME_COLOR_TYPE_NO_COLOR, 16, 4));
    }
}
