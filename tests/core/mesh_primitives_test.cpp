// SPDX-License-Identifier: MIT
// The create_* primitives: Open3D 0.20's counts, bounds, areas and layout (recorded by
// tools/reference/record_primitives.py), analytic areas and volumes, outward winding, closed surfaces,
// and argument checks.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "o3d/geometry/mesh_primitives.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"

namespace {

using o3d::geometry::TriangleMesh;
namespace g = o3d::geometry;
const double kPi = 3.14159265358979323846;

double area(const TriangleMesh& m) {
    double a = 0;
    for (size_t t = 0; t < m.triangles.size(); ++t) a += g::triangle_area(m, t);
    return a;
}

/// @brief Sum of the tetrahedra (origin, a, b, c): the enclosed volume when the triangles wind outward.
double signed_volume(const TriangleMesh& m) {
    double v = 0;
    for (const auto& t : m.triangles) v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
    return v;
}

/// @brief Every directed edge is used once and its reverse once: closed, and consistently oriented.
bool closed_and_oriented(const TriangleMesh& m) {
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    for (const auto& [e, n] : directed) {
        const auto rev = directed.find({e.second, e.first});
        if (n != 1 || rev == directed.end() || rev->second != 1) return false;
    }
    return true;
}

long euler_characteristic(const TriangleMesh& m) {
    std::map<std::pair<int, int>, int> edges;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) edges[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}] = 1;
    return long(m.vertices.size()) - long(edges.size()) + long(m.triangles.size());
}

struct Reference {
    const char* name;
    std::function<TriangleMesh()> make;
    size_t vertices, triangles;
    double area;
    double min[3], max[3];
    double vertex_fingerprint[3];
    long triangle_fingerprint[3];
    double scale;  // o3d's size over Open3D's (1 but for the icosahedron; see IcosahedronRadiusIsItsCircumradius)
};

