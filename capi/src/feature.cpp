// SPDX-License-Identifier: MIT
// C API: feature.h over o3d::registration::Feature, compute_fpfh_feature, correspondences_from_features
// and the feature files. The o3d_kdtree_* functions of feature.h live in kdtree.cpp, beside the tree handle.
#include <cmath>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "array_family.h"
#include "internal.h"
#include "o3d/feature.h"
#include "o3d/io/feature_io.h"
#include "o3d/registration/feature_matching.h"
#include "o3d/registration/fpfh.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::registration::Feature;

namespace {

const Feature& feature_of(const o3d_feature_t* f) { return require(f, "feature")->feature; }
Feature& feature_of(o3d_feature_t* f) { return require(f, "feature")->feature; }

/// @brief Throw std::bad_alloc (OUT_OF_MEMORY) when dimension x num doubles cannot be addressed.
void check_size(size_t dimension, size_t num) {
    if (num != 0 && dimension > PTRDIFF_MAX / sizeof(double) / num) throw std::bad_alloc();
}

void give(o3d_feature_t** out, Feature feature) {
    auto handle = std::make_unique<o3d_feature>();
    handle->feature = std::move(feature);
    *out = handle.release();
}

template <typename T>
T** require_out(T** out) {
    require(out, "out");
    *out = nullptr;
    return out;
}

/// @brief The descriptors as rows: Eigen stores the dimension x num matrix column by column, so row i
/// (descriptor i) is contiguous. set_array keeps the dimension and takes `rows` descriptors.
template <typename In>
void assign_descriptors(Feature& f, const In* src, size_t rows) {
    const auto dim = f.data.rows();
    check_size(static_cast<size_t>(dim), rows);
    Eigen::MatrixXd m(dim, static_cast<Eigen::Index>(rows));
    for (Eigen::Index i = 0; i < m.size(); ++i) {
        m.data()[i] = static_cast<double>(src[i]);
        if (!std::isfinite(m.data()[i])) throw o3d::InvalidArgument("feature values must be finite");
    }
    f.data = std::move(m);
}

o3d::capi::ArraySlot<double> feature_slot(o3d_feature_t* h, int32_t which) {
    Feature& f = feature_of(h);
    if (which != O3D_FEATURE_DATA) o3d::capi::bad_which(which, "a feature array (O3D_FEATURE_DATA)");
    o3d::capi::ArraySlot<double> s;
    s.data = f.data.size() ? f.data.data() : nullptr;
    s.rows = static_cast<size_t>(f.data.cols());
    s.cols = static_cast<size_t>(f.data.rows());
    s.present = f.data.size() > 0;
    s.assign = [&f](const double* src, size_t rows) { assign_descriptors(f, src, rows); };
    s.assign_f32 = [&f](const float* src, size_t rows) { assign_descriptors(f, src, rows); };
    return s;
}

}  // namespace

extern "C" {

O3D_CAPI_ARRAYS_F64(feature, o3d_feature_t, feature_slot)
O3D_CAPI_ARRAY_QUERIES(feature, o3d_feature_t, feature_slot, o3d::capi::no_index_slot)

O3D_API o3d_status o3d_feature_create(o3d_feature_t** out, size_t dimension, size_t num) {
    return guard(__func__, [&] {
        require_out(out);
        check_size(dimension, num);
        Feature f;
        f.data.setZero(static_cast<Eigen::Index>(dimension), static_cast<Eigen::Index>(num));
        give(out, std::move(f));
    });
}

O3D_API o3d_status o3d_feature_create_from_data(o3d_feature_t** out, const double* data, size_t dimension,
                                                size_t num) {
    return guard(__func__, [&] {
        require_out(out);
        check_size(dimension, num);
        const size_t count = dimension * num;
        if (count > 0 && !data)
            throw o3d::InvalidArgument("data is NULL but dimension x num = " + std::to_string(count));
        for (size_t i = 0; i < count; ++i)
            if (!std::isfinite(data[i]))
                throw o3d::InvalidArgument("value " + std::to_string(i % dimension) + " of descriptor " +
                                           std::to_string(i / dimension) + " is not finite");
        Feature f;
        f.data = Eigen::Map<const Eigen::MatrixXd>(data, static_cast<Eigen::Index>(dimension),
                                                   static_cast<Eigen::Index>(num));
        give(out, std::move(f));
    });
}

O3D_API void o3d_feature_destroy(o3d_feature_t* feature) { delete feature; }

O3D_API o3d_status o3d_feature_clone(o3d_feature_t** out, const o3d_feature_t* feature) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, feature_of(feature));
    });
}

