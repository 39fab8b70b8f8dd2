#pragma once
// The forced system with closed-form orbit and Floquet multipliers behind the Neimark-Sacker curve
// tests (ns_curve_test.cpp) and benchmark (benchmarks/ns_curve_bench.cpp).
#include <Eigen/Dense>
#include <cmath>
#include <span>

#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"

namespace rbcstab::ns_fixtures {

// x' = A x + xp'(t) - A xp(t) + c |e|^2 e_1 with e = x - xp(t) and the known orbit
// xp(t) = (cos t + p1 sin 2t, sin t + p2 cos 2t, 0.5 sin t + 0.2 cos t). The quadratic term vanishes to
// second order on the orbit, so the multipliers are those of e^{2 pi A}, while Newton sees a
// nonlinear problem. A = [[a, 1, 0], [q, a, 0], [0, 0, -1]] with a = p1 - p2^2 (q may vary with p2):
//  - q = -omega^2 (Focus): multipliers e^{2 pi (a +- i omega)}, e^{-2 pi}; NS curve p1 = p2^2 with
//    theta = 2 pi omega (omega = 0.3: no strong resonance);
//  - q = +s^2 (Saddle): multipliers e^{2 pi (a +- s)}, e^{-2 pi}; at a = 0 a neutral saddle, which the
//    squared-monodromy test function sees with kappa = cosh(2 pi s) > 1.
class Forced3 final : public ForcedSystem2 {
 public:
  // q = q0 + q1 p2.
  explicit Forced3(double q0, double q1 = 0) : q0_(q0), q1_(q1) {}
  Eigen::Index dimension() const override { return 3; }
  Eigen::Matrix3d A(double p1, double p2) const {
    const double a = p1 - p2 * p2;
    Eigen::Matrix3d M;
    M << a, 1, 0, q0_ + q1_ * p2, a, 0, 0, 0, -1;
    return M;
  }
  static Eigen::Vector3d xp(double t, double p1, double p2) {
    return {std::cos(t) + p1 * std::sin(2 * t), std::sin(t) + p2 * std::cos(2 * t),
            0.5 * std::sin(t) + 0.2 * std::cos(t)};
  }
  static Eigen::Vector3d xp_dot(double t, double p1, double p2) {
    return {-std::sin(t) + 2 * p1 * std::cos(2 * t), std::cos(t) - 2 * p2 * std::sin(2 * t),
            0.5 * std::cos(t) - 0.2 * std::sin(t)};
  }
  void rhs(double t, std::span<const double> x, double p1, double p2, std::span<double> f) const override {
    const Eigen::Vector3d e = Eigen::Vector3d(x[0], x[1], x[2]) - xp(t, p1, p2);
    const Eigen::Vector3d F = A(p1, p2) * e + xp_dot(t, p1, p2) + Eigen::Vector3d(kC * e.squaredNorm(), 0, 0);
    for (int i = 0; i < 3; ++i) f[static_cast<std::size_t>(i)] = F[i];
  }
  void jacobian(double t, std::span<const double> x, double p1, double p2, Eigen::MatrixXd& J) const override {
    const Eigen::Vector3d e = Eigen::Vector3d(x[0], x[1], x[2]) - xp(t, p1, p2);
    J = A(p1, p2);
    J.row(0) += 2 * kC * e.transpose();
  }
  // df/dp1 = dA/da e - A dxp/dp1 + d(xp')/dp1 - 2c (e . dxp/dp1) e_1 with dA/da = diag(1, 1, 0).
  void parameter_derivative(double t, std::span<const double> x, double p1, double p2,
                            std::span<double> fp) const override {
    const Eigen::Vector3d e = Eigen::Vector3d(x[0], x[1], x[2]) - xp(t, p1, p2);
    const Eigen::Vector3d dxp(std::sin(2 * t), 0, 0), dxp_dot(2 * std::cos(2 * t), 0, 0);
    const Eigen::Vector3d F =
        Eigen::Vector3d(e[0], e[1], 0) - A(p1, p2) * dxp + dxp_dot - Eigen::Vector3d(2 * kC * e.dot(dxp), 0, 0);
    for (int i = 0; i < 3; ++i) fp[static_cast<std::size_t>(i)] = F[i];
  }

 private:
  static constexpr double kC = 0.7;
  double q0_, q1_;
};

}  // namespace rbcstab::ns_fixtures
