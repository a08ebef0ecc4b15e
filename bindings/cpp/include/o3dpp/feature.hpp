// SPDX-License-Identifier: MIT
#pragma once
/// @file feature.hpp
/// @brief o3dpp::Feature (per-point descriptors, o3d.pipelines.registration.Feature), FPFH, feature
/// matching and the feature files (o3d.io.read_feature / write_feature).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/feature.h"
#include "o3d/io.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/generated/feature.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

namespace detail {
using FeatureArrayFns =
    ArrayFns<&o3d_feature_has_array, &o3d_feature_array_shape, &o3d_feature_get_array, &o3d_feature_array_view,
             &o3d_feature_array_mutable_view, &o3d_feature_set_array, &o3d_feature_set_array_f32>;
}  // namespace detail

/// @brief A `dimension` x `num` matrix of descriptors, stored descriptor by descriptor: descriptor i
/// is the `dimension` doubles at data() + i * dimension(). Move-only; clone() deep-copies. dimension(), num()
/// and resize() are generated (detail::FeatureCalls).
class Feature : public Owner<Feature, o3d_feature_t, &o3d_feature_destroy>,
                public Arrays<Feature, FeatureArray, detail::FeatureArrayFns>,
                public detail::FeatureCalls<Feature> {
    friend class detail::FeatureCalls<Feature>;  // checks its calls with done
public:
    /// @brief A `dimension` x `num` feature, all zeros.
    explicit Feature(std::size_t dimension = 0, std::size_t num = 0)
        : Owner(make([&](o3d_feature_t** o) { return o3d_feature_create(o, dimension, num); })) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit Feature(o3d_feature_t* owned) : Owner(owned) {}
    /// @brief A copy of `dimension * num` doubles (non-finite values are an error).
    static Feature from_data(const double* data, std::size_t dimension, std::size_t num) {
        return create(&o3d_feature_create_from_data, data, dimension, num);
    }
    /// @brief A copy of `data` as descriptors of `dimension` values; the size must be a multiple of it.
    static Feature from_data(const std::vector<double>& data, std::size_t dimension) {
        if (dimension == 0 ? !data.empty() : data.size() % dimension != 0)
            throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::Feature::from_data: " + std::to_string(data.size()) +
                                                        " values are not whole descriptors of dimension " +
                                                        std::to_string(dimension));
        return from_data(data.data(), dimension, dimension == 0 ? 0 : data.size() / dimension);
    }

    /// @brief Deep copy.
    Feature clone() const { return derive(&o3d_feature_clone); }

    bool empty() const { return num() == 0; }

    /// @brief Writable view of the dimension() * num() values; valid until resize() or destruction.
    Span<double> data() { return array_mutable(FeatureArray::Data).flat(); }
    /// @brief Read-only view (same validity).
    Span<const double> data() const { return array(FeatureArray::Data).flat(); }
    /// @brief Descriptor `i` (out of range: Error).
    Span<const double> descriptor(std::size_t i) const {
        const Rows<const double> rows = array(FeatureArray::Data);
        if (i >= rows.size()) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::Feature::descriptor: index out of range");
        return {rows[i], rows.cols()};
    }
    /// @brief Copy of the values.
    std::vector<double> get_data() const { return get_array<double>(FeatureArray::Data); }

    /// @brief Descriptors of points `indices` in that order, or with `invert` of every other point.
    Feature select_by_index(const std::vector<int64_t>& indices, bool invert = false) const {
        return derive(&o3d_feature_select_by_index, indices.data(), indices.size(), invert ? 1 : 0);
    }
};

/// @brief Fast Point Feature Histograms (33 x N); the cloud needs normals. With `indices` only those
/// points get a descriptor, in ascending point order (Open3D's mask semantics). num_threads 0 =
/// library default (the result does not depend on it).
/// @see o3d.pipelines.registration.compute_fpfh_feature
inline Feature compute_fpfh_feature(const PointCloud& cloud, const SearchParam& param = SearchParam{},
                                    const std::vector<int64_t>& indices = {}, int num_threads = 0) {
    const o3d_search_param_t c = param.to_c();
    return Feature::create(&o3d_compute_fpfh_feature, cloud.get(), &c, indices.empty() ? nullptr : indices.data(),
                           indices.size(), num_threads);
}

/// @brief For each source descriptor its nearest target descriptor: (source, target) pairs in
/// ascending source order; with `mutual_filter` only mutual nearest pairs, unless fewer than
/// `mutual_consistency_ratio` * num(source) survive. @see o3d.pipelines.registration.correspondences_from_features
inline std::vector<std::array<int32_t, 2>> correspondences_from_features(const Feature& source, const Feature& target,
                                                                         bool mutual_filter = false,
                                                                         double mutual_consistency_ratio = 0.1,
                                                                         int num_threads = 0) {
    // At most one pair per source descriptor: one call with room for all.
    std::vector<std::array<int32_t, 2>> out(source.num());
    size_t n = 0;
    check(o3d_correspondences_from_features(out.empty() ? nullptr : out.front().data(), out.size(), &n, source.get(),
                                            target.get(), mutual_filter ? 1 : 0, mutual_consistency_ratio, num_threads));
    if (n > out.size()) throw Error(O3D_ERROR_INTERNAL, "o3dpp::correspondences_from_features: too many pairs");
    out.resize(n);
    return out;
}

/// @brief Read a feature file (Open3D's binary layout). @see o3d.io.read_feature
inline Feature read_feature(const std::string& path) {
    return Feature::create(&o3d_io_read_feature, path.c_str());
}
/// @brief Write `feature` in the layout read_feature reads. @see o3d.io.write_feature
inline void write_feature(const std::string& path, const Feature& feature) {
    check(o3d_io_write_feature(path.c_str(), feature.get()));
}

}  // namespace o3dpp
