// SPDX-License-Identifier: MIT
// o3d.pipelines.registration robust kernels (RobustKernel, L2Loss, L1Loss, HuberLoss, CauchyLoss, GMLoss,
// TukeyLoss) over o3d_robust_kernel_weight (registration.h). Values: a kind and k; the weights come from C.
#include <cstdio>

#include "registration_types.h"

namespace o3dpy {
namespace {

const char* kernel_name(int32_t kind) {
    switch (kind) {
        case O3D_KERNEL_L2: return "L2Loss";
        case O3D_KERNEL_L1: return "L1Loss";
        case O3D_KERNEL_HUBER: return "HuberLoss";
        case O3D_KERNEL_CAUCHY: return "CauchyLoss";
        case O3D_KERNEL_GM: return "GMLoss";
        case O3D_KERNEL_TUKEY: return "TukeyLoss";
        default: return "RobustKernel";
    }
}

std::string kernel_repr(const RobustKernel& k) {
    std::string s = std::string("RobustKernel::") + kernel_name(k.kind);
    if (k.kind == O3D_KERNEL_L2 || k.kind == O3D_KERNEL_L1) return s;
    char buf[64];
    std::snprintf(buf, sizeof buf, " with k=%f", k.k);
    return s + buf;
}

template <typename K>
void def_scaled(py::module_& m, const char* name, const char* doc) {
    static_cast<py::class_<K, RobustKernel, std::shared_ptr<K>>>(m.attr(name))
        .def(py::init<double>(), py::arg("k"), doc)
        .def(py::init([](const K& other) { return std::make_shared<K>(other); }), py::arg("other"), "Copy constructor")
        .def_readwrite("k", &K::k, "The kernel's scale (> 0).");
}

}  // namespace

KernelPtr as_kernel(py::handle obj) {
    if (obj.is_none()) return std::make_shared<L2Loss>();
    if (!py::isinstance<RobustKernel>(obj))
        invalid("kernel: expected a RobustKernel (L2Loss, L1Loss, HuberLoss, CauchyLoss, GMLoss or TukeyLoss)");
    return obj.cast<KernelPtr>();
}

void declare_robust_kernel(py::module_& m) {
    py::class_<RobustKernel, std::shared_ptr<RobustKernel>>(
        m, "RobustKernel", "Base of the robust kernels (M-estimators) that weight ICP residuals.");
    py::class_<L2Loss, RobustKernel, std::shared_ptr<L2Loss>>(m, "L2Loss", "Plain least squares: w(r) = 1.");
    py::class_<L1Loss, RobustKernel, std::shared_ptr<L1Loss>>(m, "L1Loss", "w(r) = 1 / |r|.");
    py::class_<HuberLoss, RobustKernel, std::shared_ptr<HuberLoss>>(m, "HuberLoss", "w(r) = 1 if |r| <= k else k / |r|.");
    py::class_<CauchyLoss, RobustKernel, std::shared_ptr<CauchyLoss>>(m, "CauchyLoss", "w(r) = 1 / (1 + (r / k)^2).");
    py::class_<GMLoss, RobustKernel, std::shared_ptr<GMLoss>>(m, "GMLoss", "Geman-McClure: w(r) = k / (k + r^2)^2.");
    py::class_<TukeyLoss, RobustKernel, std::shared_ptr<TukeyLoss>>(
        m, "TukeyLoss", "w(r) = (1 - (r / k)^2)^2 if |r| <= k else 0.");
}

void define_robust_kernel(py::module_& m) {
    static_cast<py::class_<RobustKernel, std::shared_ptr<RobustKernel>>>(m.attr("RobustKernel"))
        .def(
            "weight",
            [](const RobustKernel& k, double residual) {
                double w = 0.0;
                check(o3d_robust_kernel_weight(&w, k.kind, k.k, residual));
                return w;
            },
            py::arg("residual"), "The weight this kernel gives to a residual.")
        .def("__repr__", &kernel_repr);
    static_cast<py::class_<L2Loss, RobustKernel, std::shared_ptr<L2Loss>>>(m.attr("L2Loss"))
        .def(py::init<>())
        .def(py::init([](const L2Loss& other) { return std::make_shared<L2Loss>(other); }), py::arg("other"));
    static_cast<py::class_<L1Loss, RobustKernel, std::shared_ptr<L1Loss>>>(m.attr("L1Loss"))
        .def(py::init<>())
        .def(py::init([](const L1Loss& other) { return std::make_shared<L1Loss>(other); }), py::arg("other"));
    def_scaled<HuberLoss>(m, "HuberLoss", "Huber's kernel with scale k.");
    def_scaled<CauchyLoss>(m, "CauchyLoss", "Cauchy's kernel with scale k.");
    def_scaled<GMLoss>(m, "GMLoss", "Geman-McClure kernel with scale k.");
    def_scaled<TukeyLoss>(m, "TukeyLoss", "Tukey's biweight with scale k.");
}

}  // namespace o3dpy
