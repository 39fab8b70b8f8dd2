#pragma once
// The physical phase diagram: for a cell given by its measured properties, the regimes in the plane of the shear
// rate (1/s) and the outer viscosity eta_ex (Pa s). Along each viscosity the shear rate moves B and C together
// (at_shear_rate); the viscosity itself moves B, C and lambda = eta_in/eta_ex (so Lambda). Per viscosity:
//  - the tumbling -> swinging shear rate of the in-plane cell (reduced_regime at beta = pi/2: tumbling below,
//    swinging or tank-treading above), by log-spaced samples and bisection in ln gamma;
//  - the l >= 3 onset for each rest orientation (shear_rate_threshold, the summary's search).
// Bands: the same boundaries for the cell at the ends of each published range (one key at a time, the others at
// their nominal values); the band is the min and max over those cells. And where the model's assumptions fail
// over the plane (quasi-spherical expansion, Stokes flow, linear shear elasticity), by how much.
#include <string>
#include <vector>

#include "rbcstab/core/progress.hpp"
#include "rbcstab/verdict/shear_rate.hpp"

namespace rbcstab {

// A published range of one input: a PhysicalCell key ("bending_modulus", SI) or a dimensionless scene parameter
// the cell does not derive ("Delta", "Delta0").
struct PhysicalSpread {
  std::string key;
  double lo = 0, hi = 0;
  std::string source;  // where the range comes from (carried into the outputs)
};
// The healthy-cell ranges of docs/units.md (the table "Typical healthy red blood cell"), for the keys `cell`
// gives: bending_modulus, shear_modulus, area and volume (or radius), inner_viscosity; Delta0 in [0.01, Delta]
// when Delta0 is a dimensionless input (no measurement bounds it).
std::vector<PhysicalSpread> healthy_cell_spreads(const Scene& scene);

// The reduced regime is stiff at small C (its relaxation rates grow as 1/C), so with an explicit stepper a
// search's cost grows as 1/min_rate: the default range starts at 0.1/s, below the experiments' tumbling (~1/s in
// 25-50 mPa s). Down to 0.1/s the explicit rk8pd is the cheaper regime stepper (measured, docs/units.md "Cost":
// the linearly implicit rosenbrock took 14x its CPU time at the predictor's rtol 1e-10, 1.5x at rtol 1e-6).
struct PhysicalMapOptions {
  double min_viscosity = 1e-3, max_viscosity = 5e-2;  // Pa s: plasma to the dextran media of the experiments
  int viscosities = 9;                                // log-spaced over [min, max]
  double min_rate = 1e-1, max_rate = 1e5;             // 1/s: both searches' range (see below on min_rate)
  int samples_per_decade = 6;                         // scan density of both searches (a factor 1.47)
  double rtol = 1e-3;                                 // bisection in ln gamma until hi/lo - 1 <= rtol
  bool onset = true;                                  // also the l >= 3 onset (the costlier search)
  std::vector<PhysicalSpread> spreads;                // the bands; empty: no band
  int threads = 0;                                    // 0: all cores; the result does not depend on it
  PredictorOptions predictor;
  // The stepper of the tumbling search's reduced runs (predictor.integrator's tolerances); the onset search's
  // verdicts keep predictor.integrator.stepper. An implicit one (rosenbrock) classifies as rk8pd does (test
  // StiffRegimeStepperKeepsTheClassification) and may pay off below 0.1/s, where C is smaller still.
  Stepper regime_stepper = Stepper::rk8pd;
  ProgressCallback on_progress;  // (cells done, cells in all) after each cell at each viscosity
  void validate() const;         // throws InvalidArgument naming the field
};

// One boundary at one viscosity: where the regime changes along the shear rate.
struct RateCrossing {
  bool found = false;
  double rate = 0;        // 1/s: the bracket's upper end (the first rate found past the boundary)
  double lo = 0, hi = 0;  // the final bracket, hi/lo - 1 <= rtol
  int l = 0;              // the onset's surviving mode (0 for the tumbling boundary)
  // Not found because the boundary lies outside the searched range: "below" (the upper regime -- swinging,
  // unstable -- holds already at min_rate), "above" (not reached by max_rate); "" when found or undetermined.
  std::string side;
  std::string reason;  // why not found
};
struct RateBand {
  int found = 0, cells = 0;    // cells whose crossing was found, out of the cells evaluated
  double lo = 0, hi = 0;       // min and max crossing rate over them (1/s); meaningful when found > 0
  std::string lo_key, hi_key;  // which spread end gave each ("" the nominal cell)
};
struct PhysicalMapColumn {
  double viscosity = 0;  // Pa s
  double lambda = 0, Lambda = 0;
  RateCrossing tumbling_to_swinging;  // nominal cell, in plane
  RateCrossing onset[2];              // nominal cell: out of plane (beta = 1e-3), in plane (beta = pi/2)
  RateBand tumbling_band, onset_band[2];
};
// Where the model's assumptions fail over the plane: each with the value, the bound it should respect and a verdict.
struct AssumptionCheck {
  std::string assumption;  // "quasi-spherical expansion", "Stokes flow", "linear shear elasticity"
  std::string quantity;    // "Delta", "Re = rho gamma R^2 / eta_ex", "C = eta_ex gamma R / mu"
  double value = 0;        // the worst value over the map's plane
  double bound = 0;        // the assumption wants value <= bound (Delta << 1 etc.)
  bool holds = false;
  std::string meaning;  // what a failure does to the predictions
};
struct PhysicalMap {
  PhysicalCell cell;  // the nominal cell (shear_rate and viscosity as given)
  std::vector<PhysicalSpread> spreads;
  std::vector<PhysicalMapColumn> columns;  // by increasing viscosity
  std::vector<AssumptionCheck> assumptions;
  double min_rate = 0, max_rate = 0;  // 1/s: the searched range
  bool onset = false;                 // the l >= 3 onset was searched (PhysicalMapOptions::onset)
  int evaluations = 0;                // regime and verdict evaluations in all
};

// Throws InvalidArgument("viscosity", ...) for a scene that is not physical or whose lambda the cell does not
// derive (give inner_viscosity: lambda must follow eta_ex), and InvalidArgument(key, ...) for a bad spread.
PhysicalMap physical_map(const Scene& scene, const PhysicalMapOptions& options = {});

// The scene's cell with one key set (a PhysicalCell field in SI, or "Delta"/"Delta0" on the parameters), and its
// parameters rederived. Throws InvalidArgument(key, ...) for an unknown key or a value the cell refuses.
Scene with_physical_value(const Scene& scene, const std::string& key, double value);

}  // namespace rbcstab
