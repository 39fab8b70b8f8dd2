#pragma once
// What the equilibrium normal forms (normal_form_analysis.cpp) and the period map's (period_map_normal_form.cpp)
// share: the rank and vanishing thresholds, and the fold's coefficients from J, F_p and the multilinear forms (an
// LP of F and an LPC of the period map P, with J = DP - I, are the same computation).
#include <functional>
#include <string>

#include "rbcstab/continuation/dense.hpp"
#include "rbcstab/continuation/normal_form.hpp"

namespace rbcstab::detail {

// Rank tests: a singular value below kSingular x the largest counts as zero (located points are singular to
// ~1e-10); a second one must exceed kKernel x the largest (branch_switch's kernel_ratio) for a simple point.
inline constexpr double kSingular = 1e-6;
inline constexpr double kKernel = 1e-4;
// A coefficient below kVanish x the scale of the terms it is made of vanishes: the third-derivative differences
// are accurate to ~1e-6 of that scale, the second-derivative ones to ~1e-8 (multilinear.hpp).
inline constexpr double kVanish = 1e-5;

NormalForm normal_form_not_computed(NormalFormKind kind, std::string why);
NormalForm normal_form_degenerate(NormalForm nf, std::string why);

// The fold at a point where J (n x n) has a 1-D kernel: coefficients a, w_Fp, p2 and the branch's amplitude law
// (fold_normal_form's conventions), kind fold; Bee(e): the second derivative B(e, e) for e = (v, 0) in (x, p).
NormalForm fold_from_derivatives(const Eigen::MatrixXd& J, const Eigen::VectorXd& Fp,
                                 const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& Bee);

// The peak over t of |2 Re(e^{it} q)|_2: 2 sqrt(g), g the largest eigenvalue of the Gram matrix of (Re q, Im q)
// (the amplitude of a Hopf orbit or an invariant circle x* + 2 Re(z q) with |z| = 1).
double circle_peak(const Eigen::VectorXcd& q);

}  // namespace rbcstab::detail
