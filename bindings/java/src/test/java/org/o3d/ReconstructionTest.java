// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The reconstruction system from Java: a stage run on a dataset written here (three frames of a textured plane 1 m
 * away, the camera sliding 1 cm a frame), progress rising to 1, cancelling, and errors naming the stage to run first.
 * (The known-trajectory run is tests/capi/test_reconstruction.c; the living-room run is the Python test.)
 */
class ReconstructionTest {
    static final int W = 96, H = 72;

    /** A dataset below {@code folder} in Open3D's layout and the config that reconstructs it into folder/out. */
    static Path writePlaneDataset(Path folder) throws IOException {
        Files.createDirectories(folder.resolve("data/color"));
        Files.createDirectories(folder.resolve("data/depth"));
        for (int k = 0; k < 3; k++) {
            byte[] rgb = new byte[3 * W * H];
            short[] depth = new short[W * H];
            for (int v = 0; v < H; v++)
                for (int u = 0; u < W; u++) {
                    double x = (u - W / 2.0) / 80.0 + 0.01 * k, y = (v - H / 2.0) / 80.0;
                    for (int c = 0; c < 3; c++)
                        rgb[3 * (v * W + u) + c] = (byte) (128 + 100 * Math.sin(9.0 * x + 2.0 * c) * Math.cos(7.0 * y - c));
                    depth[v * W + u] = 1000;
                }
            String name = String.format("%05d.png", k);
            try (Image color = Image.createFromData(W, H, 3, 1, rgb); Image d = Images.fromUInt16(W, H, 1, depth)) {
                Library.ioWriteImage(folder.resolve("data/color/" + name).toString(), color, "", -1);
                Library.ioWriteImage(folder.resolve("data/depth/" + name).toString(), d, "", -1);
            }
        }
        Library.ioWritePinholeCameraIntrinsic(folder.resolve("intrinsic.json").toString(),
                ImageCameraTest.intrinsic(W, H, 80, 80, 47.5, 35.5));
        Path config = folder.resolve("config.json");
        Files.writeString(config, "{\"path_dataset\": \"" + folder + "/data\", \"path_intrinsic\": \"" + folder
                + "/intrinsic.json\", \"path_output\": \"" + folder + "/out\", \"n_frames_per_fragment\": 3, "
                + "\"n_keyframes_per_n_frame\": 1, \"tsdf_cubic_size\": 4.0}");
        return config;
    }

    @Test
    void stageRunsReportsProgressCancelsAndNamesTheStageToRunFirst() throws IOException {
        Path folder = Files.createTempDirectory("o3d_java_reconstruction");
        String config = writePlaneDataset(folder).toString();
        try (ReconstructionOptions o = new ReconstructionOptions()) {
            assertEquals(1, o.getResume());
            assertEquals(0, o.getNumThreads());
            double[] last = {-1};
            boolean[] rising = {true};
            o.setProgress(f -> {
                rising[0] &= f >= last[0];
                last[0] = f;
                return true;
            });
            Library.reconstructionRunStage(config, Library.RECONSTRUCTION_STAGE_MAKE_FRAGMENTS, o);
            assertEquals(1.0, last[0]);
            assertTrue(rising[0]);
            Path fragment = folder.resolve("out/fragments/fragment_000.ply");
            assertTrue(Files.exists(fragment));
            o.setResume(0);
            o.setProgress(f -> false);
            assertStatus(Library.ERROR_CANCELLED,
                    () -> Library.reconstructionRunStage(config, Library.RECONSTRUCTION_STAGE_MAKE_FRAGMENTS, o));
            assertTrue(Files.exists(fragment), "finished outputs stay");
        }
        O3dException e = assertStatus(Library.ERROR_IO,
                () -> Library.reconstructionRunStage(config, Library.RECONSTRUCTION_STAGE_INTEGRATE_SCENE, null));
        assertTrue(e.getMessage().contains("run the \"refine registration\" stage first"), e.getMessage());
        try (Stream<Path> walk = Files.walk(folder)) {
            walk.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
    }
}
