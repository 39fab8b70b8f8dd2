// Normal forms at LP, BP and HB of equilibrium branches: null vectors by SVD, second and third derivatives of the
// residual by central mixed differences (detail/multilinear.hpp), Kuznetsov's formulas; the orbit branches' points
// go to period_map_normal_form.cpp. docs/continuation.md.
#include "rbcstab/continuation/normal_form_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

#include "rbcstab/continuation/autonomous_orbit.hpp"
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/detail/multilinear.hpp"
#include "rbcstab/continuation/detail/normal_form_core.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

using detail::extend;
using detail::extend_complex;
using detail::kKernel;
using detail::kSingular;
using detail::kVanish;
using detail::Multilinear;
using cd = std::complex<double>;

NormalForm not_computed(NormalFormKind kind, std::string why) {
  return detail::normal_form_not_computed(kind, std::move(why));
}
NormalForm degenerate(NormalForm nf, std::string why) {
  return detail::normal_form_degenerate(std::move(nf), std::move(why));
}

double sign(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }

// The SVD of J with the null vectors of a simple zero singular value, or the reason there is none.
struct Kernel {
  Eigen::VectorXd v, w;  // right and left null vectors, unit
  std::string why;       // non-empty: J is regular or its kernel is more than 1-D
};
// scale: what "zero" is measured against, at least J's largest singular value (a 1-D J that is zero to rounding has
// only itself to compare with: the caller adds |F_p|).
Kernel kernel_of(const Eigen::MatrixXd& J, double scale) {
  Kernel k;
  const Eigen::Index n = J.rows();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  if (!(s[n - 1] <= kSingular * std::max(s[0], scale)))
    k.why = "J is regular: smallest singular value " + format_value(s[n - 1]) + " of " + format_value(s[0]);
  else if (n >= 2 && !(s[n - 2] > kKernel * s[0]))
    k.why = "the kernel of J is more than 1-D (second singular value " + format_value(s[n - 2]) + ")";
  k.v = svd.matrixV().col(n - 1);
  k.w = svd.matrixU().col(n - 1);
  return k;
}

// x solving J x + mu psi = r, v . x = 0: the bordered system, regular when J's kernel (v) and cokernel (psi) are 1-D.
Eigen::VectorXd bordered_solve(const Eigen::MatrixXd& J, const Eigen::VectorXd& v, const Eigen::VectorXd& psi,
                               const Eigen::VectorXd& r) {
  const Eigen::Index n = J.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + 1, n + 1);
  A.topLeftCorner(n, n) = J;
  A.topRightCorner(n, 1) = psi;
  A.bottomLeftCorner(1, n) = v.transpose();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 1);
  rhs.head(n) = r;
  return A.fullPivLu().solve(rhs).head(n);
}

}  // namespace

namespace detail {

NormalForm normal_form_not_computed(NormalFormKind kind, std::string why) {
  NormalForm nf;
  nf.kind = kind;
  nf.criticality = Criticality::not_computed;
  nf.note = std::move(why);
  return nf;
}

NormalForm normal_form_degenerate(NormalForm nf, std::string why) {
  nf.criticality = Criticality::degenerate;
  nf.note = std::move(why);
  return nf;
}

NormalForm fold_from_derivatives(const Eigen::MatrixXd& J, const Eigen::VectorXd& Fp,
                                 const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& Bee) {
  Kernel k = kernel_of(J, Fp.norm());
  if (!k.why.empty()) return not_computed(NormalFormKind::fold, "not a simple fold: " + k.why);
  NormalForm nf;
  nf.kind = NormalFormKind::fold;
  nf.criticality = Criticality::not_applicable;
  const double wv = k.w.dot(k.v);
  if (!(std::abs(wv) > 1e-8)) return degenerate(nf, "<w, v> = 0: a double zero eigenvalue (Bogdanov-Takens)");
  Eigen::VectorXd w = k.w / wv;  // <w, v> = 1
  double wFp = w.dot(Fp);
  if (wFp < 0) {  // orient: <w, F_p> > 0 (keeps <w, v> = 1)
    w = -w;
    k.v = -k.v;
    wFp = -wFp;
  }
  const Eigen::VectorXd ev = extend(k.v, 0.0);
  const Eigen::VectorXd Bvv = Bee(ev);
  if (!Bvv.allFinite()) return not_computed(NormalFormKind::fold, "an evaluation near the point failed");
  const double a = w.dot(Bvv) / 2;
  nf.coefficients = {{"a", a}, {"w_Fp", wFp}};
  if (!(wFp > kSingular * (Fp.norm() + 1e-300)))
    return degenerate(nf, "<w, F_p> = 0: the branch is not a fold in this parameter (a BP or a transcritical point)");
  const double p2 = -a / wFp;
  nf.coefficients.emplace_back("p2", p2);
  // A cusp: a vanishes against the size of B(v, v) and of the first derivatives [J F_p] (states here are O(1); at
  // x' = p - x^3 everything but F_p vanishes, and a is difference noise).
  const double scale = std::max(Bvv.norm() / 2, std::hypot(J.norm(), Fp.norm()));
  if (!(std::abs(a) > kVanish * w.norm() * scale)) return degenerate(nf, "a = 0 to its accuracy: a cusp");
  nf.amplitude = 1 / std::sqrt(std::abs(p2));
  nf.exponent = 0.5;
  nf.side = sign(p2);
  return nf;
}

double circle_peak(const Eigen::VectorXcd& q) {
  Eigen::Matrix2d G;
  const Eigen::VectorXd qr = q.real(), qi = q.imag();
  G << qr.dot(qr), -qr.dot(qi), -qr.dot(qi), qi.dot(qi);
  return 2 * std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(G).eigenvalues()[1]);
}

}  // namespace detail

