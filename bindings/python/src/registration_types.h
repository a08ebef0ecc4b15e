// SPDX-License-Identifier: MIT
// Python-side types shared by the registration pipeline bindings (registration.cpp, robust_kernel.cpp,
// feature.cpp, registration_global.cpp, pose_graph.cpp, kdtree.cpp): the Feature holder, the estimation
// and robust-kernel values, the RegistrationResult value, the GIL-safe cancellable progress trampoline
// and multi-handle locking. All of it sits on the public C API only.
#pragma once

#include <optional>
#include <vector>

#include "geometry_types.h"

namespace o3dpy {

using FeatureHandle = Handle<o3d_feature_t, &o3d_feature_destroy>;
using FeaturePtr = std::shared_ptr<FeatureHandle>;

/// o3d.pipelines.registration.Feature. `data` is a zero-copy (dimension, num) view whose base keeps
/// the handle alive; resize() first gives the feature a private copy while such views exist.
struct PyFeature : Geom<o3d_feature_t> {
    using Geom::Geom;
    PyFeature();
    size_t dimension() const;
    size_t num() const;
};

/// RobustKernel and its subclasses: a kernel kind (O3D_KERNEL_*) and its scale k. Polymorphic, so
/// that a kernel handed back to Python (estimation.kernel) keeps its Python class.
struct RobustKernel {
    int32_t kind = O3D_KERNEL_L2;
    double k = init_of(&o3d_icp_options_init).kernel_k;
    RobustKernel() = default;
    RobustKernel(int32_t kind_, double k_) : kind(kind_), k(k_) {}
    virtual ~RobustKernel() = default;
};
struct L2Loss : RobustKernel {
    L2Loss() : RobustKernel(O3D_KERNEL_L2, 1.0) {}
};
struct L1Loss : RobustKernel {
    L1Loss() : RobustKernel(O3D_KERNEL_L1, 1.0) {}
};
struct HuberLoss : RobustKernel {
    explicit HuberLoss(double k_) : RobustKernel(O3D_KERNEL_HUBER, k_) {}
};
struct CauchyLoss : RobustKernel {
    explicit CauchyLoss(double k_) : RobustKernel(O3D_KERNEL_CAUCHY, k_) {}
};
struct GMLoss : RobustKernel {
    explicit GMLoss(double k_) : RobustKernel(O3D_KERNEL_GM, k_) {}
};
struct TukeyLoss : RobustKernel {
    explicit TukeyLoss(double k_) : RobustKernel(O3D_KERNEL_TUKEY, k_) {}
};
using KernelPtr = std::shared_ptr<RobustKernel>;
/// The kernel of `obj` (None: a new L2Loss); anything but a RobustKernel raises.
KernelPtr as_kernel(py::handle obj);

/// TransformationEstimation*: everything o3d_icp_options_t / o3d_ransac_options_t take from it.
/// The kernel is shared (as Open3D's shared_ptr), so `estimation.kernel.k = 2` changes the estimation.
struct Estimation {
    int32_t kind = O3D_ESTIMATION_POINT_TO_POINT;
    bool with_scaling = false;
    KernelPtr kernel = std::make_shared<L2Loss>();
    double lambda_geometric = init_of(&o3d_icp_options_init).lambda_geometric;
    double epsilon = init_of(&o3d_icp_options_init).epsilon;
};

/// RegistrationResult (a value: numpy arrays copied out of the C result).
struct Result {
    py::object transformation;
    double fitness = 0.0;
    double inlier_rmse = 0.0;
    py::object correspondence_set;
};
using ResultPtr = std::unique_ptr<o3d_registration_result_t, void (*)(o3d_registration_result_t*)>;

/// Copy a C result into a RegistrationResult.
Result convert_result(o3d_registration_result_t* r);
/// Row-major 4x4 from a (4,4) array-like; None gives the identity.
std::array<double, 16> mat4_or_identity(py::handle T, const char* what);
/// The estimation of `obj` (None: point-to-point); anything but a TransformationEstimation raises.
const Estimation& as_estimation(py::handle obj, const Estimation& fallback);
/// An (N,2) int32 C-contiguous copy-free (when possible) array from Vector2iVector, ndarray or pairs.
py::array_t<int32_t, py::array::c_style> as_corres(py::handle obj, const char* what);

/// A Python progress callable (fraction -> truthy cancels) for the C progress callbacks, plus the
/// exception it raised (or KeyboardInterrupt), re-raised after the C call returns.
struct Progress {
    py::object callback;
    std::optional<py::error_already_set> error;
    explicit Progress(py::object cb);
    /// Re-raise the callback's own exception, if any (call after the C call, GIL held).
    void rethrow();
};
/// o3d_progress_callback: takes the GIL, checks Ctrl-C, calls the Python callable.
int32_t progress_trampoline(double fraction, void* user_data);

/// Shared locks on several handles' mutexes, each taken once (the same cloud may be passed twice).
class SharedLocks {
public:
    void add(std::shared_mutex& m) {
        for (auto& l : locks_)
            if (l.mutex() == &m) return;
        locks_.emplace_back(m);
    }

private:
    std::vector<std::shared_lock<std::shared_mutex>> locks_;
};

/// Seed fields of the randomized calls: None -> the global generator (use_seed 0), an int -> that seed
/// (negative values wrap modulo 2^64, as a C uint64_t).
std::pair<int32_t, uint64_t> seed_fields(py::handle seed);

void declare_robust_kernel(py::module_& m);
void define_robust_kernel(py::module_& m);
void declare_feature(py::module_& m);
void define_feature(py::module_& m);
void declare_registration_global(py::module_& m);
void define_registration_global(py::module_& m);
void declare_pose_graph(py::module_& m);
void define_pose_graph(py::module_& m);

}  // namespace o3dpy
