#pragma once
// The full model (Eqs. eom, eom_sup, eom_g, st): every mode l = 2..L, all m.
#include <complex>
#include <vector>

#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/model/system.hpp"
#include "rbcstab/model/tension.hpp"

namespace rbcstab {

// State (Re f_{l,m}, Im f_{l,m}) for l = 2..L, all m.
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
  // S_{l,m} = 0 for every m of this l (no shear drive, no rest content there, or C = inf): the block then
  // feels the rest of the state only through sigma.
  bool unforced(int l) const;
  // The drive does not depend on t (no rest content with m != 0, or C = inf).
  bool autonomous() const;

 private:
  struct ModeData {
    GrowthRate Upsilon;
    double G3C, a;  // Gamma3/C (the rest shape's pull in S_{l,m}), a_l
  };
  void drive(double t, std::vector<std::complex<double>>& S) const;  // S_{l,m}(t)
  AreaBalance balance(std::span<const double> y, const std::vector<std::complex<double>>& S) const;
  Parameters p_;
  int L_;
  std::vector<ModeData> modes_;               // index l - 2
  std::vector<std::complex<double>> C_, g0_;  // C_{l,m}, g_{l,m}(0)
  std::vector<double> y0_;
};

}  // namespace rbcstab
