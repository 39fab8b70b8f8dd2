#include "rbcstab/model/system.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rbcstab {

double Observation::r() const { return Delta2 > 0 ? std::min(1.0, std::abs(f22) * std::sqrt(4 / Delta2)) : 0.0; }

double Observation::Psi() const {
  double psi = -std::arg(f22);
  if (psi <= -std::numbers::pi) psi += 2 * std::numbers::pi;
  return psi;
}

double Observation::Psi_near(double previous) const {
  const double raw = -std::arg(f22);
  return raw + 2 * std::numbers::pi * std::round((previous - raw) / (2 * std::numbers::pi));
}

namespace {
// J = M + v w^T from the system's own jacobian(): block-diagonal solves plus Sherman-Morrison.
class StructuredShiftedSolver final : public ShiftedSolver {
 public:
  explicit StructuredShiftedSolver(const System& system) : system_(system) {}
  void linearize(double t, std::span<const double> y, std::span<double> dfdt) override {
    system_.jacobian(t, y, J_, dfdt);
  }
  bool solve(double c, std::span<const double> b, std::span<double> x) override { return J_.solve_shifted(c, b, x); }

 private:
  const System& system_;
  StructuredJacobian J_;
};
}  // namespace

std::unique_ptr<ShiftedSolver> System::make_shifted_solver() const {
  return std::make_unique<StructuredShiftedSolver>(*this);
}

}  // namespace rbcstab
