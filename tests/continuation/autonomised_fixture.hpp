#pragma once
// A 2 pi-periodically forced system whose field is a polynomial in (cos t, sin t), made autonomous: (cos t, sin t)
// becomes the state (c, s) of the oscillator c' = -s + c (1 - c^2 - s^2), s' = c + s (1 - c^2 - s^2), which runs
// round its attracting circle c^2 + s^2 = 1 at unit speed (radial multiplier e^{-4 pi} per turn). On the circle the
// state x follows the forced system with t the angle, so a forced orbit of period 2 pi is an autonomous orbit of
// period 2 pi with the forced multipliers, e^{-4 pi} and the trivial 1. The Jacobian and the p-derivative are
// fourth-order central differences (h = 1e-3: ~1e-12 for these smooth fields).
#include <cmath>
#include <functional>
#include <span>
#include <utility>

#include "rbcstab/continuation/autonomous_orbit.hpp"

namespace rbcstab {

class Autonomised final : public AutonomousSystem {
 public:
  using Field = std::function<Eigen::VectorXd(const Eigen::VectorXd& x, double c, double s, double p)>;
  Autonomised(Eigen::Index n, Field field) : n_(n), field_(std::move(field)) {}
  Eigen::Index dimension() const override { return n_ + 2; }
  // The state (x, cos t, sin t) of the forced state x at time t.
  static Eigen::VectorXd state(const Eigen::VectorXd& x, double t) {
    Eigen::VectorXd y(x.size() + 2);
    y << x, std::cos(t), std::sin(t);
    return y;
  }
  void rhs(std::span<const double> y, double p, std::span<double> f) const override {
    Eigen::Map<Eigen::VectorXd>(f.data(), n_ + 2) = eval(Eigen::Map<const Eigen::VectorXd>(y.data(), n_ + 2), p);
  }
  void jacobian(std::span<const double> y, double p, Eigen::MatrixXd& J) const override {
    const Eigen::VectorXd y0 = Eigen::Map<const Eigen::VectorXd>(y.data(), n_ + 2);
    J.resize(n_ + 2, n_ + 2);
    for (Eigen::Index k = 0; k < n_ + 2; ++k)
      J.col(k) = difference([&](double d) {
        Eigen::VectorXd z = y0;
        z[k] += d;
        return eval(z, p);
      });
  }
  void parameter_derivative(std::span<const double> y, double p, std::span<double> fp) const override {
    const Eigen::VectorXd y0 = Eigen::Map<const Eigen::VectorXd>(y.data(), n_ + 2);
    Eigen::Map<Eigen::VectorXd>(fp.data(), n_ + 2) = difference([&](double d) { return eval(y0, p + d); });
  }

 private:
  Eigen::VectorXd eval(const Eigen::VectorXd& y, double p) const {
    const double c = y[n_], s = y[n_ + 1], a = 1 - c * c - s * s;
    Eigen::VectorXd f(n_ + 2);
    f << field_(y.head(n_), c, s, p), -s + c * a, c + s * a;
    return f;
  }
  template <class G>
  static Eigen::VectorXd difference(const G& g) {
    const double h = 1e-3;
    return (8 * (g(h) - g(-h)) - (g(2 * h) - g(-2 * h))) / (12 * h);
  }
  Eigen::Index n_;
  Field field_;
};

}  // namespace rbcstab
