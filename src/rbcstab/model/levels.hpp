#pragma once
// The three model levels: full, modal and reduced (docs/theory.md, "Model levels and why they are exact").
#include <complex>
#include <vector>

#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab {

// Full model (Eqs. eom, eom_sup, eom_g, st): state (Re f_{l,m}, Im f_{l,m}) for l = 2..L, all m.
class FullModel final : public System {
 public:
  FullModel(const Parameters& p, const InitialState& init);
  ModelLevel level() const override { return ModelLevel::full; }
  std::size_t dimension() const override { return 2 * ModeAmplitudes::count(L_); }
  int L() const override { return L_; }
  void rhs(double t, std::span<const double> y, std::span<double> dydt) const override;
  void jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> dfdt) const override;
  Observation observe(double t, std::span<const double> y) const override;
  std::vector<double> initial_state() const override;
  ModeAmplitudes amplitudes(double t, std::span<const double> y) const override;
  double sigma(double t, std::span<const double> y) const;

 private:
  struct ModeData {
    double Gamma1 = 0, Gamma2 = 0, Gamma3 = 0, a = 0;
  };
  void drive(double t, std::vector<std::complex<double>>& S) const;  // S_{l,m}(t)
  Parameters p_;
  int L_;
  std::vector<ModeData> modes_;                  // index l - 2
  std::vector<std::complex<double>> C_, g0_;     // C_{l,m}, g_{l,m}(0)
  std::vector<double> y0_;
};

// Exact modal reduction (docs/theory.md): the l = 2 block (f20, f21, f22) plus
// u_l = ln Delta_l for every l >= 3 that holds area. Exact when g has no l >= 3 content.
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
  double sigma(double t, std::span<const double> y) const;
  const std::vector<int>& active_modes() const { return active_; }  // the l >= 3 carried as u_l

 private:
  struct Sums {
    double N = 0, D = 0, Delta2 = 0;
  };
  void drive(double t, std::complex<double> S[3]) const;  // S_{2,0}, S_{2,1}, S_{2,2}
  Sums sums(double t, std::span<const double> y, const std::complex<double> S[3]) const;
  Parameters p_;
  int L_;
  std::vector<int> active_;
  std::vector<double> G1a3_, G2_;  // Gamma1 + alpha Gamma3, Gamma2 for l = 2 (index 0) and active l
  std::vector<double> ups_slope_, ups_shift_;  // Upsilon_l = slope (shift + sigma), same indexing
  std::complex<double> C22_, g20_[3];
  double G3C2_ = 0;  // Gamma3^2 / C
  double u_cut_ = 0;  // ln Delta_l below which a mode's area is negligible in the tension sums
  double area_of(double u) const { return u < u_cut_ ? 0.0 : std::exp(u); }
  ModeAmplitudes f0_;
  std::vector<double> y0_;
};

// Reduced ellipsoidal system (Eqs. subs, red_eqs) in regular coordinates: z = r e^{-i Psi} and
// w = sqrt(1 - r^2) on the unit sphere |z|^2 + w^2 = 1, with the l = 2 growth rate as multiplier:
//   z' = (i + mu) z - i/Lambda + z0/(Lambda S),  w' = mu w + w0/(Lambda S),  z0' = i z0.
// Smooth at r = 0 and r = 1, and at S = inf.
class ReducedModel final : public System {
 public:
  ReducedModel(const Parameters& p, const InitialState& init);
  ModelLevel level() const override { return ModelLevel::reduced; }
  std::size_t dimension() const override { return 3; }
  int L() const override { return L_; }
  void rhs(double t, std::span<const double> y, std::span<double> dydt) const override;
  void jacobian(double t, std::span<const double> y, StructuredJacobian& J, std::span<double> dfdt) const override;
  Observation observe(double t, std::span<const double> y) const override;
  std::vector<double> initial_state() const override { return y0_; }
  ModeAmplitudes amplitudes(double t, std::span<const double> y) const override;
  double mu(double t, std::span<const double> y) const;  // = Upsilon_2
  // sigma_R from the l = 2 growth rate mu (Eq. st_red).
  double sigma_from_mu(double mu) const;
  std::complex<double> z0(double t) const;
  double w0() const { return w0_; }  // rest shape's w component (with z0: the forcing direction)

 private:
  Parameters p_;
  int L_;
  double inv_Lambda_, kappa_;  // 1/Lambda, 1/(Lambda S)
  std::complex<double> z00_;
  double w0_;
  std::vector<double> y0_;
};

}  // namespace rbcstab
