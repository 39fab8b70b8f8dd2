// rbcstab continue: an equilibrium or periodic-orbit branch of the reduced system in one parameter,
// with its special points (AUTO-07p labels), as CSV and/or one JSON object.
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct ContinueOptions {
  SceneOptions scene;
  std::string kind = "equilibrium";
  std::string parameter = "lambda";
  double p_min = -INFINITY, p_max = INFINITY;
  std::string direction = "both";
  ContinuationOptions engine;
  double relax_T = 200;
  OrbitOptions orbit;  // --segments
  bool json = false;
  std::string csv;
};

std::string branch_csv(const Branch& b, const std::string& name) {
  std::ostringstream ss;
  ss << std::setprecision(17) << name << ",r,Psi,Re_z,Im_z,w,stable,n_unstable,max_Re_eig\n";
  for (const auto& pt : b.points) {
    const PolarState s = polar(pt.x);
    double m = -INFINITY;
    for (Eigen::Index i = 0; i < pt.spectrum.size(); ++i) m = std::max(m, pt.spectrum[i].real());
    ss << pt.p << ',' << s.r << ',' << s.Psi << ',' << pt.x[0] << ',' << pt.x[1] << ',' << pt.x[2] << ','
       << (pt.stable ? 1 : 0) << ',' << pt.n_unstable << ',' << m << '\n';
  }
  return ss.str();
}

// describe(x, p): the state fields of a point by symbol (r, Psi, ... for the problem kind).
using Describe = std::function<nlohmann::json(const Eigen::VectorXd& x, double p)>;

nlohmann::json branch_json(const Branch& b, const Describe& describe, const std::string& spectrum_key) {
  nlohmann::json pts = nlohmann::json::array();
  for (const auto& pt : b.points) {
    nlohmann::json j;
    for (std::size_t k = 0; k < b.parameter_names.size(); ++k) j[b.parameter_names[k]] = number_or_null(pt.parameters[k]);
    j.update(describe(pt.x, pt.p));
    j["stable"] = pt.stable;
    j["n_unstable"] = pt.n_unstable;
    nlohmann::json ev = nlohmann::json::array();
    for (Eigen::Index i = 0; i < pt.spectrum.size(); ++i)
      ev.push_back({number_or_null(pt.spectrum[i].real()), number_or_null(pt.spectrum[i].imag())});
    j[spectrum_key] = ev;
    pts.push_back(j);
  }
  nlohmann::json sps = nlohmann::json::array();
  for (const auto& sp : b.special_points) {
    nlohmann::json j;
    j["type"] = to_string(sp.type);
    j["name"] = sp.name;
    for (std::size_t k = 0; k < b.parameter_names.size(); ++k) j[b.parameter_names[k]] = number_or_null(sp.parameters[k]);
    j.update(describe(sp.x, sp.p));
    if (sp.type == SpecialPointType::PD || sp.type == SpecialPointType::NS || sp.type == SpecialPointType::HB)
      j["critical"] = {number_or_null(sp.eigenvalue.real()), number_or_null(sp.eigenvalue.imag())};
    j["bracket"] = {number_or_null(sp.p_lo), number_or_null(sp.p_hi)};
    j["precision"] = number_or_null(sp.precision);
    j["status"] = to_string(sp.status);
    j["unstable_before"] = sp.unstable_before;
    j["unstable_after"] = sp.unstable_after;
    sps.push_back(j);
  }
  nlohmann::json out;
  out["branch"] = pts;
  out["special_points"] = sps;
  out["status"] = to_string(b.status);
  out["message"] = b.message;
  out["counters"] = {{"steps", b.counters.steps},
                     {"rejected_steps", b.counters.rejected_steps},
                     {"newton_iterations", b.counters.newton_iterations},
                     {"residual_evaluations", b.counters.residual_evaluations},
                     {"jacobian_evaluations", b.counters.jacobian_evaluations},
                     {"location_iterations", b.counters.location_iterations}};
  return out;
}

