/* SPDX-License-Identifier: MIT */
/* Figure 1 through dlopen/dlsym only (no link-time dependency on libo3d): read, voxel down-sample
 * (0.05), estimate normals (hybrid 0.1 / 30), write. The headers are used for the types only.
 * Usage: dlopen_loader <input> <output> [path/to/libo3d.so.0] */
#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

#include "o3d/o3d.h"

#ifndef O3D_LIB_PATH
#define O3D_LIB_PATH "libo3d.so.0"
#endif

/* The entry points this program needs, resolved at run time; their types come from the headers'
 * declarations, so a signature change there cannot go unnoticed here. */
#define API_FN(field, fn) __typeof__(&fn) field
struct api {
    API_FN(version, o3d_version);
    API_FN(version_major, o3d_version_major);
    API_FN(last_error_message, o3d_last_error_message);
    API_FN(status_string, o3d_status_string);
    API_FN(read, o3d_io_read_point_cloud);
    API_FN(write, o3d_io_write_point_cloud);
    API_FN(size, o3d_pointcloud_size);
    API_FN(voxel_down_sample, o3d_pointcloud_voxel_down_sample);
    API_FN(search_param_init, o3d_search_param_init);
    API_FN(estimate_normals, o3d_pointcloud_estimate_normals);
    API_FN(has_array, o3d_pointcloud_has_array);
    API_FN(destroy, o3d_pointcloud_destroy);
};

/* dlsym `name` into the function pointer at `slot`; 0 on failure. */
static int load(void* lib, const char* name, void* slot, size_t slot_size) {
    void* p;
    dlerror();
    p = dlsym(lib, name);
    if (!p) {
        fprintf(stderr, "dlopen_loader: dlsym(%s): %s\n", name, dlerror());
        return 0;
    }
    memcpy(slot, &p, slot_size); /* object → function pointer, as POSIX allows */
    return 1;
}
#define LOAD(lib, field, name) load((lib), (name), &api->field, sizeof api->field)

static int load_api(void* lib, struct api* api) {
    return LOAD(lib, version, "o3d_version") && LOAD(lib, version_major, "o3d_version_major") &&
           LOAD(lib, last_error_message, "o3d_last_error_message") && LOAD(lib, status_string, "o3d_status_string") &&
           LOAD(lib, read, "o3d_io_read_point_cloud") && LOAD(lib, write, "o3d_io_write_point_cloud") &&
           LOAD(lib, size, "o3d_pointcloud_size") && LOAD(lib, voxel_down_sample, "o3d_pointcloud_voxel_down_sample") &&
           LOAD(lib, search_param_init, "o3d_search_param_init") &&
           LOAD(lib, estimate_normals, "o3d_pointcloud_estimate_normals") &&
           LOAD(lib, has_array, "o3d_pointcloud_has_array") && LOAD(lib, destroy, "o3d_pointcloud_destroy");
}

static int report(const struct api* api, const char* what, o3d_status status) {
    fprintf(stderr, "dlopen_loader: %s failed: %s: %s\n", what, api->status_string(status), api->last_error_message());
    return 1;
}

static int run(const struct api* api, const char* in, const char* out) {
    o3d_pointcloud_t *cloud = NULL, *down = NULL;
    o3d_search_param_t param;
    size_t n_in = 0, n_out = 0;
    int32_t has_normals = 0;
    o3d_status s;
    int rc = 1;
    if ((s = api->read(&cloud, in, NULL, NULL)) != O3D_OK) return report(api, "read", s);
    if ((s = api->size(&n_in, cloud)) != O3D_OK) {
        report(api, "size", s);
    } else if ((s = api->voxel_down_sample(&down, cloud, 0.05)) != O3D_OK) {
        report(api, "voxel_down_sample", s);
    } else if ((s = api->size(&n_out, down)) != O3D_OK) {
        report(api, "size", s);
    } else if ((s = api->search_param_init(&param, sizeof param)) != O3D_OK) {
        report(api, "search_param_init", s);
    } else {
        param.kind = O3D_SEARCH_HYBRID;
        param.radius = 0.1;
        param.knn = 30;
        printf("voxel_down_sample(0.05): %zu -> %zu points\n", n_in, n_out);
        if ((s = api->estimate_normals(down, &param, 0)) != O3D_OK) {
            report(api, "estimate_normals", s);
        } else if ((s = api->has_array(&has_normals, down, O3D_POINTCLOUD_NORMALS)) != O3D_OK) {
            report(api, "has_normals", s);
        } else if ((s = api->write(out, down, NULL, NULL)) != O3D_OK) {
            report(api, "write", s);
        } else {
            printf("estimate_normals(hybrid radius=0.1 max_nn=30): normals %s\n", has_normals ? "yes" : "no");
            printf("wrote %zu points with normals to %s\n", n_out, out);
            rc = has_normals && n_out > 0 ? 0 : 1;
        }
    }
    api->destroy(down);
    api->destroy(cloud);
    return rc;
}

int main(int argc, char** argv) {
    const char* path = argc > 3 ? argv[3] : O3D_LIB_PATH;
    struct api api;
    void* lib;
    if (argc != 3 && argc != 4) {
        fprintf(stderr, "usage: %s <input> <output> [path/to/libo3d.so.0]\n", argv[0]);
        return 2;
    }
    lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        fprintf(stderr, "dlopen_loader: dlopen(%s): %s\n", path, dlerror());
        return 1;
    }
    if (!load_api(lib, &api)) return 1;
    if (api.version_major() != O3D_VERSION_MAJOR) {
        fprintf(stderr, "dlopen_loader: %s is o3d %s, built against major %d\n", path, api.version(), O3D_VERSION_MAJOR);
        return 1;
    }
    printf("loaded %s (o3d %s)\n", path, api.version());
    /* No dlclose: a process that ran parallel code keeps the library (it is linked -z nodelete anyway). */
    return run(&api, argv[1], argv[2]);
}