NormalForm fold_normal_form(const ContinuationProblem& problem, const Eigen::VectorXd& x, double p) {
  Eigen::MatrixXd J;
  Eigen::VectorXd Fp;
  problem.jacobian(x, p, J);
  problem.parameter_derivative(x, p, Fp);
  const Multilinear D(problem, x, p);
  return detail::fold_from_derivatives(J, Fp, [&](const Eigen::VectorXd& e) { return D.B(e, e); });
}

NormalForm branch_point_normal_form(const ContinuationProblem& problem, const Eigen::VectorXd& x, double p,
                                    const Eigen::VectorXd& known, int unstable_side) {
  const Eigen::Index n = problem.dimension();
  require(known.size() == n + 1, "known", static_cast<double>(known.size()), "a vector of dimension n + 1");
  Eigen::MatrixXd J;
  Eigen::VectorXd Fp;
  problem.jacobian(x, p, J);
  problem.parameter_derivative(x, p, Fp);
  const Kernel k = kernel_of(J, Fp.norm());
  if (!k.why.empty()) return not_computed(NormalFormKind::branch_point, "not a simple branch point: " + k.why);
  const Eigen::VectorXd& v0 = k.v;
  const Eigen::VectorXd& psi = k.w;
  // [J F_p] must be rank deficient too (F_p in the range of J), else the point is a fold.
  if (!(std::abs(psi.dot(Fp)) <= kSingular * (J.norm() + Fp.norm())))
    return not_computed(NormalFormKind::branch_point, "not a branch point: F_p is not in the range of J (psi . F_p = " +
                                                          format_value(psi.dot(Fp)) + ")");
  const Eigen::VectorXd w1 = bordered_solve(J, v0, psi, -Fp);
  const Eigen::VectorXd e1 = extend(v0, 0.0), e2 = extend(w1, 1.0);
  const Multilinear D(problem, x, p);
  const double a = psi.dot(D.B(e1, e1)), b = psi.dot(D.B(e1, e2)), c = psi.dot(D.B(e2, e2));
  NormalForm nf;
  nf.kind = NormalFormKind::branch_point;
  nf.coefficients = {{"a", a}, {"b", b}, {"c", c}};
  // The same coefficients on unit directions, for the relative tests.
  const double E2 = e2.norm(), bh = b / E2, ch = c / E2 / E2,
               scale = std::max({std::abs(a), std::abs(bh), std::abs(ch)});
  const double disc = bh * bh - a * ch;
  if (!(scale > 0) || !(disc > kVanish * scale * scale))
    return degenerate(nf, "the algebraic bifurcation equation has no two distinct real roots (b^2 - ac = " +
                              format_value(b * b - a * c) + ")");
  const bool pitchfork = std::abs(a) <= kVanish * scale;
  nf.kind = pitchfork ? NormalFormKind::pitchfork : NormalFormKind::transcritical;
  // The two roots (al, be) of a al^2 + 2 b al be + c be^2 = 0, stably: q = -(b + sign(b) sqrt(b^2 - ac)) gives
  // (q, a) and (c, q); for a pitchfork (a = 0) the first is e1.
  const double sq = std::sqrt(std::max(b * b - a * c, 0.0)), q = -(b + (b >= 0 ? sq : -sq));
  const std::array<Eigen::Vector2d, 2> roots = {Eigen::Vector2d(q, pitchfork ? 0.0 : a), Eigen::Vector2d(c, q)};
  const Eigen::VectorXd kn = known.normalized();
  double align[2];
  for (int i = 0; i < 2; ++i) align[i] = std::abs((roots[i][0] * e1 + roots[i][1] * e2).normalized().dot(kn));
  if (!(std::abs(align[0] - align[1]) > 1e-3))
    return degenerate(nf, "the known branch's direction does not tell the two branches apart");
  const int inew = align[0] > align[1] ? 1 : 0;
  const Eigen::Vector2d r = roots[static_cast<std::size_t>(inew)];
  if (pitchfork && inew == 0) {
    // The new branch leaves along e1: p = p* + p2 s^2 from the third-order solvability condition (with y2 the
    // second-order correction, J y2 = -B(e1, e1)/2 on v0's complement).
    const Eigen::VectorXd y2 = extend(bordered_solve(J, v0, psi, -D.B(e1, e1) / 2), 0.0);
    const double t2 = psi.dot(D.B(e1, y2)), d = psi.dot(D.C(e1, e1, e1));
    const double p2 = -(t2 + d / 6) / b;
    nf.coefficients.emplace_back("d", d);
    nf.coefficients.emplace_back("p2", p2);
    if (!(std::abs(p2) > kVanish * (std::abs(t2) + std::abs(d) / 6) / std::abs(b)))
      return degenerate(nf, "p2 = 0 to its accuracy: the cubic term vanishes");
    nf.amplitude = 1 / std::sqrt(std::abs(p2));
    nf.exponent = 0.5;
    nf.side = sign(p2);
    if (unstable_side == 0) {
      nf.criticality = Criticality::not_computed;
      nf.note = "the unstable count does not change across the point";
    } else {
      nf.criticality = nf.side == unstable_side ? Criticality::supercritical : Criticality::subcritical;
    }
    return nf;
  }
  // A transversal new branch: x - x* = (al v0 + be w1) (p - p*) / be to first order.
  nf.amplitude = (r[0] * v0 + r[1] * w1).norm() / std::abs(r[1]);
  nf.exponent = 1;
  nf.side = 0;
  if (pitchfork) {
    nf.criticality = Criticality::not_computed;
    nf.note = "seen from the symmetric branch: the new branch is the transversal one";
  } else {
    nf.criticality = Criticality::not_applicable;
  }
  return nf;
}

