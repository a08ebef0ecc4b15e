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
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief A `dimension` x `num` matrix of descriptors, stored descriptor by descriptor: descriptor i
/// is the `dimension` doubles at data() + i * dimension(). Move-only; clone() deep-copies.
class Feature {
public:
    /// @brief A `dimension` x `num` feature, all zeros.
    explicit Feature(std::size_t dimension = 0, std::size_t num = 0) {
        o3d_feature_t* f = nullptr;
        check(o3d_feature_create(&f, dimension, num));
        h_.reset(f);
    }
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit Feature(o3d_feature_t* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::Feature: NULL handle");
    }
    /// @brief A copy of `dimension * num` doubles (non-finite values are an error).
    static Feature from_data(const double* data, std::size_t dimension, std::size_t num) {
        return adopt([&](o3d_feature_t** o) { return o3d_feature_create_from_data(o, data, dimension, num); });
    }
    /// @brief A copy of `data` as descriptors of `dimension` values; the size must be a multiple of it.
    static Feature from_data(const std::vector<double>& data, std::size_t dimension) {
        if (dimension == 0 ? !data.empty() : data.size() % dimension != 0)
            throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::Feature::from_data: " + std::to_string(data.size()) +
                                                        " values are not whole descriptors of dimension " +
                                                        std::to_string(dimension));
        return from_data(data.data(), dimension, dimension == 0 ? 0 : data.size() / dimension);
    }

    Feature(Feature&&) noexcept = default;
    Feature& operator=(Feature&&) noexcept = default;
    Feature(const Feature&) = delete;
    Feature& operator=(const Feature&) = delete;

    /// @brief The handle (NULL after a move). Still owned by this object.
    o3d_feature_t* get() const noexcept { return h_.get(); }
    /// @brief Give up ownership: the caller destroys it with o3d_feature_destroy.
    o3d_feature_t* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    /// @brief Deep copy.
    Feature clone() const { return adopt([&](o3d_feature_t** o) { return o3d_feature_clone(o, get()); }); }

    /// @brief Descriptor length (33 for FPFH).
    std::size_t dimension() const {
        size_t d = 0;
        check(o3d_feature_dimension(&d, get()));
        return d;
    }
    /// @brief Number of descriptors (points).
    std::size_t num() const {
        size_t n = 0;
        check(o3d_feature_num(&n, get()));
        return n;
    }
    bool empty() const { return num() == 0; }

    /// @brief Writable view of the dimension() * num() values; valid until resize() or destruction.
    Span<double> data() {
        double* p = nullptr;
        check(o3d_feature_data(&p, get()));
        return {p, p ? dimension() * num() : 0};
    }
    /// @brief Read-only view (same validity). o3d_feature_data only hands out the pointer.
    Span<const double> data() const {
        double* p = nullptr;
        check(o3d_feature_data(&p, const_cast<o3d_feature_t*>(get())));
        return {p, p ? dimension() * num() : 0};
    }
    /// @brief Descriptor `i` (out of range: Error).
    Span<const double> descriptor(std::size_t i) const {
        const std::size_t d = dimension();
        if (i >= num()) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::Feature::descriptor: index out of range");
        return {data().data() + i * d, d};
    }
    /// @brief Copy of the values.
    std::vector<double> get_data() const {
        std::vector<double> out(dimension() * num());
        check(o3d_feature_get_data(out.data(), out.size(), get()));
        return out;
    }

    /// @brief Resize (Open3D's Feature.resize): with the same dimension kept descriptors stay; new values are 0.
    void resize(std::size_t dimension, std::size_t num) { check(o3d_feature_resize(get(), dimension, num)); }

    /// @brief Descriptors of points `indices` in that order, or with `invert` of every other point.
    Feature select_by_index(const std::vector<int64_t>& indices, bool invert = false) const {
        return adopt([&](o3d_feature_t** o) {
            return o3d_feature_select_by_index(o, get(), indices.data(), indices.size(), invert ? 1 : 0);
        });
    }

    /// @brief Run a C constructor writing `*out` and take the result.
    template <typename F>
    static Feature adopt(F&& make) {
        o3d_feature_t* f = nullptr;
        check(make(&f));
        return Feature(f);
    }

private:
    UniqueHandle<o3d_feature_t, &o3d_feature_destroy> h_;
};

/// @brief Fast Point Feature Histograms (33 x N); the cloud needs normals. With `indices` only those
/// points get a descriptor, in ascending point order (Open3D's mask semantics). num_threads 0 =
/// library default (the result does not depend on it).
/// @see o3d.pipelines.registration.compute_fpfh_feature
inline Feature compute_fpfh_feature(const PointCloud& cloud, const SearchParam& param = SearchParam::Knn(30),
                                    const std::vector<int64_t>& indices = {}, int num_threads = 0) {
    const o3d_search_param_t c = param.to_c();
    return Feature::adopt([&](o3d_feature_t** o) {
        return o3d_compute_fpfh_feature(o, cloud.get(), &c, indices.empty() ? nullptr : indices.data(), indices.size(),
                                        num_threads);
    });
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
    return Feature::adopt([&](o3d_feature_t** o) { return o3d_io_read_feature(o, path.c_str()); });
}
/// @brief Write `feature` in the layout read_feature reads. @see o3d.io.write_feature
inline void write_feature(const std::string& path, const Feature& feature) {
    check(o3d_io_write_feature(path.c_str(), feature.get()));
}

}  // namespace o3dpp
