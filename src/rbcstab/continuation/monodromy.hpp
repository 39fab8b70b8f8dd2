#pragma once
// Floquet multipliers of a (periodic) trajectory of any model level, matrix-free: the monodromy
// action v -> Phi(t0 + T, t0) v integrates the variational equation v' = J(t, y(t)) v (J the level's
// structured Jacobian, applied in O(n)) together with y' = F(t, y) from the given orbit state, so no
// n x n matrix is ever formed; ARPACK then finds the leading multipliers from a few dozen actions.
// The orbit itself is an input (the periodic-orbit solver or a long simulation sampled at t0 + kT).
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/eigen_arpack.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab {

struct MonodromyOptions {
  double period = 6.283185307179586;  // T: the forcing period 2 pi of the in-plane scenes
  // Below implicit_from_L: rk8pd (explicit), or any stepper but GSL's dense implicit ones (msbdf,
  // bsimp, rk4imp: the variational system has no dense Jacobian); rosenbrock solves its block-
  // triangular Jacobian by two O(n) structured solves per stage. Tight tolerances: the multipliers
  // are only as accurate as each column of Phi (rk8pd is stability-bound here, ~1e-13 per action).
  IntegratorOptions integrator = {Stepper::rk8pd, 1e-11, 1e-13};
  // The full level with L >= implicit_from_L integrates with `implicit` instead (0: never). Its
  // diagonal carries Upsilon_l ~ -l^3: rk8pd's steps grow like |Upsilon_L| (1400 at L = 30, 11000 at
  // L = 60) while rosenbrock's are set by accuracy alone (~5600 at rtol 1e-10, any L); measured
  // cross-over at equal cost near L = 40 (docs/benchmarks.md, BM_FloquetAction). The modal and reduced
  // levels hold no l >= 3 amplitudes to be stiff in and keep `integrator`.
  int implicit_from_L = 40;
  IntegratorOptions implicit = {Stepper::rosenbrock, 1e-10, 1e-12};
  // The integrator options used for the variational system of `system`.
  const IntegratorOptions& integrator_for(const System& system) const {
    const bool stiff = system.level() == ModelLevel::full && implicit_from_L > 0 && system.L() >= implicit_from_L;
    return stiff ? implicit : integrator;
  }
  void validate() const;  // throws InvalidArgument naming the field
};

// The variational system (y, v)' = (F(t, y), J(t, y) v) of `base` (kept by reference), dimension 2n.
// Its make_shifted_solver() gives the exact block-triangular solve used by the rosenbrock stepper;
// jacobian() throws logic_error (J_aug is not of the form M + v w^T).
std::unique_ptr<System> make_variational_system(const System& base);

class MonodromyAction {
 public:
  // The trajectory through (t0, y0) of `system`; keeps a reference to system (must outlive this).
  MonodromyAction(const System& system, std::span<const double> y0, double t0, const MonodromyOptions& options);
  std::size_t dimension() const { return y0_.size(); }
  // out = Phi(t0 + T, t0) v. Linear in v: v is integrated scaled to unit norm (the error control then
  // acts on a fixed scale) and the result scaled back. Returns false (and out = 0) when the
  // integration fails; failure_reason() says why.
  bool apply(std::span<const double> v, std::span<double> out) const;
  // The n x n monodromy matrix, column by column (n integrations): the dense oracle for small n.
  Eigen::MatrixXd dense(bool* ok = nullptr) const;
  std::size_t applications() const { return applications_; }
  const IntegrationCounters& counters() const { return counters_; }  // summed over all actions
  const std::string& failure_reason() const { return failure_; }

 private:
  const System& system_;
  std::vector<double> y0_;
  double t0_;
  MonodromyOptions options_;
  mutable std::size_t applications_ = 0;
  mutable IntegrationCounters counters_;
  mutable std::string failure_;
};

struct FloquetResult {
  ArpackResult arpack;           // multipliers in arpack.eigenvalues, largest |mu| first
  std::size_t integrations = 0;  // monodromy actions (one variational integration each)
  IntegrationCounters counters;  // summed integrator work
};

// Leading k Floquet multipliers (largest modulus) of the trajectory through (t0, y0) over one period.
// arpack.which is forced to largest_magnitude. A failed integration gives status failed with the reason.
FloquetResult leading_floquet_multipliers(const System& system, std::span<const double> y0, double t0,
                                          const MonodromyOptions& options, ArpackOptions arpack);

// Leading Floquet multipliers of the FULL model (truncated at scene.L) along the orbit a scene relaxes to:
// the scene is integrated at its own level (choose_level: the smallest exact one) for relax_periods
// forcing periods, the state is embedded in the full model (System::amplitudes) and ARPACK analyses the
// monodromy over one period from there. The forcing period is 2 pi, or 4 pi when the rest shape has
// odd-m content (g_{l,m}(t) = g_{l,m}(0) e^{imt/2}); a multiple of the orbit's own period is fine too
// (multipliers raised to that power), so the result also reports how periodic the state is.
struct SceneFloquetOptions {
  int relax_periods = 30;  // forcing periods simulated first: the state must have reached the orbit
  // Relaxation accuracy: the multipliers belong to the state actually reached.
  IntegratorOptions relax = {Stepper::rk8pd, 1e-11, 1e-13};
  MonodromyOptions monodromy;  // its period is replaced by the scene's forcing period
  // A state farther than this from periodic (|y(t0 + T) - y(t0)| / |y(t0)|) is not on an orbit and its
  // monodromy's eigenvalues are not Floquet multipliers: status not_periodic, no ARPACK run (relax
  // longer). +inf accepts any state (the monodromy of a trajectory segment).
  double max_periodicity_defect = 1e-6;
  ArpackOptions arpack = [] {
    ArpackOptions a;
    a.k = 12;       // the leading dozen (at the Fig. 3 in-plane orbit the unstable l = 4 family alone has 18)
    a.tol = 1e-10;  // ~ the action's accuracy at the default tolerances (docs/benchmarks.md)
    return a;
  }();
  void validate(int L) const;  // throws InvalidArgument naming the field (arpack against n at truncation L)
};

enum class SceneFloquetStatus { converged, relaxation_failed, not_periodic, arpack_failed };
template <>
struct EnumTable<SceneFloquetStatus> {
  static constexpr EnumName<SceneFloquetStatus> entries[] = {
      {SceneFloquetStatus::converged, "converged"},
      {SceneFloquetStatus::relaxation_failed, "relaxation_failed"},
      {SceneFloquetStatus::not_periodic, "not_periodic"},
      {SceneFloquetStatus::arpack_failed, "arpack_failed"}};
};

struct SceneFloquetResult {
  SceneFloquetStatus status = SceneFloquetStatus::converged;
  std::string message;                        // empty when converged
  ModelLevel relax_level = ModelLevel::full;  // the level the scene was relaxed with
  double t0 = 0, period = 0;                  // the monodromy runs from t0 over one period
  Stepper stepper = Stepper::rk8pd;           // the variational integration's stepper
  std::size_t dimension = 0;                  // n of the full model
  double periodicity_defect = 0;              // |y(t0 + T) - y(t0)| / |y(t0)| along the full model
  FloquetResult floquet;                      // multipliers in floquet.arpack.eigenvalues, largest first
};

SceneFloquetResult scene_floquet_multipliers(const Scene& scene, const SceneFloquetOptions& options);

}  // namespace rbcstab