NormalForm hopf_normal_form(const ContinuationProblem& problem, const Eigen::VectorXd& x, double p, double omega) {
  require(std::isfinite(omega) && omega > 0, "omega", omega, "a finite number > 0");
  NormalForm nf;
  nf.kind = NormalFormKind::hopf;
  // How many pairs are critical: several at once (a symmetry, or a double Hopf) have no single l1.
  const Eigen::VectorXcd s = problem.spectrum(x, p);
  int pairs = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s[i].imag() > 1e-8 * (1 + std::abs(s[i])) && std::abs(s[i].real()) <= 1e-6 * (1 + std::abs(s[i]))) ++pairs;
  if (pairs == 0) return not_computed(NormalFormKind::hopf, "no critical pair in the spectrum");
  if (pairs > 1) return degenerate(nf, "degenerate (" + std::to_string(pairs) + " pairs)");
  Eigen::MatrixXd J;
  Eigen::VectorXd Fp;
  problem.jacobian(x, p, J);
  problem.parameter_derivative(x, p, Fp);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J), est(J.transpose());
  Eigen::Index i = 0, j = 0;
  (es.eigenvalues().array() - cd(0, omega)).abs().minCoeff(&i);
  (est.eigenvalues().array() - cd(0, -omega)).abs().minCoeff(&j);
  const double w = es.eigenvalues()[i].imag();
  if (es.eigenvalues().cwiseAbs().minCoeff() <= 1e-8 * (1 + es.eigenvalues().cwiseAbs().maxCoeff()))
    return degenerate(nf, "J is singular: a zero-Hopf point");
  Eigen::VectorXcd q = es.eigenvectors().col(i).normalized();
  Eigen::VectorXcd pl = est.eigenvectors().col(j);
  const cd pq = pl.dot(q);  // p^H q
  if (!(std::abs(pq) > 1e-10 * pl.norm())) return degenerate(nf, "<p, q> = 0: the critical pair is not simple");
  pl /= std::conj(pq);  // <p, q> = 1
  const Multilinear D(problem, x, p);
  const Eigen::VectorXcd eq = extend_complex(q, 0.0), eqb = extend_complex(q.conjugate(), 0.0);
  const Eigen::VectorXcd g20 = D.B(eq, eq), g11 = D.B(eq, eqb), g21 = D.C(eq, eq, eqb);
  const Eigen::MatrixXcd Jc = J.cast<cd>();
  const Eigen::VectorXcd r = Jc.partialPivLu().solve(g11);
  const Eigen::MatrixXcd R2 = cd(0, 2 * w) * Eigen::MatrixXcd::Identity(J.rows(), J.cols()) - Jc;
  const Eigen::VectorXcd s2 = R2.partialPivLu().solve(g20);
  const cd t1 = pl.dot(g21), t2 = -2.0 * pl.dot(D.B(eq, extend_complex(r, 0.0))),
           t3 = pl.dot(D.B(eqb, extend_complex(s2, 0.0)));
  const double l1 = (t1 + t2 + t3).real() / (2 * w);
  // dRe(lambda)/dp = Re <p, (J_p + B(., x_p)) q> with x_p = -J^-1 F_p: the second derivative of the residual
  // in the directions (q, 0) and (x_p, 1).
  const Eigen::VectorXd xp = -J.partialPivLu().solve(Fp);
  const double alpha1 = pl.dot(D.B(eq, extend_complex(xp.cast<cd>(), cd(1, 0)))).real();
  nf.coefficients = {{"l1", l1}, {"omega", w}, {"alpha1", alpha1}};
  if (!(std::abs(l1) > kVanish * (std::abs(t1) + std::abs(t2) + std::abs(t3)) / (2 * w)))
    return degenerate(nf, "l1 = 0 to its accuracy: a Bautin point");
  nf.criticality = l1 < 0 ? Criticality::supercritical : Criticality::subcritical;
  // x - x* = 2 Re(z q) with |z|^2 = -alpha1 (p - p*) / (omega l1).
  if (std::abs(alpha1) > 0) {
    nf.amplitude = detail::circle_peak(q) * std::sqrt(std::abs(alpha1 / (w * l1)));
    nf.exponent = 0.5;
    nf.side = -sign(alpha1 * l1);
  }
  return nf;
}

