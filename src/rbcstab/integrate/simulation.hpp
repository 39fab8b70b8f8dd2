#pragma once
// A scene run end to end: initial state, smallest exact level, integration, and the paper's
// observables (Delta_l, sigma, r, Psi, l_Delta) on the output grid.
#include <cstddef>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "rbcstab/core/progress.hpp"
#include "rbcstab/integrate/dense_output.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

// How simulate() computes the means of Delta_l and sigma over the tail window [T - tail_window, T] and judges
// oscillating (Delta_2 not monotonic there).
enum class TailMeans {
  // Simpson's rule on a 161-point grid the integrator must stop at (h <= tail_window / 160 in the window);
  // oscillating on that grid.
  grid,
  // q' = (Delta_2..Delta_L, sigma), q = 0 at the window's start, integrated alongside the system from there to T
  // under the integrator's own error control (no resampling error); mean = q(T) / (T - tail_start). The integrator
  // stops once at the window's start and keeps its step size across it. oscillating on the accepted steps in the
  // window, as for none. Explicit steppers only (the quadrature rows have no Jacobian).
  quadrature,
  // No means: they are the values at T; oscillating on the accepted steps in the window. For callers that read
  // neither (a diagram classified by Delta_l(T)).
  none,
};
template <>
struct EnumTable<TailMeans> {
  static constexpr EnumName<TailMeans> entries[] = {
      {TailMeans::grid, "grid"}, {TailMeans::quadrature, "quadrature"}, {TailMeans::none, "none"}};
};

struct SimulationOptions {
  IntegratorOptions integrator;   // stepper, tolerances, limits
  double tail_window = 10;        // Delta_l averaged over [T - tail_window, T] (Appendix E)
  bool record_trajectory = true;  // keep the samples on the output grid
  // The output grid: empty, the scene's 0, dt, 2 dt, ..., T; else these times, finite, in [0, T] and increasing
  // by more than 1e-12 T (checked by simulate, which knows T: InvalidArgument("t_eval", ...)). The integrator
  // stops at each, so the samples carry its own error (no interpolation).
  std::vector<double> t_eval{};
  // Keep the observables at every accepted step for SimulationResult::dense (memory: 8 (L + 2) bytes a step).
  bool dense_output = false;
  // Called after every accepted step with the observables there (the truncation check reads sigma(t) from
  // them), and at the resumed state after a certified skip (EarlyTermination); empty: not called.
  std::function<void(double t, const Observation& o)> on_step{};
  bool trajectory_text = false;  // the caller also renders the samples as CSV text (counted by the memory bound)
  ProgressCallback on_progress;  // t of T, after every accepted step
  // true: integrate every run to T. false: a run given an attractor certifier (simulate_certified,
  // verdict/certified_run.hpp) may skip whole forcing periods once its attractor is certified.
  bool full_horizon = false;
  TailMeans tail_means = TailMeans::grid;  // how the tail means and oscillating are computed (see TailMeans)
  void validate() const;
};

// The output grid of a run: options.t_eval, or sampling_grid(scene.T, scene.dt). Throws InvalidArgument("t_eval")
// for times that are not finite, outside [0, T] or not increasing by more than 1e-12 T.
std::vector<double> output_grid(const Scene& scene, const SimulationOptions& options);

// The samples kept on the output grid are bounded before a run starts: measured 8 (L + 8) bytes each in memory
// (Delta_2..Delta_L, t, sigma, r, Psi and the vectors' overhead), plus up to 25 (L + 4) bytes each as CSV text
// (trajectory_text); a run whose samples would take more than kMaxTrajectoryBytes is refused.
constexpr double kMaxTrajectoryBytes = 2.0 * 1024 * 1024 * 1024;
double trajectory_bytes(const Scene& scene, const SimulationOptions& options);

// The rows of the output grid a certified early stop skipped: [first, first + count), none integrated. They are
// described, not stored (a run to T = 1e7 at dt = 1 skips ~1e7 of them): their times are the grid's.
struct SkippedSamples {
  std::size_t first = 0, count = 0;
  double dt = 0;                     // the regular grid's spacing: row k at sampling_time(k, dt) (times empty)
  std::vector<double> times;         // a t_eval grid: the skipped times themselves (the caller's array holds them too)
  double time(std::size_t k) const;  // of grid row k in [first, first + count)
};

// The samples on the output grid. Only integrated samples are stored (t, Delta_l, sigma, r, Psi); a run that
// stopped early on a certified attractor skipped the rows strictly between terminated_at and resumed_at, which
// `skipped` describes. An output that needs every row (the CSV, Python's arrays) walks rows 0..rows() - 1: a
// skipped row is shown as NaN (a plot breaks its lines there) with integrated = false.
struct Trajectory {
  std::vector<double> t;                     // integrated samples only
  std::vector<std::vector<double>> Delta_l;  // [sample][l - 2]
  std::vector<double> sigma, r, Psi;         // Psi unwrapped along the accepted steps
  SkippedSamples skipped;
  std::size_t rows() const { return t.size() + skipped.count; }  // of the output grid
  std::size_t integrated_count() const { return t.size(); }
  bool integrated(std::size_t row) const { return row < skipped.first || row >= skipped.first + skipped.count; }
  // Grid row -> its index in the stored samples (integrated(row)) and its time (any row).
  std::size_t sample(std::size_t row) const { return row < skipped.first ? row : row - skipped.count; }
  double time(std::size_t row) const { return integrated(row) ? t[sample(row)] : skipped.time(row); }
};

