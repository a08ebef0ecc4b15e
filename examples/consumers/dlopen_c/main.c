/* A C program that links nothing of o3d: it dlopen()s the installed library named on its command line
 * and calls it through function pointers typed from the installed headers. */
#include <dlfcn.h>
#include <o3d/o3d.h>
#include <stdio.h>

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s <prefix>/lib/libo3d.so.0\n", argv[0]);
        return 2;
    }
    void* lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        fprintf(stderr, "dlopen: %s\n", dlerror());
        return 1;
    }
    const char* (*version)(void);
    int32_t (*major)(void);
    o3d_status (*create)(o3d_pointcloud_t**);
    o3d_status (*set_array)(o3d_pointcloud_t*, int32_t, const double*, size_t);
    o3d_status (*size)(size_t*, const o3d_pointcloud_t*);
    void (*destroy)(o3d_pointcloud_t*);
    *(void**)&version = dlsym(lib, "o3d_version");
    *(void**)&major = dlsym(lib, "o3d_version_major");
    *(void**)&create = dlsym(lib, "o3d_pointcloud_create");
    *(void**)&set_array = dlsym(lib, "o3d_pointcloud_set_array");
    *(void**)&size = dlsym(lib, "o3d_pointcloud_size");
    *(void**)&destroy = dlsym(lib, "o3d_pointcloud_destroy");
    if (!version || !major || !create || !set_array || !size || !destroy) {
        fprintf(stderr, "dlsym: a function is missing\n");
        return 1;
    }
    const double xyz[6] = {0, 0, 0, 1, 2, 3};
    o3d_pointcloud_t* pc = NULL;
    size_t n = 0;
    if (create(&pc) != O3D_OK || set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 2) != O3D_OK || size(&n, pc) != O3D_OK)
        return 1;
    destroy(pc);
    printf("dlopen %s: o3d %s, %zu points\n", argv[1], version(), n);
    /* The library loaded must be the major version these headers describe. */
    return (n == 2 && major() == O3D_VERSION_MAJOR) ? 0 : 1;
}
