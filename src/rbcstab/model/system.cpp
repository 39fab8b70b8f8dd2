#include "rbcstab/model/system.hpp"

namespace rbcstab {

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
