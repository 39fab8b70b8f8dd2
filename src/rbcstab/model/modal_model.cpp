#include "rbcstab/model/modal_model.hpp"

#include <cmath>

#include "rbcstab/core/error.hpp"
#include "rbcstab/core/phasor.hpp"

namespace rbcstab {

// State layout: y[0] = f20 (real by reality), y[1..2] = f21, y[3..4] = f22, y[5+j] = ln Delta_l
// for l = active_[j]. Exactness: with g_{l>=3} = 0, S_{l,m} = 0 for l >= 3 and every f_{l,m}
// obeys f' = (i m/2 + Upsilon_l) f, so Delta_l' = 2 Upsilon_l Delta_l (docs/theory.md, "Model levels").
ModalModel::ModalModel(const Parameters& p, const InitialState& init) : p_(p), L_(init.f.L), f0_(init.f) {
  p_.validate();
  for (int l = 3; l <= init.g.L; ++l)
    if (init.g.excess_area(l) != 0)
      throw InvalidArgument("model",
                            "model = modal cannot hold a stress-free shape with l >= 3 content: use full or auto");
  Upsilon_.push_back(Upsilon_l(p, 2));
  y0_ = {init.f.at(2, 0).real(), init.f.at(2, 1).real(), init.f.at(2, 1).imag(), init.f.at(2, 2).real(),
         init.f.at(2, 2).imag()};
  for (int l = 3; l <= L_; ++l) {
    const double Dl = init.f.excess_area(l);
    if (Dl > 0) {  // a mode with no area stays at zero: it is not carried
      active_.push_back(l);
      Upsilon_.push_back(Upsilon_l(p, l));
      y0_.push_back(std::log(Dl));
    }
  }
  // Delta_l below e^-92 (1e-40) of the total excess area cannot change the sums N and D in double
  // precision; skipping their exp() also avoids libm's slow underflow path for decayed modes.
  u_cut_ = std::log(init.f.total_excess_area()) - 92.0;
  C22_ = shear_drive(p.lambda, 2, 2);
  G3C2_ = Gamma3(p.lambda, 2) * p.inv_C();
  for (int m = 0; m <= 2; ++m) g20_[m] = init.g.at(2, m);
}

void ModalModel::drive(double t, std::complex<double> S[3]) const {
  // g_{2,m}(t) = g_{2,m}(0) e^{i m t/2}: one sincos serves m = 1 and 2.
  const std::complex<double> e1 = unit_phasor(0.5 * t), e2 = e1 * e1;
  S[0] = -G3C2_ * g20_[0];
  S[1] = -G3C2_ * g20_[1] * e1;
  S[2] = -G3C2_ * g20_[2] * e2 + C22_;
}

// Eq. st from the sums of tension.hpp.
template <class U>
AreaBalance ModalModel::balance(std::span<const double> y, const std::complex<double> S[3], U u) const {
  const double a2 = 2;
  const double Delta2 = a2 * (y[0] * y[0] + 2 * (y[1] * y[1] + y[2] * y[2] + y[3] * y[3] + y[4] * y[4]));
  // Re sum_m S_{2,m} conj(f_{2,m}): the -m terms equal the +m ones by reality.
  const double work = S[0].real() * y[0] + 2 * (S[1].real() * y[1] + S[1].imag() * y[2]) +
                      2 * (S[2].real() * y[3] + S[2].imag() * y[4]);
  AreaBalance b;
  b.add_mode(Upsilon_[0], Delta2);
  b.add_work(a2 * work);
  // Modes below the cut add nothing (area_of): skipping them keeps the hot loop free of work and calls.
  for (std::size_t j = 0; j < active_.size(); ++j) {
    const double ul = u(j);
    if (!(ul < u_cut_)) b.add_mode(Upsilon_[j + 1], std::exp(ul));
  }
  return b;
}

AreaBalance ModalModel::balance(std::span<const double> y, const std::complex<double> S[3]) const {
  return balance(y, S, [&](std::size_t j) { return y[5 + j]; });
}

double ModalModel::sigma(double t, std::span<const double> y) const {
  std::complex<double> S[3];
  drive(t, S);
  return balance(y, S).sigma();
}

void ModalModel::l2_rhs(double sigma, std::span<const double> y, const std::complex<double> S[3],
                        std::span<double> dydt) const {
  const double ups2 = Upsilon_[0](sigma);
  dydt[0] = ups2 * y[0] + S[0].real();
  dydt[1] = ups2 * y[1] - 0.5 * y[2] + S[1].real();
  dydt[2] = 0.5 * y[1] + ups2 * y[2] + S[1].imag();
  dydt[3] = ups2 * y[3] - y[4] + S[2].real();
  dydt[4] = y[3] + ups2 * y[4] + S[2].imag();
}

void ModalModel::rhs(double t, std::span<const double> y, std::span<double> dydt) const {
  std::complex<double> S[3];
  drive(t, S);
  const double sigma = balance(y, S).sigma();
  l2_rhs(sigma, y, S, dydt);
  for (std::size_t j = 0; j < active_.size(); ++j) dydt[5 + j] = 2 * Upsilon_[j + 1](sigma);
}

std::optional<CompactForm> ModalModel::compact_form(std::span<const double> y0) const {
  if (active_.empty()) return std::nullopt;
  CompactForm form;
  for (std::size_t k = 0; k < 5; ++k) form.keep(y0[k]);  // the l = 2 block: x[0..4]
  const std::size_t s = form.add_unknown(0.0, true);     // x[5]
  form.clock = form.add_unknown(0.0, true);              // x[6]
  for (std::size_t j = 0; j < active_.size(); ++j)
    form.add_component(s, 2 * Upsilon_[j + 1].slope, y0[5 + j], Upsilon_[j + 1].sigma_c);
  return form;
}

void ModalModel::compact_rhs(double t, std::span<const double> x, const CompactForm& form,
                             std::span<double> dxdt) const {
  std::complex<double> S[3];
  drive(t, S);
  const double sigma = balance(x, S, [&](std::size_t j) { return form.y(5 + j, x); }).sigma();
  l2_rhs(sigma, x, S, dxdt);
  dxdt[5] = sigma - form.reference[5];
  dxdt[form.clock] = 1;
}

void ModalModel::jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> dfdt) const {
  std::complex<double> S[3];
  drive(t, S);
  const AreaBalance b = balance(y, S);
  const double sigma = b.sigma();
  const GrowthRate& Y2 = Upsilon_[0];
  const double ups2 = Y2(sigma), ups2_0 = Y2(0.0);
  const double a2 = 2;
  J.resize(dimension());
  J.diag[0] = ups2;
  for (int i : {1, 3}) {
    J.block_start[i] = 2;
    J.block_start[i + 1] = 0;
    J.diag[i] = J.diag[i + 1] = ups2;
    J.upper[i] = i == 1 ? -0.5 : -1.0;
    J.lower[i] = -J.upper[i];
  }
  // v = dF/d sigma; w = grad sigma from the sums (tension.hpp).
  const double dDelta2[5] = {2 * a2 * y[0], 4 * a2 * y[1], 4 * a2 * y[2], 4 * a2 * y[3], 4 * a2 * y[4]};
  const double dWork[5] = {S[0].real(), 2 * S[1].real(), 2 * S[1].imag(), 2 * S[2].real(), 2 * S[2].imag()};
  for (int i = 0; i < 5; ++i) {
    J.v[i] = Y2.slope * y[i];
    J.w[i] = b.sigma_change(ups2_0 * dDelta2[i] + a2 * dWork[i], Y2.slope * dDelta2[i]);
  }
  for (std::size_t j = 0; j < active_.size(); ++j) {
    const GrowthRate& Yl = Upsilon_[j + 1];
    const double Dl = area_of(y[5 + j]);  // dDelta_l/du_l
    J.v[5 + j] = 2 * Yl.slope;
    J.w[5 + j] = b.sigma_change(Yl(0.0) * Dl, Yl.slope * Dl);
  }
  // Explicit time dependence through g_{2,m}(t): dS/dt = -Gamma3/C (i m/2) g(t).
  std::complex<double> dS[3];
  for (int m = 0; m <= 2; ++m) dS[m] = -G3C2_ * std::complex<double>(0, 0.5 * m) * g20_[m] * unit_phasor(0.5 * m * t);
  const double dwork = dS[0].real() * y[0] + 2 * (dS[1].real() * y[1] + dS[1].imag() * y[2]) +
                       2 * (dS[2].real() * y[3] + dS[2].imag() * y[4]);
  const double dsigma_dt = b.sigma_change(a2 * dwork, 0.0);
  const double dSflat[5] = {dS[0].real(), dS[1].real(), dS[1].imag(), dS[2].real(), dS[2].imag()};
  for (std::size_t i = 0; i < dimension(); ++i) dfdt[i] = (i < 5 ? dSflat[i] : 0.0) + J.v[i] * dsigma_dt;
}

