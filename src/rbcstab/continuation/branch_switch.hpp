#pragma once
// Branch switching at a simple branch point (BP), generic in the engine: at the BP the kernel of
// [J F_p] is two-dimensional; it holds the known branch's tangent and the new branch's direction.
// The new direction is the kernel vector orthogonal to the known tangent (exact for a pitchfork,
// whose branches cross at right angles in the kernel up to scaling; for a transcritical point it is
// the component that leaves the known branch). Predictor X_bp + h d, Newton on [F; d.(X - X_bp) - h],
// then the engine continues away from the BP.
#include <array>
#include <string>

#include "rbcstab/continuation/continuation.hpp"

namespace rbcstab {

// The default predictor step off a BP (BranchSwitchOptions::amplitude; the diagram's default too).
inline constexpr double kDefaultSwitchAmplitude = 1e-3;

struct BranchSwitchOptions {
  double amplitude = kDefaultSwitchAmplitude;  // |h|: predictor step off the BP; small enough for Newton, large enough
                                               // that the corrector does not fall back onto the known branch
  int side = 1;                                // +1 or -1: which of the two halves (+d or -d) of the new branch
  double kernel_ratio = 1e-4;        // sigma_{n-1}/sigma_max of [J F_p] must exceed this: a 2-D kernel, not 3-D
  int max_newton = 20;               // corrector iterations for the first point
  ContinuationOptions continuation;  // for the new branch (its direction is chosen away from the BP)
  void validate() const;             // throws InvalidArgument naming the field
};

struct BranchSwitchResult {
  bool switched = false;  // false: message says why (not a simple BP, corrector failed)
  std::string message;
  Eigen::VectorXd direction;                // d in (x, p), unit
  std::array<double, 3> singular_values{};  // the three smallest of [J F_p] at the BP, ascending
  Branch branch;                            // the bifurcating branch, starting next to the BP
};

// Newton on [F(X); d.(X - X_base) - h] (X = (x, p)) from X as given, to max|dX| <= tol (1 + |X|): the point of
// the branch on the hyperplane at distance h from X_base along d. False: no convergence (X is then the last iterate).
bool newton_on_hyperplane(const ContinuationProblem& problem, const Eigen::VectorXd& X_base, const Eigen::VectorXd& d,
                          double h, double tol, int max_newton, Eigen::VectorXd& X);
// newton_on_hyperplane from the predictor X_base + h d: the first point of a branch that leaves X_base along d
// (BP, HB and PD switching).
bool correct_on_hyperplane(const ContinuationProblem& problem, const Eigen::VectorXd& X_base, const Eigen::VectorXd& d,
                           double h, double tol, int max_newton, Eigen::VectorXd& X);

// The first point of the bifurcating branch (the corrector's result) and the way away from the BP, before it is
// continued: what recursive diagrams (bifurcation_tree.hpp) check for duplicates before following it.
struct BranchSwitchStart {
  bool found = false;  // false: message says why
  std::string message;
  Eigen::VectorXd direction;  // d in (x, p), unit
  std::array<double, 3> singular_values{};
  Eigen::VectorXd x;  // the first point
  double p = 0;
  Direction away = Direction::forward;  // the continuation direction that leaves the BP
};
BranchSwitchStart switch_start(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& bp,
                               const BranchSwitchOptions& options = {});

// bp must be a special point of type BP of `branch` (continued with `problem`): switch_start, then continued.
BranchSwitchResult switch_branch(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& bp,
                                 const BranchSwitchOptions& options = {});

}  // namespace rbcstab
