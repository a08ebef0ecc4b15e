// SPDX-License-Identifier: MIT
// TriangleMesh through the wrapper: primitives with analytic answers, arrays and views, clean-up,
// removal by index and mask, processing, PLY round trip in memory, errors as exceptions.
#include <cmath>
#include <cstdio>
#include <limits>

#include "test_util.hpp"

using o3dpp::Triangle;
using o3dpp::TriangleMesh;
using o3dpp::Vec3;

namespace {
TriangleMesh unit_square() {
    return TriangleMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
}
}  // namespace

TEST(TriangleMesh, BoxHasAnalyticAreaVolumeAndTopology) {
    const auto box = TriangleMesh::create_box();
    EXPECT_EQ(box.num_vertices(), 8u);
    EXPECT_EQ(box.num_triangles(), 12u);
    EXPECT_NEAR(box.get_surface_area(), 6.0, 1e-12);
    EXPECT_NEAR(box.get_volume(), 1.0, 1e-12);
    EXPECT_TRUE(box.is_watertight());
    EXPECT_TRUE(box.is_edge_manifold(false));
    EXPECT_TRUE(box.is_vertex_manifold());
    EXPECT_TRUE(box.is_orientable());
    EXPECT_FALSE(box.is_self_intersecting());
    EXPECT_EQ(box.euler_poincare_characteristic(), 2);
    const auto bb = box.get_axis_aligned_bounding_box();
    EXPECT_EQ(bb[0], (Vec3{0, 0, 0}));
    EXPECT_EQ(bb[1], (Vec3{1, 1, 1}));

    const auto slab = TriangleMesh::create_box(2, 3, 0.5);
    EXPECT_NEAR(slab.get_surface_area(), 2 * (6 + 1 + 1.5), 1e-12);
    EXPECT_NEAR(slab.get_volume(), 3.0, 1e-12);
}

TEST(TriangleMesh, PlatonicSolidsAndRoundPrimitives) {
    struct Case {
        TriangleMesh mesh;
        std::size_t v, f;
    };
    Case cases[] = {{TriangleMesh::create_tetrahedron(), 4, 4},
                    {TriangleMesh::create_octahedron(), 6, 8},
                    {TriangleMesh::create_icosahedron(), 12, 20}};
    for (const auto& c : cases) {
        EXPECT_EQ(c.mesh.num_vertices(), c.v);
        EXPECT_EQ(c.mesh.num_triangles(), c.f);
        EXPECT_EQ(c.mesh.euler_poincare_characteristic(), 2);
        const auto v = c.mesh.vertices();
        for (std::size_t i = 0; i < v.size(); ++i) EXPECT_NEAR(std::hypot(v[i][0], v[i][1], v[i][2]), 1.0, 1e-12);
    }
    EXPECT_NEAR(TriangleMesh::create_octahedron().get_volume(), 4.0 / 3.0, 1e-12);
    const auto sphere = TriangleMesh::create_sphere(2.0);
    EXPECT_TRUE(sphere.is_watertight());
    const double exact = 4.0 / 3.0 * M_PI * 8.0;
    EXPECT_LT(sphere.get_volume(), exact);
    EXPECT_GT(sphere.get_volume(), 0.95 * exact);
    EXPECT_EQ(TriangleMesh::create_torus().euler_poincare_characteristic(), 0);
    EXPECT_TRUE(TriangleMesh::create_cylinder().is_watertight());
    EXPECT_TRUE(TriangleMesh::create_cone().is_watertight());
    EXPECT_GT(TriangleMesh::create_arrow().num_triangles(), 0u);
    EXPECT_TRUE(TriangleMesh::create_coordinate_frame(1.0, {1, 2, 3}).has_vertex_colors());
}