// Recorded by tools/reference/record_primitives.py with Open3D 0.20.
const double kIco = 1.0 / std::sqrt(1.0 + std::pow((1.0 + std::sqrt(5.0)) / 2.0, 2));
const Reference kReferences[] = {
    {"box(1, 1, 1)", [] { return g::create_box(); }, 8, 12, 6.0, {0, 0, 0}, {1, 1, 1}, {20, 26, 22}, {91, 352, 336}, 1},
    {"box(1, 2, 3)", [] { return g::create_box(1, 2, 3); }, 8, 12, 22.0, {0, 0, 0}, {1, 2, 3}, {20, 52, 66}, {91, 352, 336}, 1},
    {"sphere(1, 20)", [] { return g::create_sphere(); }, 762, 1520, 12.501878921475342, {-1, -1, -1}, {1, 1, 1},
     {-254.12409472350157, -3228.952775951766, -113959.11103807083}, {587234480, 565406900, 542366180}, 1},
    {"sphere(2, 3)", [] { return g::create_sphere(2, 3); }, 14, 24, 39.519603686021725,
     {-1.7320508075688774, -1.5000000000000009, -2.0}, {1.7320508075688774, 1.5000000000000002, 2.0},
     {-10.392304845413298, -17.999999999999996, -37.999999999999964}, {2443, 2336, 1682}, 1},
    {"cylinder(1, 2, 20, 4)", [] { return g::create_cylinder(); }, 102, 200, 18.69509709071738, {-1, -1, -1}, {1, 1, 1},
     {-50.00000000000024, -315.6875757337522, -2001.0}, {1356780, 1206630, 1014550}, 1},
    {"cylinder(0.5, 3, 7, 2)", [] { return g::create_cylinder(0.5, 3, 7, 2); }, 23, 42, 10.479763615787775,
     {-0.4504844339512096, -0.4874639560909118, -1.5}, {0.5, 0.4874639560909118, 1.5},
     {-5.250000000000004, -10.901737332004766, -148.5}, {13335, 11746, 8988}, 1},
    {"cone(1, 2, 20, 1)", [] { return g::create_cone(); }, 22, 40, 10.068990563677295, {-1, -1, 0}, {1, 1, 2},
     {-10.00000000000001, -63.13751514675043, 4.0}, {420, 11710, 11710}, 1},
    {"cone(0.5, 3, 7, 3)", [] { return g::create_cone(0.5, 3, 7, 3); }, 23, 42, 5.29095841288481,
     {-0.4504844339512096, -0.4874639560909118, 0.0}, {0.5, 0.4874639560909118, 3.0},
     {-3.5000000000000018, -7.267824888003178, 377.0}, {13167, 11914, 8988}, 1},
    {"torus(1, 0.5, 30, 20)", [] { return g::create_torus(); }, 600, 1200, 19.56851568284109,
     {-1.5, -1.49178284305241, -0.5}, {1.5, 1.49178284305241, 0.5},
     {-6000.000000000067, -57086.1867253355, -947.0627272012558}, {280859500, 273876700, 287808100}, 1},
    {"torus(2, 0.25, 5, 4)", [] { return g::create_torus(2, 0.25, 5, 4); }, 20, 40, 15.121092911683268,
     {-1.820288237343632, -2.1398771616640957, -0.25}, {2.25, 2.1398771616640953, 0.25},
     {-80.00000000000003, -110.11055363769387, -2.4999999999999982}, {9170, 7770, 10390}, 1},
    {"arrow(1, 1.5, 5, 4, 20, 4, 1)", [] { return g::create_arrow(); }, 124, 240, 64.43849822000266, {-1.5, -1.5, 0},
     {1.5, 1.5, 9}, {-65.00000000000037, -410.39384845387804, 21031.0}, {2260840, 2209980, 2017900}, 1},
    {"arrow(0.5, 1, 2, 1, 6, 2, 2)", [] { return g::create_arrow(0.5, 1, 2, 1, 6, 2, 2); }, 34, 60, 13.86574128362686,
     {-1.0, -0.866025403784439, 0.0}, {1.0, 0.8660254037844387, 3.0},
     {-9.000000000000053, -15.588457268119896, 1023.5}, {38967, 39713, 35963}, 1},
    {"coordinate_frame(1, [0, 0, 0])", [] { return g::create_coordinate_frame(); }, 1134, 2240, 0.7441863985758009,
     {-0.06, -0.06, -0.06}, {1, 1, 1}, {47939.965238257115, 55027.875517383356, 55650.466021656255},
     {1881619160, 1864285400, 1832220440}, 1},
    {"coordinate_frame(2, [1, 2, 3])", [] { return g::create_coordinate_frame(2.0, Eigen::Vector3d(1, 2, 3)); }, 1134,
     2240, 2.9767455943032073, {0.88, 1.88, 2.88}, {3, 4, 5},
     {739424.9304765145, 1397145.7510347662, 2041935.9320433117}, {1881619160, 1864285400, 1832220440}, 1},
    {"tetrahedron(1)", [] { return g::create_tetrahedron(); }, 4, 4, 4.618802153517006,
     {-0.4714045207910317, -0.816496580927726, -0.3333333333333333}, {0.9428090415820634, 0.816496580927726, 1.0},
     {-1.414213562373095, -0.8164965809277258, 2.0}, {4, 19, 26}, 1},
    {"tetrahedron(2)", [] { return g::create_tetrahedron(2); }, 4, 4, 18.475208614068023,
     {-0.9428090415820634, -1.632993161855452, -0.6666666666666666}, {1.8856180831641267, 1.632993161855452, 2.0},
     {-2.82842712474619, -1.6329931618554516, 4.0}, {4, 19, 26}, 1},
    {"octahedron(1)", [] { return g::create_octahedron(); }, 6, 8, 6.928203230275508, {-1, -1, -1}, {1, 1, 1},
     {-3, -3, -3}, {86, 149, 71}, 1},
    {"octahedron(2)", [] { return g::create_octahedron(2); }, 6, 8, 27.71281292110203, {-2, -2, -2}, {2, 2, 2},
     {-6, -6, -6}, {86, 149, 71}, 1},
    {"icosahedron(1)", [] { return g::create_icosahedron(); }, 12, 20, 34.64101615137755,
     {-1.618033988749895, -1.618033988749895, -1.618033988749895}, {1.618033988749895, 1.618033988749895, 1.618033988749895},
     {0.0, 4.0, -10.47213595499958}, {547, 1594, 1629}, kIco},
    {"icosahedron(2)", [] { return g::create_icosahedron(2); }, 12, 20, 138.5640646055102,
     {-3.23606797749979, -3.23606797749979, -3.23606797749979}, {3.23606797749979, 3.23606797749979, 3.23606797749979},
     {0.0, 8.0, -20.94427190999916}, {547, 1594, 1629}, kIco},
};