O3D_API o3d_status o3d_feature_dimension(size_t* out, const o3d_feature_t* feature) {
    return guard(__func__, [&] {
        const Feature& f = feature_of(feature);
        *require(out, "out") = f.dimension();
    });
}

O3D_API o3d_status o3d_feature_num(size_t* out, const o3d_feature_t* feature) {
    return guard(__func__, [&] {
        const Feature& f = feature_of(feature);
        *require(out, "out") = f.num();
    });
}

O3D_API o3d_status o3d_feature_resize(o3d_feature_t* feature, size_t dimension, size_t num) {
    return guard(__func__, [&] {
        Feature& f = feature_of(feature);
        check_size(dimension, num);
        // The overlapping block keeps its values (all of them when only num changes), the rest is zero.
        f.data.conservativeResizeLike(
            Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(dimension), static_cast<Eigen::Index>(num)));
    });
}

O3D_API o3d_status o3d_feature_select_by_index(o3d_feature_t** out, const o3d_feature_t* feature,
                                               const int64_t* indices, size_t n, int32_t invert) {
    return guard(__func__, [&] {
        require_out(out);
        const Feature& f = feature_of(feature);
        if (n > 0 && !indices) throw o3d::InvalidArgument("indices is NULL but n = " + std::to_string(n));
        const size_t num = f.num();
        std::vector<uint8_t> picked(invert ? num : 0, 0);
        for (size_t j = 0; j < n; ++j) {
            if (indices[j] < 0 || static_cast<uint64_t>(indices[j]) >= num)
                throw o3d::InvalidArgument("indices[" + std::to_string(j) + "] = " + std::to_string(indices[j]) +
                                           " is out of range for a feature of " + std::to_string(num) +
                                           " descriptors");
            if (invert) picked[static_cast<size_t>(indices[j])] = 1;
        }
        std::vector<Eigen::Index> columns;
        if (invert) {
            for (size_t i = 0; i < num; ++i)
                if (!picked[i]) columns.push_back(static_cast<Eigen::Index>(i));
        } else {
            columns.assign(indices, indices + n);
        }
        Feature selected;
        selected.data.resize(f.data.rows(), static_cast<Eigen::Index>(columns.size()));
        for (size_t c = 0; c < columns.size(); ++c)
            selected.data.col(static_cast<Eigen::Index>(c)) = f.data.col(columns[c]);
        give(out, std::move(selected));
    });
}

O3D_API o3d_status o3d_compute_fpfh_feature(o3d_feature_t** out, const o3d_pointcloud_t* pc,
                                            const o3d_search_param_t* param, const int64_t* indices,
                                            size_t n_indices, int32_t num_threads) {
    return guard(__func__, [&] {
        require_out(out);
        const auto& cloud = require(pc, "pc")->cloud;
        const auto search = o3d::capi::to_search_param(param);
        const int threads = o3d::capi::to_num_threads(num_threads);
        if (n_indices > 0 && !indices)
            throw o3d::InvalidArgument("indices is NULL but n_indices = " + std::to_string(n_indices));
        std::optional<std::vector<int64_t>> subset;
        if (n_indices > 0) subset.emplace(indices, indices + n_indices);
        give(out, o3d::registration::compute_fpfh_feature(cloud, search, subset, threads));
    });
}

O3D_API o3d_status o3d_correspondences_from_features(int32_t* out, size_t capacity, size_t* out_n,
                                                     const o3d_feature_t* source, const o3d_feature_t* target,
                                                     int32_t mutual_filter, double mutual_consistency_ratio,
                                                     int32_t num_threads) {
    return guard(__func__, [&] {
        const Feature& s = feature_of(source);
        const Feature& t = feature_of(target);
        const int threads = o3d::capi::to_num_threads(num_threads);
        const auto pairs = o3d::registration::correspondences_from_features(s, t, mutual_filter != 0,
                                                                            mutual_consistency_ratio, threads);
        static_assert(sizeof(Eigen::Vector2i) == 2 * sizeof(int32_t), "a pair is two packed int32");
        o3d::capi::copy_out(reinterpret_cast<const int32_t*>(pairs.data()), pairs.size(), out, capacity, out_n, 2);
    });
}

O3D_API o3d_status o3d_io_read_feature(o3d_feature_t** out, const char* path) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, o3d::io::read_feature(require(path, "path")));
    });
}

O3D_API o3d_status o3d_io_write_feature(const char* path, const o3d_feature_t* feature) {
    return guard(__func__, [&] { o3d::io::write_feature(require(path, "path"), feature_of(feature)); });
}

}  // extern "C"
