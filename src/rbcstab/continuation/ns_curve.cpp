#include "rbcstab/continuation/ns_curve.hpp"

#include <cmath>

#include "rbcstab/continuation/detail/minimal_augmentation.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

Eigen::MatrixXd squared_pencil(const Eigen::MatrixXd& M, double kappa) {
  return M * M - 2 * kappa * M + Eigen::MatrixXd::Identity(M.rows(), M.cols());
}

}  // namespace

NeimarkSackerCurveProblem::NeimarkSackerCurveProblem(const ForcedSystem2& system, const OrbitOptions& options,
                                                     const SpecialPoint& ns, double p2)
    : system_(system), slice_(system, p2), orbit_(slice_, options), n_(system.dimension()), m_(orbit_.dimension()) {
  if (ns.type != SpecialPointType::NS || ns.status != LocationStatus::located)
    throw InvalidArgument("ns", "an NS curve starts from a located NS point (got " + to_string(ns.type) + ", " +
                                    to_string(ns.status) + ")");
  require(ns.x.size() == m_, "ns", static_cast<double>(ns.x.size()), "a point of the orbit problem's dimension");
  require(n_ >= 2, "dimension", static_cast<double>(n_), ">= 2 (an NS pair needs two multipliers)");
  const double theta = std::abs(std::arg(ns.eigenvalue));
  require(theta > 0 && theta < kPi, "ns.eigenvalue", theta,
          "a multiplier e^{i theta} with 0 < theta < pi (theta = 0, pi are 1:1 / 1:2 resonances)");
  const double kappa = std::cos(theta);
  const Floquet fl = floquet(ns.x, ns.p, p2);
  detail::null_borders(squared_pencil(fl.monodromy, kappa), 2, B_, C_);
  start_.resize(m_ + 2);
  start_ << ns.x, ns.p, kappa;

  // Two of the four entries of G, chosen at the start (one difference sweep serves all six pairs).
  Eigen::MatrixXd J;
  shooting_rows(start_, p2, J);
  entries_ = detail::best_conditioned_entries(J, g_derivatives(start_, p2));
}

void NeimarkSackerCurveProblem::at(double p2) const {
  if (slice_.p2() != p2) {
    slice_.set_p2(p2);
    orbit_.clear_cache();
  }
}

Floquet NeimarkSackerCurveProblem::floquet(const Eigen::VectorXd& X, double p1, double p2) const {
  at(p2);
  return orbit_.floquet(X, p1);
}

Eigen::Matrix2d NeimarkSackerCurveProblem::test_functions(const Eigen::VectorXd& X, double p1, double kappa,
                                                          double p2) const {
  return detail::bordered_g(squared_pencil(floquet(X, p1, p2).monodromy, kappa), B_, C_);
}

void NeimarkSackerCurveProblem::residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const {
  require(X.size() == m_ + 2, "X", static_cast<double>(X.size()), "(shooting unknowns, p1, kappa)");
  const Eigen::VectorXd x = X.head(m_);
  Eigen::VectorXd F(m_);
  at(p2);
  orbit_.residual(x, X[m_], F);
  detail::rank_two_residual(F, test_functions(x, X[m_], X[m_ + 1], p2), entries_, R);
}

Eigen::MatrixXd NeimarkSackerCurveProblem::g_derivatives(const Eigen::VectorXd& X, double p2) const {
  return detail::g_entry_derivatives(
      X, [&](const Eigen::VectorXd& Z) { return test_functions(Z.head(m_), Z[m_], Z[m_ + 1], p2); });
}

void NeimarkSackerCurveProblem::shooting_rows(const Eigen::VectorXd& X, double p2, Eigen::MatrixXd& J) const {
  const Eigen::VectorXd x = X.head(m_);
  J.setZero(m_ + 2, m_ + 2);
  Eigen::MatrixXd Fx;
  Eigen::VectorXd Fp;
  at(p2);
  orbit_.jacobian(x, X[m_], Fx);
  orbit_.parameter_derivative(x, X[m_], Fp);
  J.topLeftCorner(m_, m_) = Fx;
  J.col(m_).head(m_) = Fp;  // F does not depend on kappa
}

void NeimarkSackerCurveProblem::jacobian(const Eigen::VectorXd& X, double p2, Eigen::MatrixXd& J) const {
  require(X.size() == m_ + 2, "X", static_cast<double>(X.size()), "(shooting unknowns, p1, kappa)");
  shooting_rows(X, p2, J);
  detail::set_g_rows(J, g_derivatives(X, p2), entries_);
}

Eigen::VectorXcd NeimarkSackerCurveProblem::spectrum(const Eigen::VectorXd& X, double p2) const {
  return floquet(X.head(m_), X[m_], p2).multipliers;
}

CertifiedSpectrum NeimarkSackerCurveProblem::certified_spectrum(const Eigen::VectorXd& X, double p2,
                                                                bool refine) const {
  at(p2);
  return orbit_.certified_spectrum(X.head(m_), X[m_], refine);
}

NeimarkSackerKind NeimarkSackerCurveProblem::classify(const Eigen::VectorXd& X) const {
  require(X.size() == m_ + 2, "X", static_cast<double>(X.size()), "(shooting unknowns, p1, kappa)");
  NeimarkSackerKind k;
  k.kappa = X[m_ + 1];
  if (std::abs(k.kappa) <= 1) {
    k.theta = std::acos(k.kappa);
    return k;
  }
  // mu + 1/mu = 2 kappa: mu = kappa + sign(kappa) sqrt(kappa^2 - 1), the root with |mu| > 1 (no cancellation).
  k.neutral_saddle = true;
  k.theta = k.kappa > 0 ? 0.0 : kPi;
  k.real_multiplier = k.kappa + std::copysign(std::sqrt(k.kappa * k.kappa - 1), k.kappa);
  return k;
}

UserEvent NeimarkSackerCurveProblem::resonance_event(const std::string& name) const {
  const Eigen::Index m = m_;
  return UserEvent{name, [m](const Eigen::VectorXd& X, double) { return 1 - X[m + 1] * X[m + 1]; }};
}

}  // namespace rbcstab