bool near(double a, double b) { return std::abs(a - b) <= 1e-9 * (1.0 + std::abs(b)); }

TEST(meshPrimitives, MatchOpen3dCountsBoundsAreaAndLayout) {
    for (const Reference& r : kReferences) {
        SCOPED_TRACE(r.name);
        const TriangleMesh m = r.make();
        ASSERT_EQ(m.vertices.size(), r.vertices);
        ASSERT_EQ(m.triangles.size(), r.triangles);
        ASSERT_NO_THROW(g::validate_triangles(m));
        EXPECT_TRUE(near(area(m), r.area * r.scale * r.scale)) << area(m);
        Eigen::Vector3d lo = m.vertices[0], hi = m.vertices[0], fv = Eigen::Vector3d::Zero();
        Eigen::Matrix<long, 3, 1> ft = Eigen::Matrix<long, 3, 1>::Zero();
        for (size_t i = 0; i < m.vertices.size(); ++i) {
            lo = lo.cwiseMin(m.vertices[i]);
            hi = hi.cwiseMax(m.vertices[i]);
            fv += double(i + 1) * m.vertices[i];
        }
        for (size_t t = 0; t < m.triangles.size(); ++t) ft += long(t + 1) * m.triangles[t].cast<long>();
        for (int k = 0; k < 3; ++k) {
            EXPECT_TRUE(near(lo[k], r.min[k] * r.scale)) << k << " " << lo[k];
            EXPECT_TRUE(near(hi[k], r.max[k] * r.scale)) << k << " " << hi[k];
            // Vertex order and positions, and triangle order and corner order (so winding), as Open3D's.
            EXPECT_TRUE(near(fv[k], r.vertex_fingerprint[k] * r.scale)) << k << " " << fv[k];
            EXPECT_EQ(ft[k], r.triangle_fingerprint[k]) << k;
        }
    }
}

TEST(meshPrimitives, CoordinateFrameColorsAndNormalsMatchOpen3d) {
    const TriangleMesh m = g::create_coordinate_frame();
    ASSERT_TRUE(m.has_vertex_colors());
    ASSERT_TRUE(m.has_vertex_normals());
    ASSERT_TRUE(m.has_triangle_normals());
    EXPECT_EQ(m.vertex_colors[0], Eigen::Vector3d(0.5, 0.5, 0.5));  // the sphere
    EXPECT_EQ(m.vertex_colors[762], Eigen::Vector3d(1, 0, 0));      // the x arrow
    EXPECT_EQ(m.vertex_colors[886], Eigen::Vector3d(0, 1, 0));      // y
    EXPECT_EQ(m.vertex_colors[1010], Eigen::Vector3d(0, 0, 1));     // z
    EXPECT_NEAR(m.vertices[764].y(), 0.035, 1e-15);                 // x arrow's first rim vertex: (0.8, 0.035, 0)
    Eigen::Vector3d colors = Eigen::Vector3d::Zero(), fn = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        colors += m.vertex_colors[i];
        fn += double(i + 1) * m.vertex_normals[i];
        EXPECT_NEAR(m.vertex_normals[i].norm(), 1.0, 1e-12);
    }
    // Recorded by tools/reference/record_primitives.py: colour sums 505 each, the normal fingerprint below.
    for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(colors[k], 505.0);
    const double expected[3] = {-879.1403470614471, -3879.9711929502255, -114098.12302204139};
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(near(fn[k], expected[k])) << fn[k];
}

TEST(meshPrimitives, IcosahedronRadiusIsItsCircumradius) {
    // io.h/trianglemesh.h promise vertices at `radius` (Open3D's docs say so too; its 0.20 code leaves them at
    // radius * 1.902): o3d follows the header, and the reference test scales Open3D's numbers to match.
    for (const TriangleMesh& m : {g::create_tetrahedron(1.5), g::create_octahedron(1.5), g::create_icosahedron(1.5)})
        for (const auto& v : m.vertices) EXPECT_NEAR(v.norm(), 1.5, 1e-14);
}

