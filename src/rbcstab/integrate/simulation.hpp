#pragma once
// A scene run end to end: initial state, smallest exact level, integration, and the paper's
// observables (Delta_l, sigma, r, Psi, l_Delta) on the output grid.
#include <functional>
#include <string>
#include <vector>

#include "rbcstab/core/progress.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

struct SimulationOptions {
  IntegratorOptions integrator;  // stepper, tolerances, limits
  double tail_window = 10;       // Delta_l averaged over [T - tail_window, T] (Appendix E)
  bool record_trajectory = true; // keep the samples on the output grid
  // Called after every accepted step with the observables there (the truncation check reads sigma(t) from
  // them); empty: not called.
  std::function<void(double t, const Observation& o)> on_step{};
  bool trajectory_text = false;  // the caller also renders the samples as CSV text (counted by the memory bound)
  ProgressCallback on_progress;  // t of T, after every accepted step
  void validate() const;
};

// The samples kept on the output grid are bounded before a run starts: measured 8 (L + 8) bytes each in memory
// (Delta_2..Delta_L, t, sigma, r, Psi and the vectors' overhead), plus up to 25 (L + 4) bytes each as CSV text
// (trajectory_text); a run whose samples would take more than kMaxTrajectoryBytes is refused.
constexpr double kMaxTrajectoryBytes = 2.0 * 1024 * 1024 * 1024;
double trajectory_bytes(const Scene& scene, const SimulationOptions& options);

struct Trajectory {
  std::vector<double> t;
  std::vector<std::vector<double>> Delta_l;  // [sample][l - 2]
  std::vector<double> sigma, r, Psi;         // Psi unwrapped along the accepted steps
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
  double excess_area_drift = 0;    // max over accepted steps of |sum_l Delta_l(t) - sum_l Delta_l(0)|
  Trajectory trajectory;
  IntegrationCounters counters;
  double seconds = 0;
  std::vector<double> y_final;
  std::vector<std::string> warnings;
};

// Runs the scene (validated first, with its memory bounds: the dense stepper's dimension, require_dense_dimension,
// and the samples, kMaxTrajectoryBytes; throws InvalidArgument on bad input). Numerical failure is a
// status in the result, with everything computed up to t_reached.
SimulationResult simulate(const Scene& scene, const SimulationOptions& options = {});

// Regular-grid helper: 0, dt, 2 dt, ..., T (T always included).
std::vector<double> sampling_grid(double T, double dt);

}  // namespace rbcstab
