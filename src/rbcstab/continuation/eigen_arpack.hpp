#pragma once
// A few eigenvalues of a large real nonsymmetric linear operator by ARPACK's implicitly restarted
// Arnoldi method (dnaupd/dneupd), matrix-free: the operator is given only by its action x -> A x,
// and shift-invert (mode 3) by a user solve x -> (A - s I)^{-1} x. For the model levels,
// StructuredJacobian gives both in O(n) (shifted_inverse below).
//
// Limits a user must know: in exact arithmetic a single-vector Krylov method sees one copy of a
// semisimple multiple eigenvalue (the full model's (l, m) and (l, -m) modes give equal pairs);
// rounding usually reveals the second copy (it did in every test here), but do not rely on counts.
// ARPACK is not reentrant (Fortran SAVE state): calls from several threads are serialised inside.
#include <complex>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/model/structured_jacobian.hpp"

namespace rbcstab {

// y = A x (both of the operator's size).
using LinearOperator = std::function<void(std::span<const double> x, std::span<double> y)>;
// y = (A - s I)^{-1} x; returns false when the shifted operator is singular to working precision.
using ShiftedSolve = std::function<bool(std::span<const double> x, std::span<double> y)>;

enum class ArpackWhich {
  largest_real,       // rightmost eigenvalues (stability of equilibria); regular mode, needs apply only
  largest_magnitude,  // largest |lambda| (Floquet multipliers of a monodromy action); regular mode
  nearest_shift       // closest to the real shift: shift-invert mode 3, needs the shifted solve
};
template <>
struct EnumTable<ArpackWhich> {
  static constexpr EnumName<ArpackWhich> entries[] = {{ArpackWhich::largest_real, "largest_real"},
                                                      {ArpackWhich::largest_magnitude, "largest_magnitude"},
                                                      {ArpackWhich::nearest_shift, "nearest_shift"}};
};

struct ArpackOptions {
  int k = 6;                  // eigenvalues wanted
  int ncv = 0;                // Krylov basis size; 0 = min(n, max(2k + 1, k + 20)): ARPACK needs k + 2 <= ncv <= n
  double tol = 1e-12;         // ARPACK's relative Ritz accuracy |r| <= tol |theta| (0: machine precision)
  int max_iterations = 3000;  // Arnoldi restarts before giving up (status max_iterations)
  ArpackWhich which = ArpackWhich::largest_real;
  double shift = 0;           // real shift s for nearest_shift (ARPACK returns A's eigenvalues for a real shift)
  bool eigenvectors = false;  // also return Ritz vectors (and residuals |A v - lambda v| / |v|)
  void validate(std::size_t n) const;  // throws InvalidArgument naming the field
};

enum class ArpackStatus {
  converged,       // all k Ritz values met tol
  max_iterations,  // ARPACK stopped after max_iterations restarts (values are the converged ones)
  solve_failed,    // the shifted solve reported a singular operator (shift on or too near the spectrum)
  failed           // ARPACK returned an error code (message has it)
};
template <>
struct EnumTable<ArpackStatus> {
  static constexpr EnumName<ArpackStatus> entries[] = {{ArpackStatus::converged, "converged"},
                                                       {ArpackStatus::max_iterations, "max_iterations"},
                                                       {ArpackStatus::solve_failed, "solve_failed"},
                                                       {ArpackStatus::failed, "failed"}};
};

struct ArpackResult {
  ArpackStatus status = ArpackStatus::failed;
  std::string message;
  Eigen::VectorXcd eigenvalues;   // converged values, best first by `which` (at most k)
  Eigen::MatrixXcd eigenvectors;  // n x eigenvalues.size() when asked, unit 2-norm
  Eigen::VectorXd residuals;      // |A v - lambda v| per eigenvector when asked (one more apply each)
  int iterations = 0;             // Arnoldi restarts (iparam(3))
  int converged = 0;              // Ritz values converged (iparam(5))
  std::size_t applications = 0;   // operator applications (apply, or the shifted solve in mode 3)
};

// `apply` is required for largest_real / largest_magnitude and for residuals; `solve` for nearest_shift.
ArpackResult arpack_eigenvalues(std::size_t n, const LinearOperator& apply, const ShiftedSolve& solve,
                                const ArpackOptions& options);

// (J - s I)^{-1} for a structured Jacobian J = M + v w^T: -(1/s)(I - J/s)^{-1}, O(n) by
// StructuredJacobian::solve_shifted. s must be nonzero (InvalidArgument "shift").
ShiftedSolve shifted_inverse(const StructuredJacobian& J, double shift);

}  // namespace rbcstab
