#include "rbcstab/model/system.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "rbcstab/core/constants.hpp"

namespace rbcstab {

double Observation::r() const { return Delta2 > 0 ? std::min(1.0, std::abs(f22) * std::sqrt(4 / Delta2)) : 0.0; }

double Observation::Psi() const {
  double psi = -std::arg(f22);
  if (psi <= -kPi) psi += 2 * kPi;
  return psi;
}

double Observation::Psi_near(double previous) const {
  const double raw = -std::arg(f22);
  return raw + 2 * kPi * std::round((previous - raw) / (2 * kPi));
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

std::size_t CompactForm::add_unknown(double value, bool is_integral) {
  x0.push_back(value);
  integral.push_back(is_integral);
  reference.push_back(0.0);
  return x0.size() - 1;
}

void CompactForm::add_component(std::size_t source_index, double scale_k, double offset_k, double pivot_k) {
  source.push_back(source_index);
  scale.push_back(scale_k);
  offset.push_back(offset_k);
  pivot.push_back(pivot_k);
}

void CompactForm::expand(std::span<const double> x, std::span<double> y_out) const {
  for (std::size_t k = 0; k < source.size(); ++k) y_out[k] = y(k, x);
}

void CompactForm::rebase(std::span<double> x) {
  for (std::size_t k = 0; k < source.size(); ++k)
    if (integral[source[k]]) offset[k] = y(k, x);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (integral[i]) x[i] = reference[i] = 0;
}

void CompactForm::center(std::span<double> rate) {
  for (std::size_t i = 0; i < rate.size(); ++i)
    if (integral[i] && i != clock) {
      reference[i] += rate[i];
      rate[i] = 0;
    }
}

std::optional<CompactForm> System::compact_form(std::span<const double>) const { return std::nullopt; }

void System::compact_rhs(double, std::span<const double>, const CompactForm&, std::span<double>) const {
  throw std::logic_error("compact_rhs called on a system without a compact form");
}

}  // namespace rbcstab
