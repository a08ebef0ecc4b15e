// SPDX-License-Identifier: MIT
#pragma once
/// @file result_sets.h
/// @brief Internal: FLANN result sets that write into caller-owned storage, so a search allocates
/// nothing per query (FLANN's own sets grow a std::vector per query).
#include <flann/util/result_set.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace o3d::kdtree::detail {

/// @brief The k nearest points closer than sqrt(bound2), kept sorted by insertion (k is small).
/// bound2 = +inf gives plain knn; a finite bound gives the hybrid search. Points at exactly the
/// bound are rejected, as nanoflann/Open3D do.
class BoundedKnnSet final : public flann::ResultSet<double> {
public:
    BoundedKnnSet(int32_t* indices, double* distances2, size_t capacity, double bound2)
        : indices_(indices), distances2_(distances2), capacity_(capacity), bound2_(bound2) {}

    bool full() const override { return count_ == capacity_; }
    double worstDist() const override { return count_ == capacity_ ? distances2_[capacity_ - 1] : bound2_; }

    void addPoint(double dist, size_t index) override {
        // FLANN reads worstDist() once per leaf, so a stale bound may let farther points through.
        if (!(dist < worstDist())) return;
        size_t pos = count_ < capacity_ ? count_++ : capacity_ - 1;
        // Equal distances keep their arrival order: shift only strictly larger entries.
        while (pos > 0 && distances2_[pos - 1] > dist) {
            distances2_[pos] = distances2_[pos - 1];
            indices_[pos] = indices_[pos - 1];
            --pos;
        }
        distances2_[pos] = dist;
        indices_[pos] = static_cast<int32_t>(index);
    }

    size_t count() const { return count_; }

private:
    int32_t* indices_;
    double* distances2_;
    size_t capacity_;
    double bound2_;
    size_t count_ = 0;
};

/// @brief Every point closer than sqrt(radius2), collected unsorted into a reused buffer.
class RadiusSet final : public flann::ResultSet<double> {
public:
    RadiusSet(std::vector<std::pair<double, int32_t>>& hits, double radius2) : hits_(hits), radius2_(radius2) {
        hits_.clear();
    }

    bool full() const override { return true; }
    double worstDist() const override { return radius2_; }
    void addPoint(double dist, size_t index) override {
        if (dist < radius2_) hits_.emplace_back(dist, static_cast<int32_t>(index));
    }

    /// @brief Sort by (distance, index): ascending and independent of the traversal order.
    void sort() { std::sort(hits_.begin(), hits_.end()); }

private:
    std::vector<std::pair<double, int32_t>>& hits_;
    double radius2_;
};

}  // namespace o3d::kdtree::detail