// Certified early termination: the run stopped integrating at terminated_at, where its state was certified
// to lie within the linearisation radius of an attracting periodic orbit (an equilibrium is one of any period),
// and resumed on that orbit whole periods later at resumed_at <= T - tail_window, so that the tail window and
// T are integrated as in a full run. The margins say how attracting the orbit is.
struct EarlyTermination {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  bool terminated = false;
  double terminated_at = nan, resumed_at = nan;
  std::string note;             // why the run was integrated to T (empty when it terminated early)
  std::string kind;             // "periodic_orbit" or "equilibrium" (time-independent forcing)
  double period = nan;          // of the forcing (the orbit's period or a multiple of it)
  double margin = nan;          // 1 - max |mu| over the nontrivial Floquet multipliers
  double margin_error = nan;    // its error bound (certify, continuation.hpp)
  double rate = nan;            // -ln(max |mu|) / period: the slowest decay rate
  double residual = nan;        // periodicity defect |phi(x*) - x*| of the refined state x*
  double distance = nan;        // |x(terminated_at) - x*| in the level's regular coordinates (|x| = 1)
  double decay_bound = nan;     // linear bound on |x - x*| at resumed_at (the error the skip makes)
  double sigma_integral = nan;  // int sigma dt over [terminated_at, resumed_at] along the orbit (first order)
  int attempts = 0;             // certification attempts, failed ones included
  IntegrationCounters work;     // the attempts' integrations (not in SimulationResult::counters)
};

// Where the run resumes after a certified attractor, and how the unwrapped Psi moved meanwhile.
struct AttractorJump {
  double t = 0;
  std::vector<double> y;
  double Psi_advance = 0;  // -2 pi per turn of f_{2,2} about 0 over the skipped periods
};

// Decides early termination from above the integrate module (it needs the orbit machinery of continuation):
// simulate asks it at every accepted step before T - tail_window.
class AttractorCertifier {
 public:
  virtual ~AttractorCertifier() = default;
  // True when the state (t, y) of `system` is certified and the run may resume at jump.t in (t, t_max]: fills
  // jump and the certificate in `record`. It keeps its own attempt schedule and records every attempt.
  virtual bool certify(const System& system, double t, std::span<const double> y, double t_max, AttractorJump& jump,
                       EarlyTermination& record) = 0;
};

struct SimulationResult {
  std::string scene_name;
  LevelChoice level;
  IntegrationStatus status = IntegrationStatus::success;
  std::string reason;
  int L = 2;
  double T = 0, t_reached = 0;
  std::vector<double> Delta_initial, Delta_final, Delta_tail_mean;  // index l - 2
  double Delta_total_initial = 0;  // sum_l Delta_l(0) = Delta + sum of the perturbations
  bool oscillating = false;        // Delta_2 is not monotonic over the tail window
  int l_Delta = 2;                 // argmax_l [X_l - Delta_l(0)], X = tail mean if oscillating, else Delta_l(T)
  int l_Delta_final = 2;           // the same with X = Delta_l(T)
  double sigma_initial = 0, sigma_final = 0, sigma_tail_mean = 0;
  double r_final = 0, Psi_final = 0;
  double excess_area_drift = 0;  // max over accepted steps of |sum_l Delta_l(t) - sum_l Delta_l(0)|
  Trajectory trajectory;
  // With options.dense_output: Delta_2..Delta_L, sigma, r, Psi (columns) at any t, NaN in a certified skip.
  DenseOutput dense;
  EarlyTermination early;  // empty unless an attractor certifier was given
  IntegrationCounters counters;
  double seconds = 0;
  std::vector<double> y_final;
  std::vector<std::string> warnings;
};

// Runs the scene (validated first, with its memory bounds: the dense stepper's dimension, require_dense_dimension,
// and the samples, kMaxTrajectoryBytes; throws InvalidArgument on bad input). Numerical failure is a
// status in the result, with everything computed up to t_reached. With a certifier (and not
// options.full_horizon) the run may skip whole periods on a certified attractor (SimulationResult::early): the
// trajectory's samples strictly between terminated_at and resumed_at are then not stored (Trajectory::skipped).
SimulationResult simulate(const Scene& scene, const SimulationOptions& options = {},
                          AttractorCertifier* certifier = nullptr);
SimulationResult simulate(const ValidScene& scene, const SimulationOptions& options = {},
                          AttractorCertifier* certifier = nullptr);

// f_{l,m}(t_reached): the shape a run of `scene` ends in, rebuilt from its final state on the level it ran.
ModeAmplitudes final_amplitudes(const Scene& scene, const SimulationResult& result);

// Regular-grid helper: 0, dt, 2 dt, ..., T (T always included); sample k < n at sampling_time(k, dt).
std::vector<double> sampling_grid(double T, double dt);
inline double sampling_time(std::size_t k, double dt) { return double(k) * dt; }

// r.reason, and for a run whose state became non-finite, the inputs that made it overflow (nonfinite_reason).
std::string run_reason(const SimulationResult& r, const Parameters& p);
// The same for any run's status and message (a benchmark row, an amplitude series).
std::string run_reason(IntegrationStatus status, const std::string& reason, const Parameters& p);

}  // namespace rbcstab
