#pragma once
// The forward model of a fit: each observable of inverse/observations.hpp predicted for a cell in physical units at a
// row's shear rate and viscosity (docs/inverse.md "Observables"). The physical inputs map to the paper's numbers by
// model/physical.hpp (B = eta gamma R^3/kappa, C = eta gamma R/mu, lambda = eta_in/eta, time in 1/gamma); the
// motion is the reduced l = 2 system (Eq. red_eqs), exact for an ellipsoidal cell, from the in-plane start
// (beta = pi/2), whose attracting 2 pi-periodic orbit (swinging) or rotation (tumbling) is integrated to convergence.
#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/inverse/observations.hpp"
#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/physical.hpp"

namespace rbcstab {

// The cell a fit varies: the physical keys of model/physical.hpp and the material numbers of the parameter table.
// Defaults: the red cell's typical values (plausible_range(key).typical) and the table's defaults (Parameters{}).
struct CellModel {
  double bending_modulus = plausible_range("bending_modulus").typical;  // kappa, J
  double shear_modulus = plausible_range("shear_modulus").typical;      // mu, N/m
  double radius = plausible_range("radius").typical;                    // R, m
  double inner_viscosity = kNotGiven;  // eta_in, Pa s; NaN: lambda is held fixed instead (eta_in = lambda eta)
  double lambda = Parameters{}.lambda;
  double Delta = Parameters{}.Delta;
  double Delta0 = Parameters{}.Delta0;
  // Each given value finite and in its domain (the parameter table's, or > 0 for the physical keys); throws
  // InvalidArgument naming the key.
  void validate() const;
};

// The quantities a fit may free or fix. Names: the physical keys (bending_modulus, ...) and the table's names
// (lambda, Delta, Delta0); kappa, mu and eta_in are accepted for the moduli and the inner viscosity.
enum class FitParameter { bending_modulus, shear_modulus, radius, inner_viscosity, lambda, Delta, Delta0 };
template <>
struct EnumTable<FitParameter> {
  static constexpr EnumName<FitParameter> entries[] = {{FitParameter::bending_modulus, "bending_modulus"},
                                                       {FitParameter::shear_modulus, "shear_modulus"},
                                                       {FitParameter::radius, "radius"},
                                                       {FitParameter::inner_viscosity, "inner_viscosity"},
                                                       {FitParameter::lambda, "lambda"},
                                                       {FitParameter::Delta, "Delta"},
                                                       {FitParameter::Delta0, "Delta0"}};
};
struct FitParameterInfo {
  FitParameter id;
  std::string name;     // the key
  std::string alias;    // "kappa", "mu", "eta_in"; "" when none
  std::string unicode;  // "κ", "Δ₀"
  std::string unit;     // SI unit text, "" for a number
  bool log_scale;       // fitted in ln (a positive modulus or viscosity); else linear
  double lo, hi;        // bounds: plausible_range for the physical keys, the table's domain for the numbers
};
// Bounds of Delta0 use `cell`'s Delta (Delta0 <= Delta).
FitParameterInfo fit_parameter_info(FitParameter q, const CellModel& cell);
// By name or alias; throws InvalidArgument(parameter, "... must be one of ...").
FitParameter fit_parameter_from_string(const std::string& name, const std::string& parameter);
double get_value(const CellModel& cell, FitParameter q);
void set_value(CellModel& cell, FitParameter q, double value);
// "name=value,name=value": values read with units as the scene's [physical] keys (parse_quantity: "2e-19J",
// "6uN/m"); the numbers bare. Throws InvalidArgument naming the item.
void apply_assignments(CellModel& cell, const std::string& text, const std::string& parameter);

// The paper's numbers at one condition (gamma [1/s], eta_ex [Pa s]) through model/physical.hpp.
Parameters condition_parameters(const CellModel& cell, double shear_rate, double viscosity);

// Warm starts of the transition shear rate: the cell of its ln S grid found at each Lambda by the calls that share
// one memo (make_transition_memo). fit() makes one per fit, so no value depends on what ran before the fit; a memo
// changes the cost, never the value, where the regime changes once along S (docs/inverse.md "Observables").
struct TransitionMemo;
std::shared_ptr<TransitionMemo> make_transition_memo();

struct ForwardOptions {
  // [16, 65536]: psi samples per period over the last two periods; extrema refined by the quartic through five
  // samples, whose O(dt^5) error jumps as an extremum moves between samples: 1024 keeps it and its derivative far
  // below the sensitivities' agreement (docs/inverse.md "Sensitivities").
  int samples_per_period = 1024;
  int block_periods = 40;               // [2, 10000]: periods integrated between convergence checks
  int max_blocks = 12;                  // [1, 1000]: blocks before the orbit counts as not converged
  double periodicity_tolerance = 1e-9;  // (0, 0.1]: max |Psi(t + 2 pi) - Psi(t)| [rad] of a converged orbit
  double rtol = 1e-11;                  // (0, 1e-3]: integrator tolerance (rk8pd; atol = rtol/10)
  double transition_rtol = 1e-7;        // (0, 0.1]: relative width of the bisected transition shear rate
  // Shared by copies of these options; null: every call cold.
  std::shared_ptr<TransitionMemo> transition_memo;
  void validate() const;  // throws InvalidArgument naming the field
};

// The in-plane attractor at one condition.
struct InPlaneMotion {
  Regime regime = Regime::undetermined;  // swinging (tank_treading when psi moves < 1e-4 rad), tumbling, undetermined
  std::string reason;
  double mean_psi = kNotGiven;       // rad, in (-pi/2, pi/2]
  double amplitude_psi = kNotGiven;  // rad, half the peak-to-peak range
  double periods = 0;                // forcing periods integrated
  // The converged orbit: its state at orbit_time (a multiple of 2 pi) and the times after it, in [0, 2 pi), of the
  // sampled Psi maximum and minimum (quartic-refined): where inverse/sensitivity.hpp starts its variational run.
  std::vector<double> orbit_state;
  double orbit_time = 0, t_max = kNotGiven, t_min = kNotGiven;
};
InPlaneMotion in_plane_motion(const Parameters& p, const ForwardOptions& options = {});

// A predicted value (canonical unit of the observable) or why none: a regime row predicts a regime.
struct Prediction {
  double value = kNotGiven;
  Regime regime = Regime::undetermined;
  std::string reason;  // empty when predicted
  bool ok() const { return reason.empty(); }
};
// An in-plane observable's prediction (inclination, amplitude, frequencies) from the motion at the row's condition.
Prediction predict_from_motion(const InPlaneMotion& m, const ObservedRow& row);
// One observation's prediction (a regime row: the reduced_regime classifier of analysis/predictors.hpp, from the
// in-plane start for in-plane names and from the paper's out-of-plane start for rolling and
// oscillating-out-of-plane). transition_shear_rate: the in-plane motion along the shear rate, bracketed on a
// geometric grid in S in [1e-2, 1e3] (cold, or warm from a nearby Lambda's cell) and bisected on it in ln S to
// options.transition_rtol.
Prediction predict(const CellModel& cell, const ObservedRow& row, const ForwardOptions& options = {});
// Every row, sharing the in-plane run of rows at one condition.
std::vector<Prediction> predict_all(const CellModel& cell, std::span<const ObservedRow> rows,
                                    const ForwardOptions& options = {});

}  // namespace rbcstab
