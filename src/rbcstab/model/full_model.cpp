#include "rbcstab/model/full_model.hpp"

#include <cmath>

#include "rbcstab/core/phasor.hpp"

namespace rbcstab {

FullModel::FullModel(const Parameters& p, const InitialState& init) : p_(p), L_(init.f.L) {
  p_.validate();
  for (int l = 2; l <= L_; ++l) modes_.push_back({Upsilon_l(p, l), Gamma3(p.lambda, l) * p.inv_C(), a_l(l)});
  const std::size_t n = ModeAmplitudes::count(L_);
  C_.resize(n);
  g0_.assign(n, 0.0);
  y0_.resize(2 * n);
  for (int l = 2; l <= L_; ++l)
    for (int m = -l; m <= l; ++m) {
      const std::size_t k = ModeAmplitudes::index(l, m);
      C_[k] = shear_drive(p.lambda, l, m);
      if (l <= init.g.L) g0_[k] = init.g.at(l, m);
      y0_[2 * k] = init.f.values[k].real();
      y0_[2 * k + 1] = init.f.values[k].imag();
    }
}

std::vector<double> FullModel::initial_state() const { return y0_; }

bool FullModel::unforced(int l) const {
  if (l < 2 || l > L_) return false;
  for (int m = -l; m <= l; ++m) {
    const std::size_t k = ModeAmplitudes::index(l, m);
    if (C_[k] != 0.0 || (g0_[k] != 0.0 && modes_[l - 2].G3C != 0.0)) return false;
  }
  return true;
}

bool FullModel::autonomous() const {
  for (int l = 2; l <= L_; ++l)
    for (int m = -l; m <= l; ++m)
      if (m != 0 && g0_[ModeAmplitudes::index(l, m)] != 0.0 && modes_[l - 2].G3C != 0.0) return false;
  return true;
}

void FullModel::drive(double t, std::vector<std::complex<double>>& S) const {
  S.resize(C_.size());
  for (int l = 2; l <= L_; ++l) {
    const double G3C = modes_[l - 2].G3C;
    for (int m = -l; m <= l; ++m) {
      const std::size_t k = ModeAmplitudes::index(l, m);
      // g_{l,m}(t) = g_{l,m}(0) e^{i m t / 2}                              (Eq. eom_g)
      const std::complex<double> g = g0_[k] == 0.0 ? 0.0 : g0_[k] * unit_phasor(0.5 * m * t);
      S[k] = C_[k] - G3C * g;
    }
  }
}

// Eq. st from the sums of tension.hpp: Delta_l = a_l sum_m |f_{l,m}|^2 and W = Re sum a_l S conj(f).
AreaBalance FullModel::balance(std::span<const double> y, const std::vector<std::complex<double>>& S) const {
  AreaBalance b;
  for (int l = 2; l <= L_; ++l) {
    const ModeData& md = modes_[l - 2];
    double norm2 = 0, work = 0;
    for (int m = -l; m <= l; ++m) {
      const std::size_t k = ModeAmplitudes::index(l, m);
      const double re = y[2 * k], im = y[2 * k + 1];
      norm2 += re * re + im * im;
      work += S[k].real() * re + S[k].imag() * im;
    }
    b.add_mode(md.Upsilon, md.a * norm2);
    b.add_work(md.a * work);
  }
  return b;
}

double FullModel::sigma(double t, std::span<const double> y) const {
  std::vector<std::complex<double>> S;
  drive(t, S);
  return balance(y, S).sigma();
}

void FullModel::rhs(double t, std::span<const double> y, std::span<double> dydt) const {
  std::vector<std::complex<double>> S;
  drive(t, S);
  const double sigma = balance(y, S).sigma();
  for (int l = 2; l <= L_; ++l) {
    const double ups = modes_[l - 2].Upsilon(sigma);
    for (int m = -l; m <= l; ++m) {
      const std::size_t k = ModeAmplitudes::index(l, m);
      const double re = y[2 * k], im = y[2 * k + 1], om = 0.5 * m;
      // d f / dt = [i m/2 + Upsilon_l] f + S_{l,m}                         (Eq. eom)
      dydt[2 * k] = ups * re - om * im + S[k].real();
      dydt[2 * k + 1] = om * re + ups * im + S[k].imag();
    }
  }
}

void FullModel::jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> dfdt) const {
  std::vector<std::complex<double>> S;
  drive(t, S);
  const AreaBalance b = balance(y, S);
  const double sigma = b.sigma();
  J.resize(dimension());
  // v = dF/dsigma, w = grad sigma (tension.hpp): dDelta_l/dy = 2 a_l y, dW/dy = a_l S.
  // Explicit time dependence: dS/dt = -Gamma3/C (i m/2) g(t), so dsigma/dt follows from dW/dt alone.
  double dW_dt = 0;
  std::vector<std::complex<double>> dS(S.size());
  for (int l = 2; l <= L_; ++l) {
    const ModeData& md = modes_[l - 2];
    const double ups = md.Upsilon(sigma), ups0 = md.Upsilon(0.0), dups = md.Upsilon.slope;
    for (int m = -l; m <= l; ++m) {
      const std::size_t k = ModeAmplitudes::index(l, m), i = 2 * k;
      const double re = y[i], im = y[i + 1], om = 0.5 * m;
      J.block_start[i] = 2;
      J.block_start[i + 1] = 0;
      J.diag[i] = J.diag[i + 1] = ups;
      J.upper[i] = -om;
      J.lower[i] = om;
      J.v[i] = dups * re;
      J.v[i + 1] = dups * im;
      J.w[i] = b.sigma_change(2 * md.a * re * ups0 + md.a * S[k].real(), 2 * md.a * re * dups);
      J.w[i + 1] = b.sigma_change(2 * md.a * im * ups0 + md.a * S[k].imag(), 2 * md.a * im * dups);
      const std::complex<double> g = g0_[k] == 0.0 ? 0.0 : g0_[k] * unit_phasor(0.5 * m * t);  // as in drive()
      dS[k] = -md.G3C * std::complex<double>(0, om) * g;
      dW_dt += md.a * (dS[k].real() * re + dS[k].imag() * im);
    }
  }
  const double dsigma_dt = b.sigma_change(dW_dt, 0.0);
  for (std::size_t k = 0; k < dS.size(); ++k) {
    dfdt[2 * k] = dS[k].real() + J.v[2 * k] * dsigma_dt;
    dfdt[2 * k + 1] = dS[k].imag() + J.v[2 * k + 1] * dsigma_dt;
  }
}

Observation FullModel::observe(double t, std::span<const double> y) const {
  Observation o;
  o.Delta_l.resize(L_ - 1);
  for (int l = 2; l <= L_; ++l) {
    double norm2 = 0;
    for (int m = -l; m <= l; ++m) {
      const std::size_t k = ModeAmplitudes::index(l, m);
      norm2 += y[2 * k] * y[2 * k] + y[2 * k + 1] * y[2 * k + 1];
    }
    o.Delta_l[l - 2] = modes_[l - 2].a * norm2;
  }
  o.sigma = sigma(t, y);
  const std::size_t k22 = ModeAmplitudes::index(2, 2);
  o.f22 = {y[2 * k22], y[2 * k22 + 1]};
  o.Delta2 = o.Delta_l[0];
  return o;
}

ModeAmplitudes FullModel::amplitudes(double, std::span<const double> y) const {
  ModeAmplitudes f(L_);
  for (std::size_t k = 0; k < f.values.size(); ++k) f.values[k] = {y[2 * k], y[2 * k + 1]};
  return f;
}

}  // namespace rbcstab
