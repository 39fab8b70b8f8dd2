#pragma once
// The exact modal reduction: the l = 2 block (f20, f21, f22) plus u_l = ln Delta_l for every l >= 3 that
// holds area. Exact when the stress-free shape has no l >= 3 content (docs/theory.md, "Model levels").
#include <cmath>
#include <complex>
#include <vector>

#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/model/system.hpp"
#include "rbcstab/model/tension.hpp"

namespace rbcstab {

class ModalModel final : public System {
 public:
  ModalModel(const Parameters& p, const InitialState& init);
  ModelLevel level() const override { return ModelLevel::modal; }
  std::size_t dimension() const override { return 5 + active_.size(); }
  int L() const override { return L_; }
  void rhs(double t, std::span<const double> y, std::span<double> dydt) const override;
  void jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> dfdt) const override;
  Observation observe(double t, std::span<const double> y) const override;
  std::vector<double> initial_state() const override { return y0_; }
  ModeAmplitudes amplitudes(double t, std::span<const double> y) const override;
  // x = (the l = 2 block, s = int_t0^t (sigma - sigma_ref) dt, tau = t - t0):
  // u_l = u_l(t0) + 2 Upsilon_l' (s + (sigma_ref - sigma_l^c) tau) exactly, since u_l' = 2 Upsilon_l(sigma) is
  // affine in sigma (CompactForm; the stepper sets sigma_ref). None without an active mode (x would be y).
  std::optional<CompactForm> compact_form(std::span<const double> y0) const override;
  void compact_rhs(double t, std::span<const double> x, const CompactForm& form, std::span<double> dxdt) const override;
  double sigma(double t, std::span<const double> y) const;
  const std::vector<int>& active_modes() const { return active_; }  // the l >= 3 carried as u_l

 private:
  void drive(double t, std::complex<double> S[3]) const;  // S_{2,0}, S_{2,1}, S_{2,2}
  AreaBalance balance(std::span<const double> y, const std::complex<double> S[3]) const;
  // The sums with u_l of active mode j given by u(j).
  template <class U>
  AreaBalance balance(std::span<const double> f2, const std::complex<double> S[3], U u) const;
  // The l = 2 block's derivative at tension sigma.
  void l2_rhs(double sigma, std::span<const double> f2, const std::complex<double> S[3], std::span<double> d) const;
  Parameters p_;
  int L_;
  std::vector<int> active_;
  std::vector<GrowthRate> Upsilon_;  // l = 2 (index 0) and the active l
  std::complex<double> C22_, g20_[3];
  double G3C2_ = 0;   // Gamma3^2 / C
  double u_cut_ = 0;  // ln Delta_l below which a mode's area is negligible in the tension sums
  double area_of(double u) const { return u < u_cut_ ? 0.0 : std::exp(u); }
  ModeAmplitudes f0_;
  std::vector<double> y0_;
};

}  // namespace rbcstab
