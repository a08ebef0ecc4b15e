// SPDX-License-Identifier: MIT
// C API: kdtree.h over o3d::kdtree::KDTree, and feature.h's trees of any dimension over KDTreeXd.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <new>
#include <string>

#include "internal.h"
#include "o3d/feature.h"
#include "o3d/kdtree.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/kdtree/kd_tree_xd.h"

/// Exactly one tree is set: the 3-D one (clouds, and any 3-D points) or one of another dimension.
/// Each owns a copy of its points, so the handle is independent of what it was built from.
struct o3d_kdtree {
    std::unique_ptr<const o3d::kdtree::KDTree> tree;
    std::unique_ptr<const o3d::kdtree::KDTreeXd> tree_xd;
};

struct o3d_search_result {
    o3d::kdtree::SearchResult result;
};

using o3d::capi::guard;
using o3d::capi::require;

namespace {

template <typename T>
std::vector<Eigen::Vector3d> rows_of(const T* xyz, size_t n, const char* name) {
    if (n > 0 && !xyz) throw o3d::InvalidArgument(std::string(name) + " is NULL but n = " + std::to_string(n));
    std::vector<Eigen::Vector3d> rows(n);
    for (size_t i = 0; i < n; ++i)
        rows[i] = Eigen::Vector3d(static_cast<double>(xyz[3 * i]), static_cast<double>(xyz[3 * i + 1]),
                                  static_cast<double>(xyz[3 * i + 2]));
    return rows;
}

void give(o3d_kdtree_t** out, std::vector<Eigen::Vector3d> points) {
    auto handle = std::make_unique<o3d_kdtree>();
    handle->tree = std::make_unique<const o3d::kdtree::KDTree>(std::move(points));
    *out = handle.release();
}

/// @brief A tree over the columns of `points` (dimension x n): the 3-D tree when dimension is 3.
void give_xd(o3d_kdtree_t** out, const Eigen::Ref<const Eigen::MatrixXd>& points) {
    if (points.rows() == 3) {
        std::vector<Eigen::Vector3d> rows(static_cast<size_t>(points.cols()));
        for (size_t i = 0; i < rows.size(); ++i) rows[i] = points.col(static_cast<Eigen::Index>(i));
        give(out, std::move(rows));
        return;
    }
    if (points.rows() == 0) throw o3d::InvalidArgument("a KD-tree needs points of dimension >= 1");
    auto handle = std::make_unique<o3d_kdtree>();
    handle->tree_xd = std::make_unique<const o3d::kdtree::KDTreeXd>(Eigen::MatrixXd(points));
    *out = handle.release();
}

/// @brief The 3-D tree; a tree of another dimension is an error here (it needs o3d_kdtree_search_xd).
const o3d::kdtree::KDTree& tree_of(const o3d_kdtree_t* tree) {
    const o3d_kdtree& t = *require(tree, "tree");
    if (!t.tree)
        throw o3d::InvalidArgument("the tree indexes " + std::to_string(t.tree_xd->dimension()) +
                                   "-D points; search it with o3d_kdtree_search_xd");
    return *t.tree;
}
const o3d::kdtree::SearchResult& result_of(const o3d_search_result_t* r) { return require(r, "result")->result; }

template <typename T>
void search(const o3d_kdtree_t* tree, const T* queries, size_t num_queries, const o3d_search_param_t* param,
            int32_t num_threads, o3d_search_result_t** out) {
    require(out, "out");
    *out = nullptr;
    const auto& t = tree_of(tree);
    const auto search_param = o3d::capi::to_search_param(param);
    const int threads = o3d::capi::to_num_threads(num_threads);
    const auto rows = rows_of(queries, num_queries, "queries");
    auto handle = std::make_unique<o3d_search_result>();
    handle->result = t.search_batch(rows, search_param, threads);
    *out = handle.release();
}

template <typename T>
void copy_all(const std::vector<T>& src, T* out, size_t capacity, size_t* out_n) {
    require(out_n, "out_n");
    o3d::capi::copy_out(src.data(), src.size(), out, capacity, out_n);
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_kdtree_create_from_pointcloud(o3d_kdtree_t** out, const o3d_pointcloud_t* pc) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        give(out, require(pc, "pc")->cloud.points);
    });
}

O3D_API o3d_status o3d_kdtree_create_from_points(o3d_kdtree_t** out, const double* xyz, size_t n) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        give(out, rows_of(xyz, n, "xyz"));
    });
}

O3D_API void o3d_kdtree_destroy(o3d_kdtree_t* tree) { delete tree; }

O3D_API o3d_status o3d_kdtree_size(size_t* out_n, const o3d_kdtree_t* tree) {
    return guard(__func__, [&] {
        const o3d_kdtree& t = *require(tree, "tree");
        *require(out_n, "out_n") = t.tree ? t.tree->size() : t.tree_xd->size();
    });
}

