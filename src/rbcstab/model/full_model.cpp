#include <cmath>

#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/levels.hpp"

namespace rbcstab {

double ModeAmplitudes::excess_area(int l) const {
  double s = 0;
  for (int m = -l; m <= l; ++m) s += std::norm(at(l, m));
  return a_l(l) * s;
}

double ModeAmplitudes::total_excess_area() const {
  double s = 0;
  for (int l = 2; l <= L; ++l) s += excess_area(l);
  return s;
}

FullModel::FullModel(const Parameters& p, const InitialState& init) : p_(p), L_(init.f.L) {
  p_.validate();
  for (int l = 2; l <= L_; ++l)
    modes_.push_back({Gamma1(p.lambda, l), Gamma2(p.lambda, l), Gamma3(p.lambda, l), a_l(l)});
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

void FullModel::drive(double t, std::vector<std::complex<double>>& S) const {
  S.resize(C_.size());
  for (int l = 2; l <= L_; ++l) {
    const double G3C = modes_[l - 2].Gamma3 * p_.inv_C();
    for (int m = -l; m <= l; ++m) {
      const std::size_t k = ModeAmplitudes::index(l, m);
      // g_{l,m}(t) = g_{l,m}(0) e^{i m t / 2}                              (Eq. eom_g)
      const std::complex<double> g = g0_[k] == 0.0 ? 0.0 : g0_[k] * std::polar(1.0, 0.5 * m * t);
      S[k] = C_[k] - G3C * g;
    }
  }
}

namespace {
struct FullSums {
  double N = 0, D = 0;
};
// sigma = -N / D with N = sum_l (Gamma1 + alpha Gamma3) Delta_l + B Re sum a_l S conj(f),
// D = sum_l Gamma2 Delta_l (Eq. st with the Re the printed form lacks, docs/theory.md; D < 0 while Delta > 0).
template <class Modes>
FullSums full_sums(const Modes& modes, int L, double alpha, double B, std::span<const double> y,
                   const std::vector<std::complex<double>>& S) {
  FullSums s;
  for (int l = 2; l <= L; ++l) {
    const auto& md = modes[l - 2];
    double norm2 = 0, drive = 0;
    for (int m = -l; m <= l; ++m) {
      const std::size_t k = ModeAmplitudes::index(l, m);
      const double re = y[2 * k], im = y[2 * k + 1];
      norm2 += re * re + im * im;
      drive += S[k].real() * re + S[k].imag() * im;
    }
    const double Delta_l = md.a * norm2;
    s.N += (md.Gamma1 + alpha * md.Gamma3) * Delta_l + B * md.a * drive;
    s.D += md.Gamma2 * Delta_l;
  }
  return s;
}
}  // namespace

double FullModel::sigma(double t, std::span<const double> y) const {
  std::vector<std::complex<double>> S;
  drive(t, S);
  const FullSums s = full_sums(modes_, L_, p_.alpha(), p_.B, y, S);
  return -s.N / s.D;
}

void FullModel::rhs(double t, std::span<const double> y, std::span<double> dydt) const {
  std::vector<std::complex<double>> S;
  drive(t, S);
  const FullSums s = full_sums(modes_, L_, p_.alpha(), p_.B, y, S);
  const double sigma = -s.N / s.D;
  for (int l = 2; l <= L_; ++l) {
    const double ups = Upsilon(p_, l, sigma);
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
  const FullSums s = full_sums(modes_, L_, p_.alpha(), p_.B, y, S);
  const double sigma = -s.N / s.D;
  const double alpha = p_.alpha();
  J.resize(dimension());
  // dS/dt = -Gamma3/C (i m/2) g(t); d sigma/dt = -B sum a Re(dS/dt conj f) / D.
  double dsigma_dt_num = 0;
  std::vector<std::complex<double>> dS(S.size());
  for (int l = 2; l <= L_; ++l) {
    const auto& md = modes_[l - 2];
    const double ups = Upsilon(p_, l, sigma);
    const double dups = md.Gamma2 / p_.B;
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
      // grad sigma = -(grad N + sigma grad D) / D
      const double cN = 2 * md.a * (md.Gamma1 + alpha * md.Gamma3), cD = 2 * md.a * md.Gamma2;
      J.w[i] = -((cN + sigma * cD) * re + p_.B * md.a * S[k].real()) / s.D;
      J.w[i + 1] = -((cN + sigma * cD) * im + p_.B * md.a * S[k].imag()) / s.D;
      const std::complex<double> g = g0_[k] == 0.0 ? 0.0 : g0_[k] * std::polar(1.0, 0.5 * m * t);  // as in drive()
      dS[k] = -md.Gamma3 * p_.inv_C() * std::complex<double>(0, om) * g;
      dsigma_dt_num += md.a * (dS[k].real() * re + dS[k].imag() * im);
    }
  }
  const double dsigma_dt = -p_.B * dsigma_dt_num / s.D;
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
