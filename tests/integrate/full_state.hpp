#pragma once
#include <span>
#include <vector>

#include "rbcstab/model/system.hpp"

namespace rbcstab::testing {

// A system that forwards every call to another one except its compact form: integrate() then steps the full
// state. Tests derive from it to replace one piece (shifted_solver_test.cpp: the linear solver).
class FullState : public System {
 public:
  explicit FullState(const System& s) : s_(s) {}
  ModelLevel level() const override { return s_.level(); }
  std::size_t dimension() const override { return s_.dimension(); }
  int L() const override { return s_.L(); }
  void rhs(double t, std::span<const double> y, std::span<double> d) const override { s_.rhs(t, y, d); }
  void jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> d) const override {
    s_.jacobian(t, y, J, d);
  }
  Observation observe(double t, std::span<const double> y) const override { return s_.observe(t, y); }
  std::vector<double> initial_state() const override { return s_.initial_state(); }
  ModeAmplitudes amplitudes(double t, std::span<const double> y) const override { return s_.amplitudes(t, y); }
  const System& base() const { return s_; }

 private:
  const System& s_;
};

}  // namespace rbcstab::testing