nlohmann::json polar_json(const Eigen::VectorXd& y) {
  const PolarState s = polar(y);
  return {{"r", number_or_null(s.r)}, {"Psi", number_or_null(s.Psi)}};
}

std::string orbit_csv(const Branch& b, const std::string& name, const PeriodicOrbitProblem& pr) {
  std::ostringstream ss;
  ss << std::setprecision(17) << name
     << ",r,Psi,r_min,r_max,Psi_min,Psi_max,winding,kind,stable,n_unstable,max_abs_multiplier\n";
  for (const auto& pt : b.points) {
    const OrbitSummary s = pr.summary(pt.x, pt.p);
    double m = 0;
    for (Eigen::Index i = 0; i < pt.spectrum.size(); ++i) m = std::max(m, std::abs(pt.spectrum[i]));
    ss << pt.p << ',' << s.r0 << ',' << s.Psi0 << ',' << s.r_min << ',' << s.r_max << ',' << s.Psi_min << ','
       << s.Psi_max << ',' << s.winding << ',' << to_string(s.kind) << ',' << (pt.stable ? 1 : 0) << ','
       << pt.n_unstable << ',' << m << '\n';
  }
  return ss.str();
}

nlohmann::json orbit_json(const PeriodicOrbitProblem& pr, const Eigen::VectorXd& X, double p) {
  const OrbitSummary s = pr.summary(X, p);
  const Floquet f = pr.floquet(X, p);
  return {{"r", number_or_null(s.r0)},
          {"Psi", number_or_null(s.Psi0)},
          {"r_min", number_or_null(s.r_min)},
          {"r_max", number_or_null(s.r_max)},
          {"Psi_min", number_or_null(s.Psi_min)},
          {"Psi_max", number_or_null(s.Psi_max)},
          {"winding", s.winding},
          {"kind", to_string(s.kind)},
          {"trivial_multiplier", f.trivial ? number_or_null(*f.trivial) : nlohmann::json(nullptr)}};
}

// Shared by both kinds: output and exit code.
int report(const ContinueOptions& o, const SceneFile& sf, const Branch& b, const std::string& csv,
           const Describe& describe, const std::string& spectrum_key) {
  if (!o.csv.empty()) write_file_atomic(o.csv, csv);
  if (o.json) {
    nlohmann::json j = branch_json(b, describe, spectrum_key);
    j["kind"] = o.kind;
    j["level"] = "reduced";
    j["free_parameter"] = o.parameter;
    j["parameters"] = to_json(sf.scene.parameters);
    j["beta"] = sf.scene.beta;
    if (o.kind == "orbit") j["segments"] = o.orbit.segments;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << std::setprecision(10) << b.points.size() << " points in " << o.parameter << " from "
              << b.points.front().p << " to " << b.points.back().p << ", status " << to_string(b.status) << " ("
              << b.message << ")\n";
    for (const auto& sp : b.special_points)
      std::cout << sp.name << " " << o.parameter << " = " << sp.p << " (" << to_string(sp.status) << ", precision "
                << sp.precision << ", unstable " << sp.unstable_before << " -> " << sp.unstable_after << ")\n";
  }
  // A branch that runs into the edge of the parameter's domain has ended normally.
  if (b.status != ContinuationStatus::completed && b.status != ContinuationStatus::outside_domain) {
    std::cerr << "rbcstab: continuation stopped: " << to_string(b.status) << ": " << b.message << "\n";
    return kRunFailed;
  }
  return kOk;
}

