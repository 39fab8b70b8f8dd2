// Two-parameter orbit problems: ForcedSystem2's parameter derivative by central differences, the
// shooting problem at the slice's p2, and the PD curve.
#include "rbcstab/continuation/orbit_two_parameter.hpp"

#include <span>
#include <vector>

#include "rbcstab/continuation/detail/finite_difference.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

// Central-difference step in p: cube root of eps balances truncation against rounding.
using detail::fd_step;

}  // namespace

void ForcedSystem2::parameter_derivative(double t, std::span<const double> x, double p1, double p2,
                                         std::span<double> fp) const {
  const double h = fd_step(p1);
  std::vector<double> fm(fp.size());
  rhs(t, x, p1 + h, p2, fp);
  rhs(t, x, p1 - h, p2, fm);
  for (std::size_t i = 0; i < fp.size(); ++i) fp[i] = (fp[i] - fm[i]) / (2 * h);
}

// ---------------------------------------------------------------- two parameters

void OrbitTwoParameterProblem::at(double p2) const {
  if (slice_.p2() != p2) {
    slice_.set_p2(p2);
    orbit_.clear_cache();
  }
}

void OrbitTwoParameterProblem::residual(const Eigen::VectorXd& X, double p1, double p2, Eigen::VectorXd& F) const {
  at(p2);
  orbit_.residual(X, p1, F);
}

void OrbitTwoParameterProblem::jacobian(const Eigen::VectorXd& X, double p1, double p2, Eigen::MatrixXd& J) const {
  at(p2);
  orbit_.jacobian(X, p1, J);
}

void OrbitTwoParameterProblem::parameter_derivative(const Eigen::VectorXd& X, double p1, double p2,
                                                    Eigen::VectorXd& Fp) const {
  at(p2);
  orbit_.parameter_derivative(X, p1, Fp);
}

void OrbitTwoParameterProblem::antiperiodic_jacobian(const Eigen::VectorXd& X, double p1, double p2,
                                                     Eigen::MatrixXd& J) const {
  at(p2);
  orbit_.antiperiodic_jacobian(X, p1, J);
}

Eigen::VectorXcd OrbitTwoParameterProblem::multipliers(const Eigen::VectorXd& X, double p1, double p2) const {
  at(p2);
  return orbit_.spectrum(X, p1);
}

CertifiedSpectrum OrbitTwoParameterProblem::certified_spectrum(const Eigen::VectorXd& X, double p1, double p2,
                                                               bool refine) const {
  at(p2);
  return orbit_.certified_spectrum(X, p1, refine);
}

OrbitSummary OrbitTwoParameterProblem::summary(const Eigen::VectorXd& X, double p1, double p2) const {
  at(p2);
  return orbit_.summary(X, p1);
}

OrbitPoint OrbitTwoParameterProblem::point_at(const Eigen::VectorXd& X, double p1, double p2, double t) const {
  at(p2);
  return orbit_.point_at(X, p1, t);
}

PeriodDoublingCurveProblem::PeriodDoublingCurveProblem(const OrbitTwoParameterProblem& base, const SpecialPoint& pd,
                                                       double p2)
    : SingularityCurveProblem(base), orbit_base_(base) {
  if (pd.type != SpecialPointType::PD || pd.status != LocationStatus::located)
    throw InvalidArgument("pd", "a PD curve starts from a located PD point (got " + to_string(pd.type) + ", " +
                                    to_string(pd.status) + ")");
  start_at(pd, p2);
}

Eigen::VectorXcd PeriodDoublingCurveProblem::spectrum(const Eigen::VectorXd& X, double p2) const {
  const Eigen::Index n = orbit_base_.dimension();
  return orbit_base_.multipliers(X.head(n), X[n], p2);
}

}  // namespace rbcstab
