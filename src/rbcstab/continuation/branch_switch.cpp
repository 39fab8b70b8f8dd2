#include "rbcstab/continuation/branch_switch.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/core/error.hpp"

namespace rbcstab {

void BranchSwitchOptions::validate() const {
  require(std::isfinite(amplitude) && amplitude > 0, "amplitude", amplitude, "a finite number > 0");
  require(side == 1 || side == -1, "side", side, "+1 or -1");
  require(std::isfinite(kernel_ratio) && kernel_ratio > 0 && kernel_ratio < 1, "kernel_ratio", kernel_ratio,
          "in (0, 1)");
  require(max_newton >= 1, "max_newton", max_newton, "an integer >= 1");
  continuation.validate();
}

bool correct_on_hyperplane(const ContinuationProblem& problem, const Eigen::VectorXd& X_base, const Eigen::VectorXd& d,
                           double h, double tol, int max_newton, Eigen::VectorXd& X) {
  X = X_base + h * d;
  return newton_on_hyperplane(problem, X_base, d, h, tol, max_newton, X);
}

bool newton_on_hyperplane(const ContinuationProblem& problem, const Eigen::VectorXd& X_base, const Eigen::VectorXd& d,
                          double h, double tol, int max_newton, Eigen::VectorXd& X) {
  const Eigen::Index n = problem.dimension(), N = n + 1;
  Eigen::MatrixXd J, A(N, N);
  Eigen::VectorXd F(n), Fp(n), R(N);
  for (int it = 0; it < max_newton; ++it) {
    const Eigen::VectorXd x = X.head(n);
    problem.residual(x, X[n], F);
    problem.jacobian(x, X[n], J);
    problem.parameter_derivative(x, X[n], Fp);
    A.topLeftCorner(n, n) = J;
    A.topRightCorner(n, 1) = Fp;
    A.bottomRows(1) = d.transpose();
    R << F, d.dot(X - X_base) - h;
    const Eigen::VectorXd dX = A.partialPivLu().solve(-R);
    if (!dX.allFinite()) return false;
    X += dX;
    if (dX.lpNorm<Eigen::Infinity>() <= tol * (1 + X.lpNorm<Eigen::Infinity>())) return true;
  }
  return false;
}

BranchSwitchStart switch_start(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& bp,
                               const BranchSwitchOptions& options) {
  options.validate();
  require(bp.type == SpecialPointType::BP, "special_point", static_cast<double>(static_cast<int>(bp.type)),
          "a BP (branch point)");
  require(bp.after_index + 1 < branch.points.size(), "special_point", static_cast<double>(bp.after_index),
          "a special point between two points of the branch");
  const Eigen::Index n = problem.dimension(), N = n + 1;
  BranchSwitchStart out;
  Eigen::VectorXd Xbp(N);
  Xbp << bp.x, bp.p;

  // [J F_p] at the BP: its right null space (two smallest right singular vectors of the n x (n+1)
  // matrix, padded to square so the SVD returns the full V).
  Eigen::MatrixXd J;
  Eigen::VectorXd Fp;
  problem.jacobian(bp.x, bp.p, J);
  problem.parameter_derivative(bp.x, bp.p, Fp);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(N, N);
  A.topLeftCorner(n, n) = J;
  A.topRightCorner(n, 1) = Fp;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  // Descending. A has the rank of [J F_p]: two zero singular values at a simple BP, one elsewhere.
  const Eigen::VectorXd& sv = svd.singularValues();
  out.singular_values = {sv[N - 1], sv[N - 2], N >= 3 ? sv[N - 3] : 0.0};
  if (!(sv[N - 3] > options.kernel_ratio * sv[0])) {
    out.message = "the kernel of [J F_p] at the BP is more than 2-D (third singular value " + format_value(sv[N - 3]) +
                  "): not a simple branch point";
    return out;
  }
  // The kernel is spanned by the last two right singular vectors (A's null space is that of [J F_p]).
  const Eigen::MatrixXd K = svd.matrixV().rightCols(2);
  // The known branch's direction at the BP: the secant of the bracketing points, in the kernel.
  const Eigen::VectorXd& xa = branch.points[bp.after_index].x;
  const Eigen::VectorXd& xb = branch.points[bp.after_index + 1].x;
  Eigen::VectorXd secant(N);
  secant << xb - xa, branch.points[bp.after_index + 1].p - branch.points[bp.after_index].p;
  Eigen::Vector2d c = K.transpose() * secant;
  if (!(c.norm() > 0)) {
    out.message = "the known branch's secant has no component in the kernel";
    return out;
  }
  c.normalize();
  const Eigen::Vector2d c_perp(-c[1], c[0]);
  Eigen::VectorXd d = K * c_perp;
  d.normalize();
  // A reproducible orientation: the largest component positive, then the requested side.
  Eigen::Index imax = 0;
  d.cwiseAbs().maxCoeff(&imax);
  if (d[imax] < 0) d = -d;
  d *= options.side;
  out.direction = d;

  // Corrector: Newton on [F(X); d.(X - X_bp) - h] from the predictor X_bp + h d.
  const double h = options.amplitude;
  Eigen::VectorXd X;
  if (!correct_on_hyperplane(problem, Xbp, d, h, options.continuation.newton_tol, options.max_newton, X)) {
    out.message = "the corrector did not converge off the BP (try another amplitude)";
    return out;
  }
  // Away from the BP: along the new branch p moves from p_bp the way the first point did
  // (pitchfork: p - p_bp ~ s^2 has the sign of dp/ds at s = h; transcritical: that of d_p).
  out.found = true;
  out.x = X.head(n);
  out.p = X[n];
  out.away = X[n] >= bp.p ? Direction::forward : Direction::backward;
  return out;
}

BranchSwitchResult switch_branch(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& bp,
                                 const BranchSwitchOptions& options) {
  BranchSwitchStart start = switch_start(problem, branch, bp, options);
  BranchSwitchResult out;
  out.branch.parameter_names = problem.parameter_names();
  out.direction = std::move(start.direction);
  out.singular_values = start.singular_values;
  out.message = std::move(start.message);
  if (!start.found) return out;
  ContinuationOptions o = options.continuation;
  o.direction = start.away;
  out.branch = continue_branch(problem, start.x, start.p, o);
  out.switched = !out.branch.points.empty();
  out.message = out.branch.message;
  return out;
}

}  // namespace rbcstab
