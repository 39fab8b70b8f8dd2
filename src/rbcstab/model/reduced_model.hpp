#pragma once
// The reduced ellipsoidal system (Eqs. subs, st_red, red_eqs) in regular coordinates.
#include <complex>
#include <vector>

#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/model/system.hpp"
#include "rbcstab/model/tension.hpp"

namespace rbcstab {

// z = r e^{-i Psi} and w = sqrt(1 - r^2) on the unit sphere |z|^2 + w^2 = 1, with the l = 2 growth rate
// as multiplier:
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
  // sigma_R from the l = 2 growth rate mu (Eq. st_red): the inverse of Upsilon_2.
  double sigma_from_mu(double mu) const { return Upsilon2_.sigma_at(mu); }
  double sigma(double t, std::span<const double> y) const { return sigma_from_mu(mu(t, y)); }  // sigma_R
  const GrowthRate& Upsilon2() const { return Upsilon2_; }
  std::complex<double> z0(double t) const;
  double w0() const { return w0_; }  // rest shape's w component (with z0: the forcing direction)
  // f, the dense df/dy (row-major) and the forcing direction (Re z0(t), Im z0(t), w0) of one state at once
  // (the same terms as rhs and jacobian, the phasor computed once): the orbit shooting's variational equations.
  struct DenseTerms {
    double f[3];
    double J[9];
    double direction[3];
  };
  DenseTerms dense_terms(double t, std::span<const double> y) const;
  // df/d(1/Lambda) and df/dkappa at y, with g = the forcing direction (DenseTerms::direction): f depends on the
  // parameters only through these two coefficients, mu = (y1/Lambda - kappa y.g)/|y|^2, so
  //   df/d(1/Lambda) = (y1/Q) y - e_1,  df/dkappa = g - (y.g/Q) y  (Q = |y|^2), exact in y and t.
  static void coefficient_derivatives(std::span<const double> y, const double g[3], double dinvL[3], double dkappa[3]);

 private:
  AreaBalance balance(std::complex<double> zz0, std::span<const double> y) const;  // yields mu; zz0 = z0(t)
  void rhs_at(std::complex<double> zz0, double mu, std::span<const double> y, std::span<double> dydt) const;
  void grad_mu(std::complex<double> zz0, const AreaBalance& b, std::span<const double> y, std::span<double> g) const;
  Parameters p_;
  int L_;
  GrowthRate Upsilon2_;
  double inv_Lambda_, kappa_;  // 1/Lambda, 1/(Lambda S)
  std::complex<double> z00_;
  double w0_;
  std::vector<double> y0_;
};

}  // namespace rbcstab
