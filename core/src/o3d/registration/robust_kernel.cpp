// SPDX-License-Identifier: MIT
#include "o3d/registration/robust_kernel.h"

#include <string>

#include "o3d/utility/error.h"

namespace o3d::registration {

void check_robust_kernel(const RobustKernel& kernel) {
    const int type = static_cast<int>(kernel.type);
    if (type < static_cast<int>(RobustKernelType::L2) || type > static_cast<int>(RobustKernelType::Tukey))
        throw InvalidArgument("unknown robust kernel type " + std::to_string(type));
    if (kernel.uses_k() && !(std::isfinite(kernel.k) && kernel.k > 0.0))
        throw InvalidArgument("robust kernel k must be finite and > 0, got " + std::to_string(kernel.k));
}

}  // namespace o3d::registration
