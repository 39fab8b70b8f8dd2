#include "rbcstab/verdict/certified_run.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/modal_model.hpp"

namespace rbcstab {

void EarlyTerminationOptions::validate() const {
  require(std::isfinite(min_rate) && min_rate > 0, "min_rate", min_rate, "finite and > 0");
  require(std::isfinite(max_distance) && max_distance > 0 && max_distance < 1, "max_distance", max_distance, "(0, 1)");
  require(std::isfinite(state_tolerance) && state_tolerance >= 0, "state_tolerance", state_tolerance,
          "finite and >= 0 (0: the run's rtol / 10)");
  require(std::isfinite(first_attempt) && first_attempt >= 0, "first_attempt", first_attempt, "finite and >= 0");
  require(std::isfinite(attempt_growth) && attempt_growth >= 1, "attempt_growth", attempt_growth, "finite and >= 1");
  screen.validate();
  refinement.validate();
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Size of the difference along the approach direction: far above the runs' noise (rtol 1e-10 of an O(1)
// integral), far below the linearisation radius.
constexpr double kDifferenceStep = 1e-4;

// |A^k|_2 by repeated squaring (A is small: the tangent monodromy).
double power_norm(const Eigen::MatrixXd& A, int k) {
  Eigen::MatrixXd result = Eigen::MatrixXd::Identity(A.rows(), A.cols()), base = A;
  for (int e = k; e > 0; e >>= 1) {
    if (e & 1) result = result * base;
    if (e > 1) base = base * base;
  }
  return Eigen::JacobiSVD<Eigen::MatrixXd>(result).singularValues()(0);
}

// The quadratures along a refined orbit: the angle of z = x_0 + i x_1 (Psi = -arg f_{2,2} = -arg z advances by
// minus it), and the tension (the decayed modes' rates are affine in it; its integral over the skip is recorded).
using Tension = std::function<double(double, std::span<const double>)>;
Quadrature orbit_integrands(Tension sigma) {
  Quadrature q;
  q.count = 2;
  q.rate = [sigma = std::move(sigma)](double t, std::span<const double> x, std::span<const double> f,
                                      std::span<double> rate) {
    rate[0] = (x[0] * f[1] - x[1] * f[0]) / (x[0] * x[0] + x[1] * x[1]);
    rate[1] = sigma(t, x);
  };
  return q;
}

class SceneCertifier final : public AttractorCertifier {
 public:
  SceneCertifier(const Scene& scene, const SimulationOptions& sim, const EarlyTerminationOptions& o)
      : scene_(scene), o_(o), next_(o.first_attempt) {
    o_.refinement.period = 2 * kPi;  // the forcing period of the modal and reduced levels
    tolerance_ = o.state_tolerance > 0 ? o.state_tolerance : sim.integrator.rtol / 10;
    // The skip is exact to first order in the distance; the second order (the decayed modes' area acting on
    // sigma, the curvature along the approach) is kept below the state tolerance by the radius.
    radius_ = std::min(o.max_distance, std::sqrt(tolerance_));
    // The resumed state is the refined orbit's: its residual, and the period map it is computed with, within
    // the state tolerance too.
    o_.refinement.residual_tol = std::min(o_.refinement.residual_tol, tolerance_);
    o_.refinement.plain.rtol = std::max(1e-14, std::min(o_.refinement.plain.rtol, tolerance_ / 10));
    o_.refinement.plain.atol = std::min(o_.refinement.plain.atol, o_.refinement.plain.rtol / 10);
    // The screen cannot resolve a defect much below its own tolerance.
    screen_radius_ = std::max(radius_, 10 * o.screen.rtol);
  }

  bool certify(const System& system, double t, std::span<const double> y, double t_max, AttractorJump& jump,
               EarlyTermination& record) override {
    if (t < next_) return false;
    const double P = o_.refinement.period;
    const double periods = std::floor((t_max - t) / P);
    if (periods < 1) return false;
    ++record.attempts;
    attempt_t_ = t;
    next_ = std::max(t + P, o_.attempt_growth * t);
    const int k = static_cast<int>(periods);
    try {
      switch (system.level()) {
        case ModelLevel::modal:
          return modal(static_cast<const ModalModel&>(system), t, y, k, jump, record);
        case ModelLevel::reduced:
          return reduced(t, y, k, jump, record);
        case ModelLevel::full:
        case ModelLevel::automatic:
          break;
      }
    } catch (const InvalidArgument& e) {
      // The orbit problem refuses this scene (e.g. its total excess area outside Delta's domain): the run
      // goes on without a certificate rather than failing.
      next_ = kInf;
      return fail(record, t, e.what());
    }
    record.note = "the " + to_string(system.level()) + " level has no attractor certificate: integrated to T";
    next_ = kInf;
    return false;
  }

 private:
  bool fail(EarlyTermination& record, double t, const std::string& why) {
    record.note = "no certificate at the last attempt (t = " + format_value(t) + "): " + why;
    return false;
  }

  // A refinement that failed near the orbit (no convergence, a slow direction) waits longer than a screen.
  void backoff() { next_ = std::max(next_, 2 * attempt_t_); }

  // The one-period defect screens a refinement; its decrease between attempts predicts when it gets small.
  bool screened(const ForcedSystem& sys, double p, double t, const Eigen::VectorXd& x, EarlyTermination& record) {
    const PeriodRun run = run_period(sys, p, t, x, o_.refinement.period, o_.screen);
    record.work += run.work;
    const double defect = run.ok ? (run.x - x).norm() : std::numeric_limits<double>::quiet_NaN();
    const bool small = defect <= screen_radius_;
    if (!small && std::isfinite(defect) && last_defect_ > defect && t > last_t_) {
      const double rate = std::log(last_defect_ / defect) / (t - last_t_);
      const double predicted = t + std::log(defect / (0.1 * screen_radius_)) / rate;
      next_ = std::max(t + o_.refinement.period, std::min(predicted, next_ + (predicted - next_) / 2));
    }
    last_t_ = t;
    last_defect_ = defect;
    if (!small)
      fail(record, t,
           "the periodicity defect over one period is " + format_value(defect) + " (above " +
               format_value(screen_radius_) + ")");
    return small;
  }

  // Multipliers (refined orbit plus decoupled modes), margin and the decay bound; fills the record.
  bool accept(const PeriodicRefinement& ref, CertifiedSpectrum spectrum, double decayed_distance, int k, double t,
              EarlyTermination& record) {
    const double P = o_.refinement.period;
    const StabilityCertificate c = rbcstab::certify(spectrum, StabilityKind::multipliers);
    const double needed = 1 - std::exp(-o_.min_rate * P);
    if (c.stability != Stability::stable || !(c.margin - c.margin_error >= needed)) {
      backoff();
      return fail(
          record, t,
          "the orbit's slowest direction is not attracting by the margin (1 - max |mu| = " + format_value(c.margin) +
              " +- " + format_value(c.margin_error) + ", needed " + format_value(needed) + ")");
    }
    const double distance = std::hypot(ref.distance, decayed_distance);
    if (distance > radius_)
      return fail(record, t,
                  "the state is " + format_value(distance) + " from the orbit (above " + format_value(radius_) + ")");
    const double bound = power_norm(ref.monodromy, k) * ref.distance;
    if (!(bound <= tolerance_)) {
      // In the linear regime the bound at the (fixed) resume time does not improve with later attempts.
      if (bound > 10 * tolerance_) next_ = kInf;
      return fail(record, t,
                  "the linear decay bound " + format_value(bound) + " after " + std::to_string(k) +
                      " periods is above the state tolerance " + format_value(tolerance_));
    }
    record.kind = forced_ ? "periodic_orbit" : "equilibrium";
    record.period = P;
    record.margin = c.margin;
    record.margin_error = c.margin_error;
    record.rate = -std::log1p(-c.margin) / P;
    record.residual = ref.residual;
    record.distance = distance;
    record.decay_bound = bound;
    return true;
  }

  bool modal(const ModalModel& m, double t, std::span<const double> y, int k, AttractorJump& jump,
             EarlyTermination& record) {
    if (!modal_) {
      // Regular coordinates scaled by the total excess area; at least one mode l >= 3 for the orbit problem.
      Scene s = total_area_scene(scene_);
      s.L = std::max(s.L, 3);
      modal_.emplace(s, ContinuationParameter::B);
      p_ = modal_->start_parameter();
      total_ = s.parameters.Delta;
      forced_ = modal_->forcing(0, p_) != modal_->forcing(kPi / 2, p_);
    }
    const Eigen::VectorXd x = modal_->from_modal_model_state(m, t, y, p_);
    const std::vector<int>& active = m.active_modes();
    std::vector<int> carried;
    std::vector<std::size_t> decayed;  // indices into active
    double decayed2 = 0;
    for (std::size_t j = 0; j < active.size(); ++j) {
      const double a = x[ModalEquilibriumProblem::index_of_mode(active[j])];
      if (a > radius_) {
        carried.push_back(active[j]);
      } else {
        decayed.push_back(j);
        decayed2 += a * a;
      }
    }
    const ModalSubsystem sub(*modal_, p_, carried);
    const Eigen::VectorXd xc = sub.restrict(x);
    if (!screened(sub, p_, t, xc, record)) return false;
    const Quadrature integrands =
        orbit_integrands([&sub](double s, std::span<const double> z) { return sub.sigma(s, z); });
    const PeriodicRefinement ref = refine_periodic_orbit(sub, p_, t, xc, o_.refinement, integrands);
    record.work += ref.work;
    if (!ref.converged) {
      backoff();
      return fail(record, t, ref.reason);
    }

    // The modal model carries ln Delta_l: a carried mode must keep its (positive) amplitude on the orbit.
    if (!(ref.x.tail(static_cast<Eigen::Index>(carried.size())).array() > 0).all())
      return fail(record, t, "the refined orbit has a carried mode l >= 3 at zero amplitude");

    // Decayed modes: multipliers exp(P Upsilon_l(<sigma>)), error from <sigma>'s integration tolerance.
    const double P = o_.refinement.period;
    const double mean_sigma = ref.integrals[1] / P;
    CertifiedSpectrum spectrum = ref.multipliers;
    const Eigen::Index n0 = spectrum.values.size();
    spectrum.values.conservativeResize(n0 + static_cast<Eigen::Index>(decayed.size()));
    spectrum.errors.conservativeResize(n0 + static_cast<Eigen::Index>(decayed.size()));
    for (std::size_t d = 0; d < decayed.size(); ++d) {
      const GrowthRate& rate = sub.rate(active[decayed[d]]);
      const double mu = std::exp(P * rate(mean_sigma));
      spectrum.values[n0 + static_cast<Eigen::Index>(d)] = mu;
      spectrum.errors[n0 + static_cast<Eigen::Index>(d)] =
          mu * P * std::abs(rate.slope) * o_.refinement.plain.rtol * std::max(1.0, std::abs(mean_sigma));
    }
    if (!accept(ref, spectrum, std::sqrt(decayed2), k, t, record)) return false;

    // The decayed modes advance by 2 int Upsilon_l(sigma) dt, affine in int sigma dt: the orbit's k P <sigma>
    // plus, to first order, what the state's approach to the orbit adds (the one-period integral's change from
    // x* to x* + deviation_sum, by a difference with its step capped where the linearisation holds).
    double approach = 0;
    const double y_norm = ref.deviation_sum.norm();
    if (y_norm > 0) {
      const double s = std::min(1.0, kDifferenceStep / y_norm);
      const PeriodRun run = run_period(sub, p_, t, ref.x + s * ref.deviation_sum, P, o_.refinement.plain, integrands);
      record.work += run.work;
      if (!run.ok) return fail(record, t, "the run along the approach failed: " + run.reason);
      approach = (run.integrals[1] - ref.integrals[1]) / s;
    }

    // The resumed state: the decayed modes' ln Delta_l advanced, the refined orbit state scaled to the area
    // they leave, in the ModalModel's lab-frame coordinates at the resume time.
    const double skipped = k * P;
    jump.t = t + skipped;
    jump.y.assign(y.begin(), y.end());
    double remaining = 0;
    for (std::size_t j : decayed) {
      const GrowthRate& rate = sub.rate(active[j]);
      jump.y[5 + j] += 2 * (skipped * rate(mean_sigma) + rate.slope * approach);
      remaining += std::exp(jump.y[5 + j]) / total_;
    }
    Eigen::VectorXd full = sub.embed(ref.x * (std::sqrt(std::max(0.0, 1 - remaining)) / ref.x.norm()));
    for (int l = 3; l <= modal_->L(); ++l)
      if (std::find(carried.begin(), carried.end(), l) == carried.end())
        full[ModalEquilibriumProblem::index_of_mode(l)] = 1;  // placeholder: these entries are not taken
    const std::vector<double> lab = modal_->to_modal_model_state(jump.t, full, p_);
    std::copy(lab.begin(), lab.begin() + 5, jump.y.begin());
    for (std::size_t j = 0; j < active.size(); ++j)
      if (std::find(carried.begin(), carried.end(), active[j]) != carried.end())
        jump.y[5 + j] = lab[static_cast<std::size_t>(5 + active[j] - 3)];
    jump.Psi_advance = -2 * kPi * std::round(ref.integrals[0] / (2 * kPi)) * k;
    record.sigma_integral = k * ref.integrals[1] + approach;
    return true;
  }

  bool reduced(double t, std::span<const double> y, int k, AttractorJump& jump, EarlyTermination& record) {
    if (!reduced_) {
      reduced_.emplace(scene_, ContinuationParameter::B);
      p_ = reduced_->start_parameter();
      forced_ = reduced_->model(p_).z0(0) != reduced_->model(p_).z0(kPi / 2);
    }
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(y.data(), 3);
    if (!screened(*reduced_, p_, t, x, record)) return false;
    const ReducedModel& model = reduced_->model(p_);
    const PeriodicRefinement ref = refine_periodic_orbit(
        *reduced_, p_, t, x, o_.refinement,
        orbit_integrands([&model](double s, std::span<const double> z) { return model.sigma(s, z); }));
    record.work += ref.work;
    if (!ref.converged) {
      backoff();
      return fail(record, t, ref.reason);
    }
    if (!accept(ref, ref.multipliers, 0.0, k, t, record)) return false;
    jump.t = t + k * o_.refinement.period;
    jump.y.assign(ref.x.data(), ref.x.data() + 3);
    jump.Psi_advance = -2 * kPi * std::round(ref.integrals[0] / (2 * kPi)) * k;
    record.sigma_integral = k * ref.integrals[1];  // first order in the distance, as the state
    return true;
  }

  Scene scene_;
  EarlyTerminationOptions o_;
  double tolerance_ = 0;
  double radius_ = 0;         // the linearisation radius used: max_distance, at most sqrt(tolerance_)
  double screen_radius_ = 0;  // the one-period defect that lets a refinement go ahead
  double next_ = 0;
  double attempt_t_ = 0, last_t_ = 0, last_defect_ = 0;
  std::optional<ModalForcedSystem> modal_;
  std::optional<ReducedForcedSystem> reduced_;
  double p_ = 0, total_ = 1;
  bool forced_ = true;  // the forcing depends on time: a periodic orbit, else an equilibrium
};

}  // namespace

SimulationResult simulate_certified(const Scene& scene, const SimulationOptions& options,
                                    const EarlyTerminationOptions& early) {
  return simulate_certified(validated(scene), options, early);
}

SimulationResult simulate_certified(const ValidScene& valid, const SimulationOptions& options,
                                    const EarlyTerminationOptions& early) {
  early.validate();
  SceneCertifier certifier(*valid, options, early);
  return simulate(valid, options, &certifier);
}

ReducedTransient certified_transient(const ValidScene& valid, const TruncationOptions& options,
                                     const EarlyTerminationOptions& early) {
  options.validate();
  early.validate();
  const Scene& scene = *valid;
  const double T = scene.T;
  const int K = options.checkpoints;
  std::vector<double> checkpoints;
  for (int k = 1; k <= K; ++k) checkpoints.push_back(T * k / K);
  const double P = 2 * kPi;  // the reduced level's forcing period (SceneCertifier)
  if (T < early.first_attempt + 2 * P) return truncation_transient(valid, options);

  // Integrate to the checkpoints until the state is certified, leaving a period before T for the partial ones.
  SimulationOptions run;
  run.integrator = options.predictor.integrator;
  SceneCertifier certifier(reduced_scene(scene), run, early);
  const ReducedIntegralSystem reduced(valid);
  const System& sys = reduced.system();
  ReducedTransient tr;
  tr.parameters = scene.parameters;
  tr.beta = scene.beta;
  tr.T = T;
  tr.checkpoints = K;
  auto on_sample = [&](double t, std::span<const double> y) {
    tr.t.push_back(t);
    tr.integral.push_back(y[3]);
  };
  AttractorJump jump;
  EarlyTermination record;
  const StopCondition stop = [&](double t, std::span<const double> y) {
    return certifier.certify(sys, t, y.first(3), T - P, jump, record);
  };
  IntegrationResult first = integrate(sys, sys.initial_state(), 0.0, checkpoints, run.integrator, on_sample, {}, stop);
  tr.counters = first.counters;
  tr.counters += record.work;
  if (!first.stopped) {
    tr.status = first.status;
    tr.reason = first.reason;
    tr.t_end = first.status == IntegrationStatus::success ? T : first.t_reached;
    tr.integral_end = first.status == IntegrationStatus::success ? tr.integral.back() : first.y[3];
    return tr;
  }
  // From the resume state on the orbit (jump.y at jump.t, k whole periods after the stop at t_s): a checkpoint t
  // skipped, t = t_s + m P + rem, gets J(t_s) + m I + [J(jump.t + rem) - J(jump.t)], I = the orbit's integral over
  // one period (record.sigma_integral / k); the later checkpoints are integrated.
  const double t_s = first.t_reached, J_s = first.y[3];
  const double k = std::round((jump.t - t_s) / P), I = record.sigma_integral / k;
  std::vector<double> resumed(jump.y.begin(), jump.y.end());
  resumed.push_back(J_s + record.sigma_integral);
  const std::size_t skipped_from = tr.t.size();
  const auto later = std::lower_bound(checkpoints.begin(), checkpoints.end(), jump.t);
  std::vector<double> times;
  std::vector<std::pair<double, double>> partial;  // skipped checkpoint: (m, rem)
  for (auto c = checkpoints.begin() + std::ptrdiff_t(skipped_from); c != later; ++c) {
    const double m = std::floor((*c - t_s) / P);
    partial.emplace_back(m, *c - t_s - m * P);
    times.push_back(jump.t + partial.back().second);
  }
  times.insert(times.end(), later, checkpoints.end());
  std::vector<double> grid = times;
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  if (!grid.empty() && grid.front() <= jump.t) grid.erase(grid.begin());  // rem = 0: J(jump.t) is known
  std::vector<double> at_J;                                               // at each time of grid
  const IntegrationResult second = integrate(sys, resumed, jump.t, grid, run.integrator,
                                             [&](double, std::span<const double> y) { at_J.push_back(y[3]); });
  tr.counters += second.counters;
  if (second.status != IntegrationStatus::success || at_J.size() != grid.size())
    return truncation_transient(valid, options);
  auto J_at = [&](double t) {
    return t <= jump.t ? resumed[3] : at_J[std::size_t(std::lower_bound(grid.begin(), grid.end(), t) - grid.begin())];
  };
  for (std::size_t j = 0; j < partial.size(); ++j) {
    tr.t.push_back(checkpoints[skipped_from + j]);
    tr.integral.push_back(J_s + partial[j].first * I + (J_at(times[j]) - resumed[3]));
  }
  for (auto c = later; c != checkpoints.end(); ++c) {
    tr.t.push_back(*c);
    tr.integral.push_back(J_at(*c));
  }
  tr.t_end = T;
  tr.integral_end = tr.integral.back();
  return tr;
}

SimulationResult simulate_scene(SceneFile& file, const SimulationOptions& options, const ReducedTransient* transient) {
  return simulate_scene(file, validated(file), options, transient);
}

namespace {
const SceneRunner kCertifiedRun = [](const ValidScene& scene, const SimulationOptions& o) {
  return simulate_certified(scene, o);
};

// A full-horizon run skips no work: its automatic L reads the reduced transient integrated to T as well.
TransientRunner transient_runner(bool full_horizon) {
  if (full_horizon) return {};
  return [](const ValidScene& scene, const TruncationOptions& o) { return certified_transient(scene, o); };
}
}  // namespace

SimulationResult simulate_scene(SceneFile& file, const ValidScene& valid, const SimulationOptions& options,
                                const ReducedTransient* transient) {
  return simulate_truncated(file, valid, options, transient, kCertifiedRun, transient_runner(options.full_horizon));
}

void apply_scene_truncation(SceneFile& file, TruncationUse use) {
  const ValidScene valid = validated(file);
  apply_truncation(file, valid, use, nullptr, kCertifiedRun, transient_runner(file.options.full_horizon));
}

ReducedTransient scene_transient(const ValidScene& scene, bool full_horizon) {
  return full_horizon ? truncation_transient(scene) : certified_transient(scene);
}

}  // namespace rbcstab
