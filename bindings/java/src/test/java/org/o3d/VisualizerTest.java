// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Visualizer in a hidden window (EGL: no display needed), the scenarios of tests/capi/test_visualizer.c and
 * bindings/csharp/tests/VisualizerTest.cs: the default view against Open3D's ViewControl model, a key callback
 * by its effect on the captured image, an animation callback turning the view, a callback's exception coming
 * out of run(), trajectory playback, and calls without a window.
 */
class VisualizerTest {
    @TempDir
    Path tmp;

    static final int W = 160, H = 120;

    /** A hidden visualizer showing a unit cube centred at the origin, unlit: its pixels have exactly its colour. */
    static Visualizer cubeViewer(double[] color) {
        Visualizer v = Visualizer.create(0);
        v.createWindow("test", W, H, -1, -1, 0);
        try (TriangleMesh cube = TriangleMesh.createBox(1, 1, 1)) {
            cube.translate(new double[] {-0.5, -0.5, -0.5}, 1);
            cube.paintUniformColor(color);
            v.addTrianglemesh("cube", cube, 1);
        }
        try (RenderOption o = v.getRenderOption()) {
            o.setLightOn(0);
            v.setRenderOption(o);
        }
        return v;
    }

    static double[] screenAt(Visualizer v, int u, int y) {
        try (Image img = v.captureScreenFloatBuffer(1)) {
            float[] f = Images.toFloatArray(img);
            int i = 3 * (y * W + u);
            return new double[] {f[i], f[i + 1], f[i + 2]};
        }
    }

    static double[] front(Visualizer v) {
        try (ViewGetResult g = v.viewGet()) {
            return g.front();
        }
    }

    @Test
    void defaultViewDepthAndViewStatus() {
        try (Visualizer v = cubeViewer(new double[] {1, 0, 0})) {
            assertArrayEquals(new double[] {1, 1, 1}, screenAt(v, 0, 0), 0, "white background");
            assertArrayEquals(new double[] {1, 0, 0}, screenAt(v, W / 2, H / 2), 0, "the cube's colour");
            // Open3D's default view: the eye on +z at zoom * extent / tan(30 deg) from the centre; the front face
            // (z = 0.5) is 0.5 nearer.
            double expected = 0.7 / Math.tan(Math.PI / 6) - 0.5;
            try (Image depth = v.captureDepthFloatBuffer(1)) {
                assertEquals(expected, Images.toFloatArray(depth)[H / 2 * W + W / 2], 1e-3 * expected);
            }
            assertEquals(60, v.viewGetFieldOfView(), 1e-12);
            String status = v.getViewStatus();
            assertTrue(status.contains("\"class_name\": \"ViewTrajectory\""), status);
            v.viewRotate(100, 0);
            v.setViewStatus(status);
            assertArrayEquals(new double[] {0, 0, 1}, front(v), 1e-9, "front from the status");
            assertEquals(0, v.getPickedPoints().length);
            assertTrue(v.pollEvents());
        }
    }

    @Test
    void keyCallbackPaintsTheBackground() {
        try (Visualizer v = cubeViewer(new double[] {1, 0, 0})) {
            int[] calls = {0};
            v.registerKeyCallback('K', vis -> {
                calls[0]++;
                try (RenderOption o = vis.getRenderOption()) {
                    o.setBackgroundColor(new double[] {0, 0, 0});
                    vis.setRenderOption(o);
                }
                return true;
            });
            v.sendKey('K', Library.KEY_ACTION_RELEASE, 0);
            assertEquals(0, calls[0], "not on release");
            v.sendKey('K', Library.KEY_ACTION_PRESS, 0);
            assertEquals(1, calls[0]);
            assertArrayEquals(new double[] {0, 0, 0}, screenAt(v, 0, 0), 0, "black background");
            List<Integer> actions = new ArrayList<>();
            v.registerKeyActionCallback('K', (vis, action, mods) -> actions.add(action * 10 + mods) && false);
            v.sendKey('K', Library.KEY_ACTION_RELEASE, Library.KEY_MOD_SHIFT);
            assertEquals(List.of(Library.KEY_ACTION_RELEASE * 10 + Library.KEY_MOD_SHIFT), actions);
            v.registerKeyCallback('K', null);
            v.sendKey('K', Library.KEY_ACTION_PRESS, 0);
            assertEquals(1, calls[0]);
            assertEquals(1, actions.size());
        }
    }

    @Test
    void animationCallbackTurnsTheView() {
        try (Visualizer v = cubeViewer(new double[] {0, 0, 1})) {
            int[] frames = {0};
            v.registerAnimationCallback(vis -> {
                vis.viewRotate(10, 0);
                if (++frames[0] == 5) vis.closeWindow();
                return true;
            });
            v.run();
            assertEquals(5, frames[0]);
            // five turns of 10 px at 0.003 rad per pixel about the up axis: 0.15 rad in all
            assertArrayEquals(new double[] {-Math.sin(0.15), 0, Math.cos(0.15)}, front(v), 1e-9);
        }
    }

    @Test
    void callbackExceptionComesOutOfRun() {
        try (Visualizer v = cubeViewer(new double[] {0, 1, 0})) {
            IllegalStateException thrown = new IllegalStateException("spin failed on purpose");
            int[] frames = {0};
            v.registerAnimationCallback(vis -> {
                if (++frames[0] == 2) throw thrown;
                return false;
            });
            assertSame(thrown, assertThrows(IllegalStateException.class, v::run));
            assertEquals(2, frames[0]);
            v.registerAnimationCallback(null);
            v.run(); // no callback: one frame, and the visualizer still works
            v.registerKeyCallback('E', vis -> {
                throw new IllegalArgumentException("key failed");
            });
            assertThrows(IllegalArgumentException.class, () -> v.sendKey('E', Library.KEY_ACTION_PRESS, 0));
            assertInvalid(() -> v.registerKeyCallback(-1, vis -> true));
        }
        Visualizer v = Visualizer.create(0);
        assertInvalid(v::run);
        assertInvalid(() -> v.captureScreenFloatBuffer(1));
        v.close();
        assertThrows(IllegalStateException.class, v::run);
    }

    @Test
    void trajectoryPlayback() throws Exception {
        // two key views, two frames between: four frames, each captured
        String view = "{\"boundingbox_max\": [0.5, 0.5, 0.5], \"boundingbox_min\": [-0.5, -0.5, -0.5], "
                + "\"field_of_view\": 60.0, \"front\": [F], \"lookat\": [0, 0, 0], \"up\": [0, 1, 0], \"zoom\": 0.7}";
        Path path = tmp.resolve("trajectory.json");
        Files.writeString(path, "{\"class_name\": \"ViewTrajectory\", \"interval\": 2, \"is_loop\": false, \"trajectory\": ["
                + view.replace("F", "0, 0, 1") + ", " + view.replace("F", "1, 0, 0") + "]}");
        try (Visualizer v = cubeViewer(new double[] {1, 0, 0})) {
            List<Double> fractions = new ArrayList<>();
            v.playViewTrajectory(path.toString(), tmp.toString(), 1, f -> fractions.add(f));
            assertEquals(4, fractions.size());
            assertEquals(1.0, fractions.get(3));
            assertArrayEquals(new double[] {1, 0, 0}, front(v), 1e-12, "ends on the last key view");
            assertTrue(Files.exists(tmp.resolve("image_000003.png")) && Files.exists(tmp.resolve("depth_000003.png")));
            assertStatus(Library.ERROR_CANCELLED, () -> v.playViewTrajectory(path.toString(), null, 0, f -> false));
        }
    }
}
