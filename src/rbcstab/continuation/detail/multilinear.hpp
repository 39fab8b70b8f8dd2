#pragma once
// The second and third derivatives of a problem's residual g(X) = F(x, p), X = (x, p), as the multilinear forms
//   B(u, v) = D^2 g(X0)[u, v],   C(u, v, w) = D^3 g(X0)[u, v, w],
// by central mixed differences of residual() alone (no nested differences of a difference Jacobian):
//   B(u, v) ~ sum_{a,b = +-1} a b g(X0 + h (a u + b v)) / (4 h^2)                 (4 residuals)
//   C(u, v, w) ~ sum_{a,b,c = +-1} a b c g(X0 + h (a u + b v + c w)) / (8 h^3)     (8 residuals)
// on unit directions (the forms are multilinear: the norms are multiplied back). Truncation is O(h^2), rounding
// O(eps |g| / h^2) for B and O(eps |g| / h^3) for C, so h = eps^(1/4) (1 + |X0|) gives B to ~1e-8 and
// h = eps^(1/5) (1 + |X0|) gives C to ~1e-6 (relative to the scale of g and its derivatives). Complex arguments
// are expanded into real and imaginary parts (the forms have real coefficients).
#include <cmath>
#include <complex>
#include <limits>

#include "rbcstab/continuation/dense.hpp"
#include "rbcstab/continuation/problem.hpp"

namespace rbcstab::detail {

class Multilinear {
 public:
  Multilinear(const ContinuationProblem& problem, const Eigen::VectorXd& x, double p)
      : pr_(problem), n_(problem.dimension()), X0_(x.size() + 1) {
    X0_ << x, p;
    const double scale = 1 + X0_.lpNorm<Eigen::Infinity>();
    hB_ = std::pow(std::numeric_limits<double>::epsilon(), 0.25) * scale;
    hC_ = std::pow(std::numeric_limits<double>::epsilon(), 0.2) * scale;
  }
  // Given steps: a residual accurate to less than rounding (the period map's shootings) needs larger ones.
  Multilinear(const ContinuationProblem& problem, const Eigen::VectorXd& x, double p, double hB, double hC)
      : pr_(problem), n_(problem.dimension()), X0_(x.size() + 1), hB_(hB), hC_(hC) {
    X0_ << x, p;
  }
  Eigen::Index n() const { return n_; }

  Eigen::VectorXd B(const Eigen::VectorXd& u, const Eigen::VectorXd& v) const {
    const double nu = u.norm(), nv = v.norm();
    Eigen::VectorXd out = Eigen::VectorXd::Zero(n_);
    if (!(nu > 0 && nv > 0)) return out;
    const Eigen::VectorXd du = u / nu, dv = v / nv;
    for (int a : {1, -1})
      for (int b : {1, -1}) out += (a * b) * g(X0_ + hB_ * (a * du + b * dv));
    return out * (nu * nv / (4 * hB_ * hB_));
  }
  Eigen::VectorXd C(const Eigen::VectorXd& u, const Eigen::VectorXd& v, const Eigen::VectorXd& w) const {
    const double nu = u.norm(), nv = v.norm(), nw = w.norm();
    Eigen::VectorXd out = Eigen::VectorXd::Zero(n_);
    if (!(nu > 0 && nv > 0 && nw > 0)) return out;
    const Eigen::VectorXd du = u / nu, dv = v / nv, dw = w / nw;
    for (int a : {1, -1})
      for (int b : {1, -1})
        for (int c : {1, -1}) out += (a * b * c) * g(X0_ + hC_ * (a * du + b * dv + c * dw));
    return out * (nu * nv * nw / (8 * hC_ * hC_ * hC_));
  }
  Eigen::VectorXcd B(const Eigen::VectorXcd& u, const Eigen::VectorXcd& v) const {
    const Eigen::VectorXd ur = u.real(), ui = u.imag(), vr = v.real(), vi = v.imag();
    const std::complex<double> I(0, 1);
    return B(ur, vr).cast<std::complex<double>>() - B(ui, vi).cast<std::complex<double>>() +
           I * (B(ur, vi) + B(ui, vr)).cast<std::complex<double>>();
  }
  Eigen::VectorXcd C(const Eigen::VectorXcd& u, const Eigen::VectorXcd& v, const Eigen::VectorXcd& w) const {
    // Each argument contributes its real part (factor 1) or its imaginary part (factor i).
    Eigen::VectorXcd out = Eigen::VectorXcd::Zero(n_);
    for (int mask = 0; mask < 8; ++mask) {
      const Eigen::VectorXd a = (mask & 1) ? Eigen::VectorXd(u.imag()) : Eigen::VectorXd(u.real());
      const Eigen::VectorXd b = (mask & 2) ? Eigen::VectorXd(v.imag()) : Eigen::VectorXd(v.real());
      const Eigen::VectorXd c = (mask & 4) ? Eigen::VectorXd(w.imag()) : Eigen::VectorXd(w.real());
      const int k = (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1);
      const std::complex<double> f = std::pow(std::complex<double>(0, 1), k);
      out += f * C(a, b, c).cast<std::complex<double>>();
    }
    return out;
  }

 private:
  Eigen::VectorXd g(const Eigen::VectorXd& X) const {
    Eigen::VectorXd F(n_);
    pr_.residual(X.head(n_), X[n_], F);
    return F;
  }
  const ContinuationProblem& pr_;
  Eigen::Index n_;
  Eigen::VectorXd X0_;
  double hB_ = 0, hC_ = 0;
};

// (v, 0) and (v, 1)-style extensions of state vectors to X = (x, p).
inline Eigen::VectorXd extend(const Eigen::VectorXd& v, double p_component) {
  Eigen::VectorXd X(v.size() + 1);
  X << v, p_component;
  return X;
}
inline Eigen::VectorXcd extend_complex(const Eigen::VectorXcd& v, std::complex<double> p_component) {
  Eigen::VectorXcd X(v.size() + 1);
  X << v, p_component;
  return X;
}

}  // namespace rbcstab::detail