TEST(meshPrimitives, ClosedOutwardAndTopologicallyRight) {
    struct Case {
        const char* name;
        TriangleMesh mesh;
        long euler;
    };
    const Case cases[] = {
        {"box", g::create_box(0.5, 2, 3), 2},          {"sphere", g::create_sphere(1.5, 7), 2},
        {"cylinder", g::create_cylinder(1, 3, 9, 3), 2}, {"cone", g::create_cone(2, 1, 5, 4), 2},
        {"torus", g::create_torus(2, 0.7, 11, 6), 0},  {"tetrahedron", g::create_tetrahedron(2), 2},
        {"octahedron", g::create_octahedron(), 2},      {"icosahedron", g::create_icosahedron(3), 2},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_TRUE(closed_and_oriented(c.mesh));
        EXPECT_EQ(euler_characteristic(c.mesh), c.euler);
        EXPECT_GT(signed_volume(c.mesh), 0.0);
    }
    // Every triangle of a convex solid faces away from the centroid of its vertices.
    for (const Case& c : cases) {
        if (std::string(c.name) == "torus") continue;
        SCOPED_TRACE(c.name);
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        for (const auto& v : c.mesh.vertices) centre += v;
        centre /= double(c.mesh.vertices.size());
        for (size_t t = 0; t < c.mesh.triangles.size(); ++t) {
            const auto& tri = c.mesh.triangles[t];
            const Eigen::Vector3d mid = (c.mesh.vertices[tri[0]] + c.mesh.vertices[tri[1]] + c.mesh.vertices[tri[2]]) / 3;
            EXPECT_GT(g::triangle_cross(c.mesh, t).dot(mid - centre), 0.0) << t;
        }
    }
    // The torus's triangles face away from the tube's centre circle.
    const TriangleMesh& torus = cases[4].mesh;
    for (size_t t = 0; t < torus.triangles.size(); ++t) {
        const auto& tri = torus.triangles[t];
        const Eigen::Vector3d mid = (torus.vertices[tri[0]] + torus.vertices[tri[1]] + torus.vertices[tri[2]]) / 3;
        const Eigen::Vector3d on_circle = 2.0 * Eigen::Vector3d(mid.x(), mid.y(), 0).normalized();
        EXPECT_GT(g::triangle_cross(torus, t).dot(mid - on_circle), 0.0) << t;
    }
    // The arrow is two closed parts (cylinder, cone), each outward.
    const TriangleMesh arrow = g::create_arrow(0.5, 1, 2, 1, 6, 2, 2);
    EXPECT_TRUE(closed_and_oriented(arrow));
    EXPECT_EQ(euler_characteristic(arrow), 4);
    EXPECT_GT(signed_volume(arrow), 0.0);
}