NormalForm normal_form(const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& sp) {
  if (sp.type == SpecialPointType::LPC || sp.type == SpecialPointType::PD || sp.type == SpecialPointType::NS)
    return period_map_normal_form(problem, sp);
  const NormalFormKind kind = sp.type == SpecialPointType::LP   ? NormalFormKind::fold
                              : sp.type == SpecialPointType::HB ? NormalFormKind::hopf
                                                                : NormalFormKind::branch_point;
  if (problem.stability_kind() != StabilityKind::eigenvalues)
    return not_computed(kind, "normal forms of orbit branches are not computed");
  if (sp.type != SpecialPointType::LP && sp.type != SpecialPointType::BP && sp.type != SpecialPointType::HB)
    return not_computed(kind, "no normal form for " + to_string(sp.type));
  if (sp.status != LocationStatus::located) return not_computed(kind, "the point is not located (a guess)");
  if (problem.dimension() > kNormalFormMaxDimension)
    return not_computed(
        kind, "dimension " + std::to_string(problem.dimension()) + " > " + std::to_string(kNormalFormMaxDimension));
  try {
    if (sp.type == SpecialPointType::LP) return fold_normal_form(problem, sp.x, sp.p);
    if (sp.type == SpecialPointType::HB) {
      const double omega = std::abs(sp.eigenvalue.imag());
      if (!(omega > 0)) return not_computed(kind, "the HB has no crossing frequency (omega = 0)");
      return hopf_normal_form(problem, sp.x, sp.p, omega);
    }
    // BP: the known branch's secant across the point, and the side of p where it gains the unstable mode.
    const std::size_t k = sp.after_index;
    if (k + 1 >= branch.points.size()) return not_computed(kind, "the point is not between two branch points");
    const BranchPoint &A = branch.points[k], &Bq = branch.points[k + 1];
    const Eigen::VectorXd known = extend(Eigen::VectorXd(Bq.x - A.x), Bq.p - A.p);
    const int dp = static_cast<int>(sign(Bq.p - A.p));
    const int side = sp.unstable_after > sp.unstable_before ? dp : (sp.unstable_after < sp.unstable_before ? -dp : 0);
    return branch_point_normal_form(problem, sp.x, sp.p, known, side);
  } catch (const InvalidArgument& e) {
    return not_computed(kind, std::string("the residual refused a difference step: ") + e.what());
  }
}

void attach_normal_forms(const ContinuationProblem& problem, Branch& branch) {
  const bool equilibria = problem.stability_kind() == StabilityKind::eigenvalues;
  const bool orbits = dynamic_cast<const PeriodicOrbitProblem*>(&problem) != nullptr ||
                      dynamic_cast<const AutonomousOrbitProblem*>(&problem) != nullptr;
  for (SpecialPoint& sp : branch.special_points)
    if ((equilibria &&
         (sp.type == SpecialPointType::LP || sp.type == SpecialPointType::BP || sp.type == SpecialPointType::HB)) ||
        (orbits &&
         (sp.type == SpecialPointType::LPC || sp.type == SpecialPointType::PD || sp.type == SpecialPointType::NS)))
      sp.normal_form = normal_form(problem, branch, sp);
}

}  // namespace rbcstab
