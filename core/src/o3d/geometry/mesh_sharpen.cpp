// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_sharpen.h"

#include <cmath>
#include <string>

#include "o3d/geometry/mesh_filter_detail.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

TriangleMesh filter_sharpen(const TriangleMesh& mesh, int number_of_iterations, double strength, FilterScope scope,
                            int num_threads) {
    detail::check_filter_input(mesh, number_of_iterations, scope);
    if (!std::isfinite(strength)) throw InvalidArgument("strength must be finite, got " + std::to_string(strength));
    return detail::apply_vertex_filter(mesh, number_of_iterations, {{detail::FilterStepKind::Sharpen, strength}}, scope,
                                       num_threads);
}

}  // namespace o3d::geometry