TEST(meshPrimitives, AnalyticAreasAndVolumes) {
    // Box: exact.
    const TriangleMesh box = g::create_box(0.5, 2, 3);
    EXPECT_DOUBLE_EQ(area(box), 2 * (0.5 * 2 + 2 * 3 + 0.5 * 3));
    EXPECT_DOUBLE_EQ(signed_volume(box), 3.0);
    // Cylinder and cone: a prism and a pyramid on a regular n-gon, exactly (any split).
    for (int n : {3, 8, 50}) {
        SCOPED_TRACE(n);
        const double r = 0.7, h = 2.5;
        const double base = 0.5 * n * r * r * std::sin(2 * kPi / n), side = 2 * r * std::sin(kPi / n);
        const TriangleMesh cyl = g::create_cylinder(r, h, n, 3);
        EXPECT_NEAR(area(cyl), 2 * base + n * side * h, 1e-12);
        EXPECT_NEAR(signed_volume(cyl), base * h, 1e-12);
        const TriangleMesh cone = g::create_cone(r, h, n, 2);
        const double apothem = r * std::cos(kPi / n);
        EXPECT_NEAR(area(cone), base + 0.5 * n * side * std::hypot(apothem, h), 1e-12);
        EXPECT_NEAR(signed_volume(cone), base * h / 3, 1e-12);
    }
    // Sphere and torus: the smooth values as the resolution grows, the error shrinking each time.
    const double r = 1.3, big = 2.0, tube = 0.4;
    double last_sphere = 1, last_torus = 1;
    for (int res : {10, 40, 160}) {
        SCOPED_TRACE(res);
        const TriangleMesh s = g::create_sphere(r, res);
        const double es = std::abs(area(s) / (4 * kPi * r * r) - 1);
        EXPECT_LT(es, last_sphere);
        EXPECT_LT(std::abs(signed_volume(s) / (4.0 / 3.0 * kPi * r * r * r) - 1), 4 * es + 1e-12);
        last_sphere = es;
        const TriangleMesh t = g::create_torus(big, tube, 2 * res, res);
        const double et = std::abs(area(t) / (4 * kPi * kPi * big * tube) - 1);
        EXPECT_LT(et, last_torus);
        EXPECT_LT(std::abs(signed_volume(t) / (2 * kPi * kPi * big * tube * tube) - 1), 4 * et + 1e-12);
        last_torus = et;
    }
    EXPECT_LT(last_sphere, 1e-3);
    EXPECT_LT(last_torus, 1e-3);
}

TEST(meshPrimitives, BadArgumentsAreRejected) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (double bad : {0.0, -1.0, nan, inf}) {
        SCOPED_TRACE(bad);
        EXPECT_THROW(g::create_box(bad, 1, 1), o3d::InvalidArgument);
        EXPECT_THROW(g::create_box(1, 1, bad), o3d::InvalidArgument);
        EXPECT_THROW(g::create_sphere(bad, 10), o3d::InvalidArgument);
        EXPECT_THROW(g::create_cylinder(1, bad, 10, 1), o3d::InvalidArgument);
        EXPECT_THROW(g::create_cone(bad, 1, 10, 1), o3d::InvalidArgument);
        EXPECT_THROW(g::create_torus(1, bad, 10, 10), o3d::InvalidArgument);
        EXPECT_THROW(g::create_arrow(1, 1, 1, bad, 10, 1, 1), o3d::InvalidArgument);
        EXPECT_THROW(g::create_coordinate_frame(bad), o3d::InvalidArgument);
        EXPECT_THROW(g::create_tetrahedron(bad), o3d::InvalidArgument);
        EXPECT_THROW(g::create_octahedron(bad), o3d::InvalidArgument);
        EXPECT_THROW(g::create_icosahedron(bad), o3d::InvalidArgument);
    }
    EXPECT_THROW(g::create_coordinate_frame(1, Eigen::Vector3d(0, nan, 0)), o3d::InvalidArgument);
    for (int bad : {0, -3}) {
        EXPECT_THROW(g::create_cylinder(1, 1, bad, 1), o3d::InvalidArgument);
        EXPECT_THROW(g::create_cylinder(1, 1, 5, bad), o3d::InvalidArgument);
        EXPECT_THROW(g::create_cone(1, 1, bad, 1), o3d::InvalidArgument);
        EXPECT_THROW(g::create_cone(1, 1, 5, bad), o3d::InvalidArgument);
        EXPECT_THROW(g::create_torus(1, 0.5, bad, 5), o3d::InvalidArgument);
        EXPECT_THROW(g::create_torus(1, 0.5, 5, bad), o3d::InvalidArgument);
        EXPECT_THROW(g::create_arrow(1, 1, 1, 1, 5, 1, bad), o3d::InvalidArgument);
    }
    // A sphere needs one ring between its poles (Open3D 0.20 indexes past its vertices at resolution 1).
    EXPECT_THROW(g::create_sphere(1, 1), o3d::InvalidArgument);
    EXPECT_EQ(g::create_sphere(1, 2).vertices.size(), 6u);
    // Vertex counts that int32 indices cannot reach are refused before anything is allocated.
    EXPECT_THROW(g::create_sphere(1, 40000), o3d::InvalidArgument);
    EXPECT_THROW(g::create_torus(1, 0.5, 1 << 16, 1 << 16), o3d::InvalidArgument);
}

}  // namespace