int run(ContinueOptions& o) {
  if (o.kind != "equilibrium" && o.kind != "orbit")
    throw InvalidArgument("kind", "kind = '" + o.kind + "' is not available: must be equilibrium or orbit "
                                                        "(two-parameter curves are not implemented yet)");
  const bool orbit = o.kind == "orbit";
  if (orbit) o.orbit.validate();
  SceneFile sf = o.scene.resolve();
  // Equilibria need an autonomous reduced system (rest shape out of plane), periodic orbits a forced
  // one (rest shape in plane), unless beta is given.
  if (o.scene.o_beta->count() == 0 && o.scene.scene_path.empty()) sf.scene.beta = orbit ? M_PI / 2 : 0;
  if (sf.scene.model != ModelLevel::automatic && sf.scene.model != ModelLevel::reduced)
    throw InvalidArgument("model", "model = " + to_string(sf.scene.model) +
                                       " is not available for continuation: must be reduced (or auto)");
  const ContinuationParameter q = continuation_parameter_from_string(o.parameter);
  // lambda's domain starts at 0 inclusive: land there exactly unless told otherwise.
  o.engine.p_min = (q == ContinuationParameter::lambda && o.p_min < 0) ? 0.0 : o.p_min;
  o.engine.p_max = o.p_max;
  o.engine.direction = o.direction == "forward" ? Direction::forward
                       : o.direction == "backward" ? Direction::backward
                                                   : Direction::both;
  if (!orbit) {
    const ReducedEquilibriumProblem problem(sf.scene, q);
    const Branch b = continue_branch(problem, problem.relaxed_state(o.relax_T), problem.start_parameter(), o.engine);
    return report(o, sf, b, branch_csv(b, o.parameter), [](const Eigen::VectorXd& y, double) { return polar_json(y); },
                  "eigenvalues");
  }
  const ReducedForcedSystem system(sf.scene, q);
  const PeriodicOrbitProblem problem(system, o.orbit);
  const double p0 = system.start_parameter();
  // Start: the scene relaxed for relax_T (rounded up to a multiple of 2 pi), then Newton on the orbit.
  const NewtonResult start = solve_fixed_parameter(problem, problem.shooting_guess(system.relaxed_state(o.relax_T), p0), p0);
  if (!start.converged) {
    std::cerr << "rbcstab: no periodic orbit near the relaxed state (Newton residual " << start.residual_norm
              << " after " << start.iterations << " iterations); try a longer --relax-T\n";
    return kRunFailed;
  }
  o.engine.events.push_back(problem.transition_event());
  const Branch b = continue_branch(problem, start.x, p0, o.engine);
  return report(o, sf, b, orbit_csv(b, o.parameter, problem),
                [&](const Eigen::VectorXd& X, double p) { return orbit_json(problem, X, p); }, "multipliers");
}
}  // namespace

static Runner add_continue(CLI::App& app) {
  auto o = std::make_shared<ContinueOptions>();
  o->scene.add_to(app);
  app.add_option("--kind", o->kind,
                 "what to continue: equilibrium (reduced system, out-of-plane rest shape) or orbit (periodic orbits "
                 "of the forced in-plane reduced system: swinging/tumbling, Floquet multipliers, LPC/PD/NS, UZ "
                 "swing_tumble)");
  app.add_option("--segments", o->orbit.segments, "orbit: number of multiple-shooting segments");
  app.add_option("--parameter", o->parameter, "free parameter: lambda, Delta, Delta0, B, C, Lambda or S");
  app.add_option("--min", o->p_min, "lower bound of the free parameter (the branch ends there exactly)");
  app.add_option("--max", o->p_max, "upper bound of the free parameter (the branch ends there exactly)");
  app.add_option("--direction", o->direction, "forward (parameter increasing), backward or both")
      ->check(CLI::IsMember({"forward", "backward", "both"}));
  app.add_option("--step", o->engine.initial_step, "first arclength step");
  app.add_option("--max-step", o->engine.max_step, "largest arclength step");
  app.add_option("--max-points", o->engine.max_points, "points per direction");
  app.add_option("--relax-T", o->relax_T, "relaxation time that gives the start state from the scene's shape (orbits: rounded up to a multiple of 2 pi)");
  app.add_flag("--json", o->json, "print one JSON object (branch, special_points) on stdout");
  app.add_option("--csv", o->csv, "write the branch as CSV to this file");
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegister{"continue", "Continue an equilibrium or periodic-orbit branch in one parameter; locate LP/BP/HB, LPC/PD/NS",
                                add_continue, 40};
}  // namespace

}  // namespace rbcstab::cli
