#pragma once
// A ForcedSystem at fixed p seen as a System for integrate(), optionally augmented with the variational
// equations Phi' = J Phi (n x n, column-major) and, for shooting in p, s' = J s + f_p (the parameter
// sensitivity). Only explicit steppers are used (rk8pd), which never ask for the Jacobian of the augmented
// system, so jacobian/observe/amplitudes are not part of this adapter's contract and throw logic_error.
#include <span>
#include <stdexcept>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/forced_system.hpp"
#include "rbcstab/integrate/quadrature.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab::detail {

class ForcedFlow final : public System {
 public:
  enum class Mode {
    plain,        // x
    monodromy,    // x, Phi
    variational,  // x, Phi, s
  };
  ForcedFlow(const ForcedSystem& s, double p, Mode mode) : s_(s), p_(p), mode_(mode), n_(s.dimension()) {}
  ModelLevel level() const override { return ModelLevel::automatic; }
  std::size_t dimension() const override {
    const auto n = static_cast<std::size_t>(n_);
    switch (mode_) {
      case Mode::plain:
        return n;
      case Mode::monodromy:
        return n + n * n;
      case Mode::variational:
        return n + n * n + n;
    }
    return n;
  }
  int L() const override { return 2; }
  void rhs(double t, std::span<const double> y, std::span<double> dydt) const override {
    const auto n = static_cast<std::size_t>(n_);
    if (mode_ == Mode::plain) {
      s_.rhs(t, y.first(n), p_, dydt.first(n));
      return;
    }
    const bool sensitivity = mode_ == Mode::variational;
    fp_.resize(n_);
    s_.flow_terms(t, y.first(n), p_, dydt.first(n), J_,
                  sensitivity ? std::span<double>(fp_.data(), n) : std::span<double>());
    if (n_ == 3) {
      // The reduced system: fixed-size products (the dynamic ones were a tenth of a shooting's time).
      const Eigen::Matrix3d J = J_;
      Eigen::Map<Eigen::Matrix3d>(dydt.data() + n).noalias() = J * Eigen::Map<const Eigen::Matrix3d>(y.data() + n);
      if (sensitivity)
        Eigen::Map<Eigen::Vector3d>(dydt.data() + 12).noalias() =
            J * Eigen::Map<const Eigen::Vector3d>(y.data() + 12) + Eigen::Map<const Eigen::Vector3d>(fp_.data());
      return;
    }
    Eigen::Map<const Eigen::MatrixXd> Phi(y.data() + n, n_, n_);
    Eigen::Map<Eigen::MatrixXd>(dydt.data() + n, n_, n_).noalias() = J_ * Phi;
    if (!sensitivity) return;
    Eigen::Map<const Eigen::VectorXd> sp(y.data() + n + n * n, n_);
    Eigen::Map<Eigen::VectorXd>(dydt.data() + n + n * n, n_).noalias() = J_ * sp + fp_;
  }
  void jacobian(double, std::span<const double>, StructuredJacobian&, std::span<double>) const override {
    throw std::logic_error("orbit shooting integrates with explicit steppers only");
  }
  Observation observe(double, std::span<const double>) const override {
    throw std::logic_error("orbit shooting adapter has no observation");
  }
  std::vector<double> initial_state() const override { return {}; }
  ModeAmplitudes amplitudes(double, std::span<const double>) const override {
    throw std::logic_error("orbit shooting adapter has no amplitudes");
  }

 private:
  const ForcedSystem& s_;
  double p_;
  Mode mode_;
  Eigen::Index n_;
  mutable Eigen::MatrixXd J_;
  mutable Eigen::VectorXd fp_;
};

// theta' = (x0 f1 - x1 f0) / (x0^2 + x1^2): the continuous argument of z = x0 + i x1.
inline Quadrature winding_angle() {
  Quadrature q;
  q.rate = [](double, std::span<const double> x, std::span<const double> f, std::span<double> rate) {
    rate[0] = (x[0] * f[1] - x[1] * f[0]) / (x[0] * x[0] + x[1] * x[1]);
  };
  return q;
}

}  // namespace rbcstab::detail