O3D_API o3d_status o3d_kdtree_create_from_feature(o3d_kdtree_t** out, const o3d_feature_t* feature) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        give_xd(out, require(feature, "feature")->feature.data);
    });
}

O3D_API o3d_status o3d_kdtree_create_from_points_xd(o3d_kdtree_t** out, const double* data, size_t dimension,
                                                    size_t n) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        if (dimension == 0) throw o3d::InvalidArgument("dimension must be >= 1");
        if (n > 0 && !data) throw o3d::InvalidArgument("data is NULL but n = " + std::to_string(n));
        if (n > static_cast<size_t>(PTRDIFF_MAX) / sizeof(double) / dimension) throw std::bad_alloc();
        // n rows of `dimension` doubles are the columns of a column-major dimension x n matrix.
        static const double kNone = 0.0;
        give_xd(out, Eigen::Map<const Eigen::MatrixXd>(n ? data : &kNone, static_cast<Eigen::Index>(dimension),
                                                       static_cast<Eigen::Index>(n)));
    });
}

O3D_API o3d_status o3d_kdtree_dimension(size_t* out, const o3d_kdtree_t* tree) {
    return guard(__func__, [&] {
        const o3d_kdtree& t = *require(tree, "tree");
        *require(out, "out") = t.tree ? 3 : t.tree_xd->dimension();
    });
}

O3D_API o3d_status o3d_kdtree_search_xd(o3d_search_result_t** out, const o3d_kdtree_t* tree, const double* queries,
                                        size_t num_queries, size_t dimension, const o3d_search_param_t* param,
                                        int32_t num_threads) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        const o3d_kdtree& t = *require(tree, "tree");
        const size_t tree_dimension = t.tree ? 3 : t.tree_xd->dimension();
        if (dimension != tree_dimension)
            throw o3d::InvalidArgument("queries have dimension " + std::to_string(dimension) +
                                       " but the tree indexes " + std::to_string(tree_dimension) + "-D points");
        if (t.tree) {
            search(tree, queries, num_queries, param, num_threads, out);
            return;
        }
        const auto search_param = o3d::capi::to_search_param(param);
        const int threads = o3d::capi::to_num_threads(num_threads);
        auto handle = std::make_unique<o3d_search_result>();
        handle->result = t.tree_xd->search_batch(queries, num_queries, search_param, threads);
        *out = handle.release();
    });
}

O3D_API o3d_status o3d_kdtree_search(o3d_search_result_t** out, const o3d_kdtree_t* tree, const double* queries,
                                     size_t num_queries, const o3d_search_param_t* param, int32_t num_threads) {
    return guard(__func__, [&] { search(tree, queries, num_queries, param, num_threads, out); });
}

O3D_API o3d_status o3d_kdtree_search_f32(o3d_search_result_t** out, const o3d_kdtree_t* tree, const float* queries,
                                         size_t num_queries, const o3d_search_param_t* param, int32_t num_threads) {
    return guard(__func__, [&] { search(tree, queries, num_queries, param, num_threads, out); });
}

O3D_API void o3d_search_result_destroy(o3d_search_result_t* result) { delete result; }

O3D_API o3d_status o3d_search_result_counts(size_t* out_num_queries, size_t* out_total,
                                            const o3d_search_result_t* result) {
    return guard(__func__, [&] {
        const auto& r = result_of(result);
        require(out_num_queries, "out_num_queries");
        require(out_total, "out_total");
        *out_num_queries = r.offsets.size() - 1;
        *out_total = r.indices.size();
    });
}

O3D_API o3d_status o3d_search_result_view(const int64_t** out_offsets, const int32_t** out_indices,
                                          const double** out_distances2, const o3d_search_result_t* result) {
    return guard(__func__, [&] {
        const auto& r = result_of(result);
        require(out_offsets, "out_offsets");
        require(out_indices, "out_indices");
        require(out_distances2, "out_distances2");
        *out_offsets = r.offsets.data();
        *out_indices = r.indices.empty() ? nullptr : r.indices.data();
        *out_distances2 = r.distances2.empty() ? nullptr : r.distances2.data();
    });
}

O3D_API o3d_status o3d_search_result_get_offsets(int64_t* out, size_t capacity, size_t* out_n,
                                                 const o3d_search_result_t* result) {
    return guard(__func__, [&] { copy_all(result_of(result).offsets, out, capacity, out_n); });
}

O3D_API o3d_status o3d_search_result_get_indices(int32_t* out, size_t capacity, size_t* out_n,
                                                 const o3d_search_result_t* result) {
    return guard(__func__, [&] { copy_all(result_of(result).indices, out, capacity, out_n); });
}

O3D_API o3d_status o3d_search_result_get_distances2(double* out, size_t capacity, size_t* out_n,
                                                    const o3d_search_result_t* result) {
    return guard(__func__, [&] { copy_all(result_of(result).distances2, out, capacity, out_n); });
}

}  // extern "C"
