#pragma once
// Stability labels with a certificate (stability_certificate.cpp): the margin of the critical eigenvalue or
// Floquet multiplier from the stability boundary, its error bound, and which term decided an uncertain label.
#include <limits>

#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/core/enum_table.hpp"

namespace rbcstab {

// A stability label with a certificate: uncertain when the critical eigenvalue (multiplier) is not
// farther from the stability boundary than its error estimate.
enum class Stability { stable, unstable, uncertain };
template <>
struct EnumTable<Stability> {
  static constexpr EnumName<Stability> entries[] = {
      {Stability::stable, "stable"}, {Stability::unstable, "unstable"}, {Stability::uncertain, "uncertain"}};
};

// What made a label uncertain (none: it is not): the spectrum is empty or not finite (no margin), a
// spectral value has no finite error bound, or the largest term of margin_error reaches |margin|: the
// spectrum's own error, the margin's change when the state moves by its error, or (special points) its
// change across the located bracket; unknown: read from a branch file written before the reason was kept.
enum class CertificateTerm { none, spectrum, error_bound, spectral_error, state_error, location, unknown };
template <>
struct EnumTable<CertificateTerm> {
  static constexpr EnumName<CertificateTerm> entries[] = {{CertificateTerm::none, "none"},
                                                          {CertificateTerm::spectrum, "spectrum"},
                                                          {CertificateTerm::error_bound, "error_bound"},
                                                          {CertificateTerm::spectral_error, "spectral_error"},
                                                          {CertificateTerm::state_error, "state_error"},
                                                          {CertificateTerm::location, "location"},
                                                          {CertificateTerm::unknown, "unknown"}};
};

// margin: the signed distance of the critical spectral value from the stability boundary, > 0 on the
// stable side: -max Re(lambda) for eigenvalues, 1 - max |mu| over the nontrivial Floquet multipliers.
// margin_error: an estimate of its error (docs/continuation.md, "Stability certificates").
struct StabilityCertificate {
  Stability stability = Stability::uncertain;
  double margin = std::numeric_limits<double>::quiet_NaN();
  double margin_error = std::numeric_limits<double>::quiet_NaN();
  CertificateTerm uncertain_because = CertificateTerm::spectrum;
};
// From a certified spectrum: the margin and the range of the critical value the errors allow,
// [max(a_i - e_i), max(a_i + e_i)] with a_i = Re(lambda_i) or |mu_i| - 1, so margin_error is the larger
// distance of the margin from its ends. Uncertain when |margin| <= margin_error, an error is unknown
// (NaN) or the spectrum is empty.
StabilityCertificate certify(const CertifiedSpectrum& spectrum, StabilityKind kind);
// The certificate of a solution x of F(x, p) = 0 found by Newton to newton_tol (a start point): the
// problem's refined certified spectrum, widened by the margin's change when x moves by its error (the
// next Newton step, at least newton_tol (1 + |x|) in size).
StabilityCertificate certify_solution(const ContinuationProblem& problem, const Eigen::VectorXd& x, double p,
                                      double newton_tol = 1e-12);

}  // namespace rbcstab