Observation ModalModel::observe(double t, std::span<const double> y) const {
  Observation o;
  o.Delta_l.assign(L_ - 1, 0.0);
  o.Delta_l[0] = 2 * (y[0] * y[0] + 2 * (y[1] * y[1] + y[2] * y[2] + y[3] * y[3] + y[4] * y[4]));
  for (std::size_t j = 0; j < active_.size(); ++j)
    o.Delta_l[active_[j] - 2] = std::exp(y[5 + j]);  // exact, even if denormal
  o.sigma = sigma(t, y);
  o.f22 = {y[3], y[4]};
  o.Delta2 = o.Delta_l[0];
  return o;
}

ModeAmplitudes ModalModel::amplitudes(double t, std::span<const double> y) const {
  ModeAmplitudes f(L_);
  const std::complex<double> f2[3] = {{y[0], 0.0}, {y[1], y[2]}, {y[3], y[4]}};
  for (int m = 0; m <= 2; ++m) {
    f.at(2, m) = f2[m];
    f.at(2, -m) = (m % 2 == 0 ? 1.0 : -1.0) * std::conj(f2[m]);
  }
  // f_{l,m}(t) = f_{l,m}(0) e^{i m t/2} sqrt(Delta_l(t)/Delta_l(0))
  for (std::size_t j = 0; j < active_.size(); ++j) {
    const int l = active_[j];
    const double scale = std::exp(0.5 * (y[5 + j] - y0_[5 + j]));
    for (int m = -l; m <= l; ++m) f.at(l, m) = f0_.at(l, m) * scale * unit_phasor(0.5 * m * t);
  }
  return f;
}

}  // namespace rbcstab