TEST(TriangleMesh, BadParametersThrow) {
    EXPECT_O3D_ERROR(TriangleMesh::create_box(-1, 1, 1), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(TriangleMesh::create_sphere(1.0, 0), O3D_ERROR_INVALID_ARGUMENT);
    auto mesh = unit_square();
    mesh.set_triangles({{0, 1, 9}});
    EXPECT_O3D_ERROR(mesh.get_surface_area(), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(mesh.compute_vertex_normals(), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(mesh.sample_points_uniformly(10), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(TriangleMesh().merge_close_vertices(-1.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(mesh.texture(0), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(TriangleMesh, ArraysViewsAndCopies) {
    auto mesh = unit_square();
    EXPECT_TRUE(mesh.has_vertices());
    EXPECT_TRUE(mesh.has_triangles());
    EXPECT_FALSE(mesh.has_vertex_normals());
    EXPECT_EQ(mesh.get_triangles(), (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(mesh.triangles().size(), 2u);
    EXPECT_EQ(mesh.triangles()[1][2], 3);
    mesh.set_vertex_colors(std::vector<Vec3>(4, Vec3{1, 0, 0}));
    EXPECT_TRUE(mesh.has_vertex_colors());
    mesh.set_vertex_normals(std::vector<Vec3>(3, Vec3{0, 0, 1}));  // wrong row count: does not count
    EXPECT_FALSE(mesh.has_vertex_normals());
    std::vector<o3dpp::Vec2> uvs{{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    mesh.set_triangle_uvs(uvs);
    EXPECT_TRUE(mesh.has_triangle_uvs());
    EXPECT_EQ(mesh.get_triangle_uvs(), uvs);
    EXPECT_EQ(mesh.triangle_uvs().size(), 12u);
    mesh.set_triangle_material_ids({0, 3});
    EXPECT_TRUE(mesh.has_triangle_material_ids());
    EXPECT_EQ(mesh.get_triangle_material_ids(), (std::vector<int32_t>{0, 3}));

    mesh.vertices_mutable()[2][0] = 2.0;
    mesh.array_mutable(o3dpp::MeshArray::VertexColors)[0][1] = 1.0;
    mesh.triangles_mutable()[1][1] = 3;
    EXPECT_EQ(mesh.get_vertices()[2], (Vec3{2, 1, 0}));
    EXPECT_EQ(mesh.get_vertex_colors()[0], (Vec3{1, 1, 0}));
    EXPECT_EQ(mesh.get_triangles()[1], (Triangle{0, 3, 3}));

    const auto copy = mesh.clone();
    mesh.clear();
    EXPECT_EQ(mesh.num_vertices(), 0u);
    EXPECT_TRUE(mesh.vertices().empty());
    EXPECT_EQ(copy.num_triangles(), 2u);
}

TEST(TriangleMesh, NormalsTransformsAndTextures) {
    auto mesh = unit_square();
    mesh.compute_triangle_normals().compute_vertex_normals();
    for (const auto& n : mesh.get_vertex_normals()) EXPECT_EQ(n, (Vec3{0, 0, 1}));
    for (const auto& n : mesh.get_triangle_normals()) EXPECT_EQ(n, (Vec3{0, 0, 1}));
    mesh.normalize_normals().paint_uniform_color({0.25, 0.5, 0.75});
    for (const auto& c : mesh.get_vertex_colors()) EXPECT_EQ(c, (Vec3{0.25, 0.5, 0.75}));

    auto box = TriangleMesh::create_box();
    EXPECT_EQ(box.get_center(), (Vec3{0.5, 0.5, 0.5}));
    box.translate({1, 2, 3});
    EXPECT_EQ(box.get_min_bound(), (Vec3{1, 2, 3}));
    box.translate({0, 0, 0}, false).scale(2.0);
    EXPECT_EQ(box.get_max_bound(), (Vec3{1, 1, 1}));
    box.scale(0.5, {0, 0, 0}).rotate({0, -1, 0, 1, 0, 0, 0, 0, 1}, {0, 0, 0});  // 90 deg about z
    box.rotate({1, 0, 0, 0, 1, 0, 0, 0, 1});
    auto t = o3dpp::identity4();
    t[11] = 10.0;
    box.transform(t);
    EXPECT_NEAR(box.get_min_bound()[2], 9.5, 1e-12);

    auto tex = o3dpp::Image::from_values<uint8_t>(2, 2, {1, 2, 3, 4});
    mesh.add_texture(tex);
    EXPECT_EQ(mesh.texture_count(), 1u);
    EXPECT_EQ(mesh.texture(0).to_bytes(), (std::vector<uint8_t>{1, 2, 3, 4}));
    mesh.clear_textures();
    EXPECT_EQ(mesh.texture_count(), 0u);
}

TEST(TriangleMesh, CleanUp) {
    TriangleMesh mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {5, 5, 5}},
                      {{0, 1, 2}, {3, 2, 1}, {1, 1, 2}, {2, 1, 0}});
    mesh.remove_duplicated_vertices();
    EXPECT_EQ(mesh.num_vertices(), 4u);
    mesh.remove_degenerate_triangles();
    EXPECT_EQ(mesh.num_triangles(), 3u);
    mesh.remove_duplicated_triangles();
    EXPECT_EQ(mesh.num_triangles(), 1u);
    mesh.remove_unreferenced_vertices();
    EXPECT_EQ(mesh.num_vertices(), 3u);
    EXPECT_NEAR(mesh.get_surface_area(), 0.5, 1e-15);

    TriangleMesh near({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1 + 1e-4, 1, 0}}, {{0, 1, 2}, {0, 1, 3}});
    near.merge_close_vertices(1e-3);
    EXPECT_EQ(near.num_vertices(), 3u);

    TriangleMesh fan({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 2}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    EXPECT_FALSE(fan.is_edge_manifold(true));
    fan.remove_non_manifold_edges();
    EXPECT_EQ(fan.num_triangles(), 2u);
    EXPECT_TRUE(fan.is_edge_manifold(true));
}

TEST(TriangleMesh, ClustersOfTwoPieces) {
    auto mesh = unit_square();
    auto box = TriangleMesh::create_box();
    box.translate({5, 0, 0});
    mesh += box;
    EXPECT_EQ(mesh.num_vertices(), 12u);
    const auto c = mesh.cluster_connected_triangles();
    ASSERT_EQ(c.triangle_clusters.size(), 14u);
    EXPECT_EQ(c.triangle_clusters[0], 0);
    EXPECT_EQ(c.triangle_clusters[13], 1);
    EXPECT_EQ(c.cluster_n_triangles, (std::vector<int32_t>{2, 12}));
    ASSERT_EQ(c.cluster_area.size(), 2u);
    EXPECT_NEAR(c.cluster_area[0], 1.0, 1e-12);
    EXPECT_NEAR(c.cluster_area[1], 6.0, 1e-12);
}

TEST(TriangleMesh, Processing) {
    const auto box = TriangleMesh::create_box();
    const auto a = box.sample_points_uniformly(300, true, 7);
    const auto b = box.sample_points_uniformly(300, true, 7);
    EXPECT_EQ(a.size(), 300u);
    EXPECT_EQ(a.get_points(), b.get_points());
    for (const auto& p : a.get_points()) {
        bool on_face = false;
        for (double c : p) on_face |= std::abs(c) < 1e-12 || std::abs(c - 1) < 1e-12;
        EXPECT_TRUE(on_face);
    }
    EXPECT_EQ(box.sample_points_poisson_disk(50).size(), 50u);

    const auto mid = box.subdivide_midpoint(1);
    EXPECT_EQ(mid.num_triangles(), 48u);
    EXPECT_EQ(mid.num_vertices(), 26u);
    EXPECT_NEAR(mid.get_surface_area(), 6.0, 1e-12);
    EXPECT_EQ(box.subdivide_loop(2).num_triangles(), 12u * 16u);

    const auto sphere = TriangleMesh::create_sphere();
    const std::size_t n = sphere.num_triangles();
    EXPECT_LE(sphere.simplify_quadric_decimation(n / 4).num_triangles(), n / 4);
    EXPECT_LT(sphere.simplify_vertex_clustering(0.5).num_vertices(), sphere.num_vertices());
    EXPECT_LT(sphere.simplify_vertex_clustering(0.5, o3dpp::SimplificationContraction::Quadric).num_vertices(),
              sphere.num_vertices());
    for (const auto& smooth : {sphere.filter_smooth_simple(1, o3dpp::FilterScope::Vertex),
                               sphere.filter_smooth_laplacian(2), sphere.filter_smooth_taubin(2)}) {
        EXPECT_EQ(smooth.num_vertices(), sphere.num_vertices());
        EXPECT_EQ(smooth.get_triangles(), sphere.get_triangles());
    }
    for (const auto& p : sphere.filter_smooth_simple(1, o3dpp::FilterScope::Vertex).get_vertices())
        EXPECT_LT(std::hypot(p[0], p[1], p[2]), 1.0 + 1e-12);

    const auto cropped = box.crop({-0.1, -0.1, -0.1}, {1.1, 1.1, 0.5});
    EXPECT_EQ(cropped.num_triangles(), 2u);
    EXPECT_EQ(cropped.num_vertices(), 4u);
}

TEST(TriangleMesh, PlyRoundTripInMemory) {
    auto mesh = TriangleMesh::create_box(1, 2, 3);
    mesh.compute_vertex_normals().paint_uniform_color({1, 0, 0});
    for (bool ascii : {false, true}) {
        o3dpp::MeshWriteOptions opts;
        opts.write_ascii = ascii;
        const auto buf = o3dpp::write_triangle_mesh_to_memory(mesh, "ply", opts);
        EXPECT_EQ(buf.to_string().substr(0, 3), "ply");
        const auto back = o3dpp::read_triangle_mesh_from_memory(buf.to_vector(), "ply");
        EXPECT_EQ(back.get_vertices(), mesh.get_vertices());
        EXPECT_EQ(back.get_triangles(), mesh.get_triangles());
        EXPECT_EQ(back.get_vertex_colors(), mesh.get_vertex_colors());
        EXPECT_TRUE(back.has_vertex_normals());
        EXPECT_NEAR(back.get_volume(), 6.0, 1e-12);
    }
}

TEST(TriangleMesh, FilesInEveryFormat) {
    const auto octa = TriangleMesh::create_octahedron();
    for (const char* ext : {"ply", "obj", "stl", "off", "glb"}) {
        const std::string path = o3dpp_test::tmp_path(std::string("trianglemesh_test.") + ext);
        o3dpp::write_triangle_mesh(path, octa);
        o3dpp::MeshReadOptions opts;
        opts.enable_post_processing = true;
        const auto back = o3dpp::read_triangle_mesh(path, "", opts);
        EXPECT_EQ(back.num_triangles(), 8u) << ext;
        EXPECT_EQ(back.num_vertices(), 6u) << ext;
        EXPECT_NEAR(back.get_surface_area(), 4 * std::sqrt(3.0), 1e-6) << ext;
        std::remove(path.c_str());
    }
    EXPECT_O3D_ERROR(o3dpp::read_triangle_mesh("/nonexistent/dir/x.ply"), O3D_ERROR_IO);
    EXPECT_O3D_ERROR(o3dpp::read_triangle_mesh_from_memory(std::vector<uint8_t>{1, 2, 3}, "nope"),
                     O3D_ERROR_UNSUPPORTED);
}

TEST(TriangleMesh, KnotFromSharedData) {
    O3DPP_DATA_OR_SKIP(path, "open3d/knot.ply");
    auto mesh = o3dpp::read_triangle_mesh(path);
    // Open3D 0.20 (tools/reference/record_mesh.py "knot.counts", "knot.area"): 1440 / 2880, 112072.277931022.
    EXPECT_EQ(mesh.num_vertices(), 1440u);
    EXPECT_EQ(mesh.num_triangles(), 2880u);
    EXPECT_NEAR(mesh.get_surface_area(), 112072.277931022, 1e-6);
    EXPECT_TRUE(mesh.is_watertight());
    mesh.remove_duplicated_vertices().remove_unreferenced_vertices();
    EXPECT_EQ(mesh.num_vertices(), 1440u);
    EXPECT_EQ(mesh.sample_points_uniformly(1000).size(), 1000u);
}

TEST(TriangleMesh, GenericArraysCoverIndexArrays) {
    auto mesh = TriangleMesh::create_box();
    EXPECT_EQ(mesh.array_shape(o3dpp::MeshArray::Triangles), (std::array<std::size_t, 2>{12, 3}));
    EXPECT_EQ(mesh.get_array<Triangle>(o3dpp::MeshArray::Triangles), mesh.get_triangles());
    EXPECT_EQ(mesh.get_array<int32_t>(o3dpp::MeshArray::Triangles).size(), 36u);
    EXPECT_EQ(mesh.array<int32_t>(o3dpp::MeshArray::Triangles).cols(), 3u);
    EXPECT_O3D_ERROR(mesh.get_array<o3dpp::Line>(o3dpp::MeshArray::Triangles), O3D_ERROR_INVALID_ARGUMENT);
    // A float64 row type on an index array reaches the C call, which refuses it.
    EXPECT_O3D_ERROR(mesh.get_array<Vec3>(o3dpp::MeshArray::Triangles), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(TriangleMesh, MobiusUsesTheLibraryDefaults) {
    o3d_mobius_options_t lib;
    o3dpp::check(o3d_mobius_options_init(&lib, sizeof lib));
    const o3dpp::MobiusOptions defaults;
    EXPECT_EQ(defaults.length_split, lib.length_split);
    EXPECT_EQ(defaults.twists, lib.twists);
    const auto strip = TriangleMesh::create_mobius();
    EXPECT_EQ(strip.num_vertices(), static_cast<std::size_t>(lib.length_split * lib.width_split));
    o3dpp::MobiusOptions bad;
    bad.length_split = 1;
    EXPECT_O3D_ERROR(TriangleMesh::create_mobius(bad), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(TriangleMesh, RemoveByIndexAndMask) {
    // The unit square (two triangles) and a third triangle out to (2, 0, 0); colors tell the vertices apart.
    const TriangleMesh mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}}, {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}});
    TriangleMesh colored = mesh.clone();
    colored.set_vertex_colors({{0, 0, 0}, {0.1, 0, 0}, {0.2, 0, 0}, {0.3, 0, 0}, {0.4, 0, 0}});

    TriangleMesh a = colored.clone();
    a.remove_vertices_by_index({4, 4});  // repeats allowed
    EXPECT_EQ(a.get_triangles(), (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(a.get_vertex_colors(), (std::vector<Vec3>{{0, 0, 0}, {0.1, 0, 0}, {0.2, 0, 0}, {0.3, 0, 0}}));

    TriangleMesh b = colored.clone();
    b.remove_vertices_by_mask({false, false, false, true, false});
    EXPECT_EQ(b.get_vertices(), (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}}));
    EXPECT_EQ(b.get_triangles(), (std::vector<Triangle>{{0, 1, 2}, {1, 3, 2}}));
    EXPECT_EQ(b.get_vertex_colors()[3], (Vec3{0.4, 0, 0}));

    TriangleMesh c = mesh.clone();
    c.remove_triangles_by_index({0});
    EXPECT_EQ(c.num_vertices(), 5u);
    EXPECT_EQ(c.get_triangles(), (std::vector<Triangle>{{0, 2, 3}, {1, 4, 2}}));
    c.remove_triangles_by_mask({false, true});
    EXPECT_EQ(c.get_triangles(), (std::vector<Triangle>{{0, 2, 3}}));

    // Bad input throws and leaves the mesh as it was.
    TriangleMesh d = mesh.clone();
    EXPECT_O3D_ERROR(d.remove_vertices_by_index({5}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(d.remove_vertices_by_mask({true, false}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(d.remove_triangles_by_index({-1}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(d.remove_triangles_by_mask({true, false, false, false}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(d.get_vertices(), mesh.get_vertices());
    EXPECT_EQ(d.get_triangles(), mesh.get_triangles());
}
