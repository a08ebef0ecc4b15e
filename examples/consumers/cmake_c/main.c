/* A C program built against an installed o3d, through find_package(o3d) (CMakeLists.txt here) and through
 * pkg-config (scripts/check_consumers.sh): down-sample a synthetic cloud. */
#include <o3d/o3d.h>
#include <stdio.h>

int main(void) {
    double xyz[3 * 1000];
    for (int i = 0; i < 1000; ++i) { /* a 10 x 10 x 10 grid with spacing 1 */
        xyz[3 * i] = i % 10;
        xyz[3 * i + 1] = (i / 10) % 10;
        xyz[3 * i + 2] = i / 100;
    }
    o3d_pointcloud_t *pc = NULL, *down = NULL;
    size_t n = 0;
    if (o3d_pointcloud_create(&pc) != O3D_OK ||
        o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 1000) != O3D_OK ||
        o3d_pointcloud_voxel_down_sample(&down, pc, 2.0) != O3D_OK || o3d_pointcloud_size(&n, down) != O3D_OK) {
        fprintf(stderr, "o3d failed: %s\n", o3d_last_error_message());
        return 1;
    }
    /* As Open3D, voxels start half a voxel below the minimum: 0 | 1 2 | 3 4 | ... | 9 gives 6 per axis. */
    printf("o3d %s: 1000 points -> %zu after voxel_down_sample(2)\n", o3d_version(), n);
    o3d_pointcloud_destroy(down);
    o3d_pointcloud_destroy(pc);
    /* Bad input is an error, not a crash. */
    if (o3d_pointcloud_voxel_down_sample(&down, NULL, 0.2) != O3D_ERROR_INVALID_ARGUMENT) return 1;
    return n == 216 ? 0 : 1;
}
