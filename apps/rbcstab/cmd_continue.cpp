// rbcstab continue: an equilibrium branch (reduced system, modal or full model) or a periodic-orbit branch of the reduced system in one parameter,
// with its special points (AUTO-07p labels), as CSV and/or one JSON object.
#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "checks.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/continuation/branch_point_curve.hpp"
#include "rbcstab/continuation/branch_switch.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/hopf_curve.hpp"
#include "rbcstab/continuation/two_parameter.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/modal_orbit_bp_curve.hpp"
#include "rbcstab/continuation/ns_curve.hpp"
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
  bool switch_at_bp = false;  // continue the bifurcating branch from the first BP (equilibrium, modal)
  // --curve: the two-parameter curve of the point-th special point of this type, in (parameter, parameter2).
  std::string curve;
  std::string parameter2;
  double p2_min = -INFINITY, p2_max = INFINITY;
  int point = 1;
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

// Modal and full equilibria: the l = 2 shape (r, Psi), sigma and every Delta_l; `branch` tells the
// continued branch (primary) from the one switched to at its first BP (switched).
template <class Problem>  // ModalEquilibriumProblem, FullEquilibriumProblem
std::string modal_csv(const Branch& b, const BranchSwitchResult* sw, const std::string& name, const Problem& pr) {
  std::ostringstream ss;
  ss << std::setprecision(17) << name << ",branch,r,Psi,sigma";
  for (int l = 2; l <= pr.L(); ++l) ss << ",Delta_" << l;
  ss << ",stable,n_unstable,max_Re_eig\n";
  auto rows = [&](const Branch& br, const char* label) {
    for (const auto& pt : br.points) {
      const auto st = pr.observe(pt.x, pt.p);
      double m = -INFINITY;
      for (Eigen::Index i = 0; i < pt.spectrum.size(); ++i) m = std::max(m, pt.spectrum[i].real());
      ss << pt.p << ',' << label << ',' << st.r << ',' << st.Psi << ',' << st.sigma;
      for (double D : st.Delta_l) ss << ',' << D;
      ss << ',' << (pt.stable ? 1 : 0) << ',' << pt.n_unstable << ',' << m << '\n';
    }
  };
  rows(b, "primary");
  if (sw && sw->switched) rows(sw->branch, "switched");
  return ss.str();
}

template <class Problem>  // ModalEquilibriumProblem, FullEquilibriumProblem
nlohmann::json modal_json(const Problem& pr, const Eigen::VectorXd& x, double p) {
  const auto st = pr.observe(x, p);
  nlohmann::json j = {{"r", number_or_null(st.r)}, {"Psi", number_or_null(st.Psi)}, {"sigma", number_or_null(st.sigma)}};
  for (int l = 2; l <= pr.L(); ++l) j["Delta_" + std::to_string(l)] = number_or_null(st.Delta_l[static_cast<std::size_t>(l - 2)]);
  return j;
}

// Modal orbits (--kind modal-orbit): the state at t = 0 (r, Psi, sigma, every Delta_l), the winding
// of z and the trivial multiplier.
std::string modal_orbit_csv(const Branch& b, const std::string& name, const PeriodicOrbitProblem& pr,
                            const ModalForcedSystem& sys) {
  std::ostringstream ss;
  ss << std::setprecision(17) << name << ",r,Psi,sigma";
  for (int l = 2; l <= sys.L(); ++l) ss << ",Delta_" << l;
  ss << ",winding,kind,stable,n_unstable,max_abs_multiplier\n";
  for (const auto& pt : b.points) {
    const ModalState st = sys.observe(0.0, pr.state_at_zero(pt.x), pt.p);
    const OrbitSummary s = pr.summary(pt.x, pt.p);
    double m = 0;
    for (Eigen::Index i = 0; i < pt.spectrum.size(); ++i) m = std::max(m, std::abs(pt.spectrum[i]));
    ss << pt.p << ',' << st.r << ',' << st.Psi << ',' << st.sigma;
    for (double D : st.Delta_l) ss << ',' << D;
    ss << ',' << s.winding << ',' << to_string(s.kind) << ',' << (pt.stable ? 1 : 0) << ',' << pt.n_unstable << ','
       << m << '\n';
  }
  return ss.str();
}

nlohmann::json modal_orbit_json(const PeriodicOrbitProblem& pr, const ModalForcedSystem& sys, const Eigen::VectorXd& X,
                                double p) {
  const ModalState st = sys.observe(0.0, pr.state_at_zero(X), p);
  const OrbitSummary s = pr.summary(X, p);
  const Floquet f = pr.floquet(X, p);
  nlohmann::json j = {{"r", number_or_null(st.r)},
                      {"Psi", number_or_null(st.Psi)},
                      {"sigma", number_or_null(st.sigma)},
                      {"winding", s.winding},
                      {"kind", to_string(s.kind)},
                      {"trivial_multiplier", f.trivial ? number_or_null(*f.trivial) : nlohmann::json(nullptr)}};
  for (int l = 2; l <= sys.L(); ++l) j["Delta_" + std::to_string(l)] = number_or_null(st.Delta_l[static_cast<std::size_t>(l - 2)]);
  return j;
}

// --switch-at-bp: the bifurcating branch at the first BP of b, continued with the same engine options.
BranchSwitchResult switch_at_first_bp(const ContinuationProblem& problem, const Branch& b, const ContinuationOptions& engine) {
  for (const auto& sp : b.special_points) {
    if (sp.type != SpecialPointType::BP) continue;
    BranchSwitchOptions so;
    so.continuation = engine;
    return switch_branch(problem, b, sp, so);
  }
  BranchSwitchResult none;
  none.message = "--switch-at-bp: the branch has no BP (branch point) to switch at";
  return none;
}

// Shared by both kinds: output and exit code.
int report(const ContinueOptions& o, const SceneFile& sf, const Branch& b, const std::string& csv,
           const Describe& describe, const std::string& spectrum_key, const BranchSwitchResult* switched = nullptr) {
  if (!o.csv.empty()) write_file_atomic(o.csv, csv);
  if (o.json) {
    nlohmann::json j = branch_json(b, describe, spectrum_key);
    j["kind"] = o.kind;
    j["level"] = o.kind == "full" ? "full" : o.kind == "modal" || o.kind == "modal-orbit" ? "modal" : "reduced";
    j["free_parameter"] = o.parameter;
    put_truncation(j, sf);
    j["parameters"] = to_json(sf.scene.parameters);
    j["beta"] = sf.scene.beta;
    if (o.kind == "orbit" || o.kind == "modal-orbit") j["segments"] = o.orbit.segments;
    if (switched) {
      nlohmann::json sw = branch_json(switched->branch, describe, spectrum_key);
      sw["switched"] = switched->switched;
      if (!switched->switched) sw["message"] = switched->message;
      j["switched_branch"] = sw;
    }
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << std::setprecision(10) << b.points.size() << " points in " << o.parameter << " from "
              << b.points.front().p << " to " << b.points.back().p << ", status " << to_string(b.status) << " ("
              << b.message << ")\n";
    for (const auto& sp : b.special_points)
      std::cout << sp.name << " " << o.parameter << " = " << sp.p << " (" << to_string(sp.status) << ", precision "
                << sp.precision << ", unstable " << sp.unstable_before << " -> " << sp.unstable_after << ")\n";
    if (switched && switched->switched) {
      const Branch& s = switched->branch;
      std::cout << "switched at the first BP: " << s.points.size() << " points in " << o.parameter << " from "
                << s.points.front().p << " to " << s.points.back().p << ", status " << to_string(s.status) << " ("
                << s.message << ")\n";
      for (const auto& sp : s.special_points)
        std::cout << "  " << sp.name << " " << o.parameter << " = " << sp.p << " (" << to_string(sp.status)
                  << ", precision " << sp.precision << ", unstable " << sp.unstable_before << " -> "
                  << sp.unstable_after << ")\n";
    }
  }
  if (switched && !switched->switched) {
    std::cerr << "rbcstab: branch switching failed: " << switched->message << "\n";
    return kRunFailed;
  }
  // A branch that runs into the edge of the parameter's domain has ended normally.
  if (b.status != ContinuationStatus::completed && b.status != ContinuationStatus::outside_domain) {
    std::cerr << "rbcstab: continuation stopped: " << to_string(b.status) << ": " << b.message << "\n";
    return kRunFailed;
  }
  return kOk;
}

// ---- --curve: a special point's curve in two parameters ----

// The point-th special point of type `type` on b (located: the curve systems start from an exact point).
const SpecialPoint& pick_point(const Branch& b, const std::string& type, int point) {
  int k = 0;
  for (const auto& sp : b.special_points) {
    if (to_string(sp.type) != type) continue;
    if (++k < point) continue;
    if (sp.status != LocationStatus::located)
      throw std::runtime_error("--curve " + type + ": special point " + sp.name + " at " + b.parameter_names.front() +
                               " = " + std::to_string(sp.p) + " was not located (" + to_string(sp.status) +
                               "); its curve needs an exact start");
    return sp;
  }
  throw std::runtime_error("--curve " + type + ": no located " + type + " point number " + std::to_string(point) +
                           ": the one-parameter branch has " + std::to_string(k) + " " + type +
                           " point(s); widen --min/--max");
}

// Output of a curve: the underlying point's state by symbol (describe(x, p1, p2)) and, for HB, omega.
using DescribeCurve = std::function<nlohmann::json(const Eigen::VectorXd& x, double p1, double p2)>;

int report_curve(const ContinueOptions& o, const SceneFile& sf, const Branch& one, const SpecialPoint& start,
                 const ContinuationProblem& curve, const Branch& c, Eigen::Index n, const DescribeCurve& describe,
                 const std::string& spectrum_key, const std::function<double(const Eigen::VectorXd&)>& omega) {
  // describe a curve point X (first n entries: the state, then p1 at n except for the modal BP curve).
  auto state = [&](const Eigen::VectorXd& X, double p2) {
    const double p1 = curve.parameter_values(X, p2)[0];
    nlohmann::json j = describe(X.head(n), p1, p2);
    if (omega) j["omega"] = number_or_null(omega(X));
    return j;
  };
  if (!o.csv.empty()) {
    std::ostringstream ss;
    // The ellipsoidal-orbit BP curve also reports sigma_bar and the critical mode.
    const bool zbp = !c.points.empty() && state(c.points.front().x, c.points.front().p).contains("sigma_bar");
    ss << std::setprecision(17) << o.parameter << ',' << o.parameter2 << ",r,Psi" << (omega ? ",omega" : "")
       << (zbp ? ",sigma_bar,mode" : "") << ",stable,n_unstable\n";
    for (const auto& pt : c.points) {
      const nlohmann::json j = state(pt.x, pt.p);
      ss << pt.parameters[0] << ',' << pt.parameters[1] << ',' << j["r"].get<double>() << ',' << j["Psi"].get<double>();
      if (omega) ss << ',' << j["omega"].get<double>();
      if (zbp) ss << ',' << j["sigma_bar"].get<double>() << ',' << j["mode"].get<int>();
      ss << ',' << (pt.stable ? 1 : 0) << ',' << pt.n_unstable << '\n';
    }
    write_file_atomic(o.csv, ss.str());
  }
  if (o.json) {
    nlohmann::json j = branch_json(c, [&](const Eigen::VectorXd& X, double p2) { return state(X, p2); }, spectrum_key);
    j["kind"] = o.kind;
    j["level"] = o.kind == "full" ? "full" : o.kind == "modal" || o.kind == "modal-orbit" ? "modal" : "reduced";
    j["free_parameter"] = o.parameter2;
    put_truncation(j, sf);
    j["parameters"] = to_json(sf.scene.parameters);
    j["beta"] = sf.scene.beta;
    if (o.kind == "orbit" || o.kind == "modal-orbit") j["segments"] = o.orbit.segments;
    nlohmann::json st;
    st["type"] = to_string(start.type);
    st["name"] = start.name;
    st[o.parameter] = number_or_null(start.p);
    const Scene& s2 = o.kind == "modal-orbit" ? total_area_scene(sf.scene) : sf.scene;  // as run_curve
    st[o.parameter2] = number_or_null(get_parameter(s2, continuation_parameter_from_string(o.parameter2)));
    st["precision"] = number_or_null(start.precision);
    st["status"] = to_string(start.status);
    j["curve"] = {{"type", o.curve}, {"parameters", {o.parameter, o.parameter2}}, {"start", st},
                  {"one_parameter_points", one.points.size()}};
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << std::setprecision(10) << o.curve << " curve from " << start.name << " (" << o.parameter << " = "
              << start.p << "): " << c.points.size() << " points in (" << o.parameter << ", " << o.parameter2
              << "), " << o.parameter2 << " from " << c.points.front().p << " to " << c.points.back().p << ", status "
              << to_string(c.status) << " (" << c.message << ")\n";
    for (const auto& sp : c.special_points)
      std::cout << sp.name << " " << o.parameter << " = " << sp.parameters[0] << ", " << o.parameter2 << " = "
                << sp.parameters[1] << " (" << to_string(sp.status) << ", precision " << sp.precision << ")\n";
  }
  if (c.status != ContinuationStatus::completed && c.status != ContinuationStatus::outside_domain) {
    std::cerr << "rbcstab: curve continuation stopped: " << to_string(c.status) << ": " << c.message << "\n";
    return kRunFailed;
  }
  return kOk;
}

// The curve run: validates the combination, runs the curve from the chosen point of `one`.
// --parameter2, checked against --parameter (before any work is done).
ContinuationParameter parameter2(const ContinueOptions& o) {
  const ContinuationParameter q2 = [&] {
    try {
      return continuation_parameter_from_string(o.parameter2);
    } catch (const InvalidArgument&) {
      throw InvalidArgument("parameter2", "parameter2 = '" + o.parameter2 +
                                              "' is not a continuation parameter: must be one of lambda, Delta, "
                                              "Delta0, B, C, Lambda, S, beta");
    }
  }();
  require_independent(continuation_parameter_from_string(o.parameter), q2, "parameter2");
  return q2;
}

// The engine's bounds of parameter q from --min/--max (or --min2/--max2). Closed domain edges are
// landed on exactly unless told otherwise: lambda >= 0, beta in [0, pi].
void set_bounds(ContinuationOptions& engine, ContinuationParameter q, double lo, double hi) {
  const bool beta = q == ContinuationParameter::beta;
  engine.p_min = ((q == ContinuationParameter::lambda || beta) && lo < 0) ? 0.0 : lo;
  engine.p_max = (beta && hi > M_PI) ? M_PI : hi;
}

int run_curve(ContinueOptions& o, const SceneFile& sf, const Branch& one) {
  const ContinuationParameter q1 = continuation_parameter_from_string(o.parameter);
  const ContinuationParameter q2 = parameter2(o);
  const SpecialPoint* sp = nullptr;
  try {
    sp = &pick_point(one, o.curve, o.point);
  } catch (const std::runtime_error& e) {
    std::cerr << "rbcstab: " << e.what() << "\n";
    return kRunFailed;
  }
  ContinuationOptions engine = o.engine;
  engine.events.clear();  // the one-parameter events read the one-parameter state
  set_bounds(engine, q2, o.p2_min, o.p2_max);  // as for --min/--max
  engine.direction = Direction::both;
  // modal-orbit: the orbit problem's Delta is the relaxed scene's total excess area (as in run()).
  Scene scene = o.kind == "modal-orbit" ? total_area_scene(sf.scene) : sf.scene;
  scene = with_parameter(scene, q1, sp->p);  // the curve's start
  const double p2_0 = get_parameter(scene, q2);
  auto polar_of = [](const Eigen::VectorXd& y, double, double) { return polar_json(y.head(3)); };
  // Continues a curve from its own start and writes it (n: the curve point's state size).
  auto trace = [&](const auto& curve, Eigen::Index n, const DescribeCurve& describe, const std::string& spectrum_key,
                   const std::function<double(const Eigen::VectorXd&)>& omega = nullptr) {
    return report_curve(o, sf, one, *sp, curve, continue_branch(curve, curve.start(), p2_0, engine), n, describe,
                        spectrum_key, omega);
  };
  // Cycle curves: one code path for the reduced and the modal forced systems. The curve unknowns start
  // with the shooting state (the NS curve's are (X, p1, kappa = cos theta)); r, Psi are those of (z, w).
  auto cycle_curve = [&](const ForcedSystem2& system) {
    const OrbitTwoParameterProblem base(system, o.orbit);
    const Eigen::Index n = base.dimension();
    if (o.curve == "LPC") {
      const FoldCurveProblem curve(base, *sp, p2_0);
      return trace(curve, n, polar_of, "multipliers");
    }
    if (o.curve == "BP") {
      // A BP of cycles (e.g. the modal orbit's symmetry-breaking a_l -> -a_l pitchfork): the generic
      // BP system over the shooting problem (2 n + 2 unknowns, central-difference Jacobian).
      const BranchPointCurveProblem curve(base, *sp, p2_0);
      return trace(curve, n, polar_of, "multipliers");
    }
    if (o.curve == "NS") {
      const NeimarkSackerCurveProblem curve(system, o.orbit, *sp, p2_0);
      return trace(curve, n, polar_of, "multipliers");
    }
    const PeriodDoublingCurveProblem curve(base, *sp, p2_0);
    return trace(curve, n, polar_of, "multipliers");
  };
  // Equilibrium curves over any level's two-parameter problem: the generic LP, BP (2n + 2 system) and HB
  // systems; the first n unknowns of a curve point are the state.
  auto equilibrium_curve = [&](const TwoParameterProblem& base, Eigen::Index n, const DescribeCurve& describe) {
    if (o.curve == "LP") {
      const FoldCurveProblem curve(base, *sp, p2_0);
      return trace(curve, n, describe, "eigenvalues");
    }
    if (o.curve == "BP") {
      const BranchPointCurveProblem curve(base, *sp, p2_0);
      return trace(curve, n, describe, "eigenvalues");
    }
    const HopfCurveProblem curve(base, *sp, p2_0);
    return trace(curve, n, describe, "eigenvalues", [&](const Eigen::VectorXd& X) { return curve.omega(X); });
  };
  if (o.kind == "orbit") return cycle_curve(ReducedForcedSystem2(scene, q1, q2));
  if (o.kind == "modal-orbit" && o.curve == "BP") {
    // A symmetry-breaking BP of the in-plane ellipsoidal orbit (v~ = 0 and every a_l = 0 at the point):
    // the Z2-reduced system (reduced shooting + sigma_bar = sigma_l^c, 3 N + 1 unknowns, cost independent
    // of L). Any other BP (e.g. of the post-instability orbit) keeps the generic system.
    const Eigen::Index nm = 5 + (scene.L - 2);
    const Eigen::VectorXd x0 = sp->x.head(nm);
    if (ModalOrbitBranchPointCurve::has_untilted_rest_shape(scene) && q1 != ContinuationParameter::beta && q2 != ContinuationParameter::beta &&
        x0.tail(nm - 3).cwiseAbs().maxCoeff() <= 1e-8) {
      const ModalOrbitBranchPointCurve probe(scene, q1, q2, 3, o.orbit);
      const Eigen::VectorXd X0 = probe.start_from_modal(sp->x, sp->p);
      const Eigen::Index n = X0.size() - 1;
      const int l = ellipsoidal_orbit_critical_mode(probe.parameters(sp->p, p2_0), scene.L,
                                                    probe.sigma_bar(X0.head(n), sp->p, p2_0));
      const ModalOrbitBranchPointCurve curve(scene, q1, q2, l, o.orbit);
      const DescribeCurve zbp_of = [&](const Eigen::VectorXd& X, double p1, double p2) {
        nlohmann::json j = polar_json(X.head(3));
        j["sigma_bar"] = number_or_null(curve.sigma_bar(X, p1, p2));
        j["mode"] = l;
        return j;
      };
      return report_curve(o, sf, one, *sp, curve, continue_branch(curve, X0, p2_0, engine), n, zbp_of, "multipliers",
                          nullptr);
    }
  }
  if (o.kind == "modal-orbit") return cycle_curve(ModalForcedSystem2(scene, q1, q2));
  if (o.kind == "modal") {
    const SceneTwoParameterProblem<ModalEquilibriumProblem> base(scene, q1, q2);
    const DescribeCurve modal_of = [&](const Eigen::VectorXd& x, double p1, double p2) {
      Eigen::VectorXd full = Eigen::VectorXd::Zero(base.dimension());
      full.head(x.size()) = x;
      return modal_json(base.at(p2), full, p1);
    };
    if (o.curve == "BP") {
      // The symmetry-breaking BP of mode l: ModalBranchPointCurve (the ellipsoidal l = 2 block plus
      // Upsilon_l(sigma) = 0, six unknowns, exact) instead of the generic 2n + 2 BP system.
      const ModalBranchPointCurve curve(scene, q1, q2, critical_mode(base.at(p2_0), sp->x, sp->p));
      return report_curve(o, sf, one, *sp, curve, continue_branch(curve, curve.start(sp->x, sp->p), p2_0, engine), 5,
                          modal_of, "eigenvalues", nullptr);
    }
    return equilibrium_curve(base, base.dimension(), modal_of);
  }
  if (o.kind == "full") {
    // The generic curve systems over the full problem (BP: the 2n + 2 system of branch_point_curve.hpp,
    // e.g. an unforced mode's Z2 pitchfork).
    const SceneTwoParameterProblem<FullEquilibriumProblem> base(scene, q1, q2);
    const DescribeCurve full_of = [&](const Eigen::VectorXd& x, double p1, double p2) {
      return modal_json(base.at(p2), x, p1);
    };
    return equilibrium_curve(base, base.dimension(), full_of);
  }
  return equilibrium_curve(SceneTwoParameterProblem<ReducedEquilibriumProblem>(scene, q1, q2), 3, polar_of);
}

int run(ContinueOptions& o) {
  if (o.kind != "equilibrium" && o.kind != "orbit" && o.kind != "modal" && o.kind != "modal-orbit" && o.kind != "full")
    throw InvalidArgument("kind", "kind = '" + o.kind + "' is not available: must be equilibrium, orbit, modal, modal-orbit or full");
  const bool full = o.kind == "full";
  const bool modal_orbit = o.kind == "modal-orbit";
  const bool orbit = o.kind == "orbit" || modal_orbit;
  const bool modal = o.kind == "modal" || modal_orbit;
  if (orbit && o.switch_at_bp)
    throw InvalidArgument("switch-at-bp", "--switch-at-bp is available for --kind equilibrium, modal and full, not orbit or modal-orbit");
  if (orbit) o.orbit.validate();
  if (!o.curve.empty()) {
    const bool cycle_curve = o.curve == "LPC" || o.curve == "PD" || o.curve == "NS";
    if (orbit != cycle_curve && !(orbit && o.curve == "BP"))
      throw InvalidArgument("curve", "curve = " + o.curve + " is not available for --kind " + o.kind + ": must be " +
                                         (orbit ? "LPC, PD, NS or BP" : "LP, BP or HB"));
    if (o.parameter2.empty()) throw InvalidArgument("parameter2", "--curve needs --parameter2 (the second free parameter)");
    if (o.switch_at_bp) throw InvalidArgument("switch-at-bp", "--switch-at-bp and --curve cannot be combined");
    parameter2(o);
    if (!(o.p2_min < o.p2_max))
      throw InvalidArgument("min2", "min2 = " + std::to_string(o.p2_min) + " must be < max2 = " + std::to_string(o.p2_max));
  } else if (!o.parameter2.empty()) {
    throw InvalidArgument("parameter2", "--parameter2 needs --curve LP|BP|HB|LPC|PD|NS");
  }
  SceneFile sf = o.scene.resolve(full || modal ? TruncationUse::analysis : TruncationUse::reduced);
  // Equilibria need an autonomous reduced system (rest shape out of plane), periodic orbits a forced
  // one (rest shape in plane), unless beta is given.
  if (sf.origin("initial.beta") != Origin::flag && o.scene.scene_path.empty()) sf.scene.beta = orbit ? M_PI / 2 : 0;
  const ModelLevel level = full ? ModelLevel::full : modal ? ModelLevel::modal : ModelLevel::reduced;
  if (sf.scene.model != ModelLevel::automatic && sf.scene.model != level)
    throw InvalidArgument("model", "model = " + to_string(sf.scene.model) + " is not available for --kind " + o.kind +
                                       ": must be " + to_string(level) + " (or auto)");
  const ContinuationParameter q = continuation_parameter_from_string(o.parameter);
  set_bounds(o.engine, q, o.p_min, o.p_max);
  {
    // Every branch starts at the scene's value (modal-orbit: its total excess area, as below).
    const double p_start = get_parameter(modal_orbit ? total_area_scene(sf.scene) : sf.scene, q);
    if (!(p_start >= o.engine.p_min && p_start <= o.engine.p_max)) {
      std::ostringstream m;
      m << std::setprecision(10) << "the branch starts at the scene's " << o.parameter << " = " << p_start
        << ", outside [--min, --max] = [" << o.engine.p_min << ", " << o.engine.p_max
        << "]: widen the range or change the scene";
      throw InvalidArgument("min", m.str());
    }
  }
  o.engine.direction = o.direction == "forward" ? Direction::forward
                       : o.direction == "backward" ? Direction::backward
                                                   : Direction::both;
  if (modal_orbit) {
    // The scene is the one simulated to relax; the orbit problem's Delta is its total excess area.
    const ModalForcedSystem system(total_area_scene(sf.scene), q);
    const PeriodicOrbitProblem problem(system, o.orbit);
    const double p0 = system.start_parameter();
    const NewtonResult start =
        solve_fixed_parameter(problem, problem.shooting_guess(system.relaxed_state(sf.scene, o.relax_T), p0), p0);
    if (!start.converged) {
      std::cerr << "rbcstab: no periodic orbit near the relaxed modal state (Newton residual " << start.residual_norm
                << " after " << start.iterations << " iterations); try a longer --relax-T\n";
      return kRunFailed;
    }
    o.engine.events.push_back(problem.transition_event());
    const Branch b = continue_branch(problem, start.x, p0, o.engine);
    if (!o.curve.empty()) return run_curve(o, sf, b);
    return report(o, sf, b, modal_orbit_csv(b, o.parameter, problem, system),
                  [&](const Eigen::VectorXd& X, double p) { return modal_orbit_json(problem, system, X, p); },
                  "multipliers");
  }
  if (full) {
    // Start: without stress-free l >= 3 content the ellipsoidal closed form (exact); with it, the scene
    // relaxed by the full model for --relax-T (an attracting state; Newton from the ellipsoid may land
    // on an unstable member of the unfolded pitchfork), then Newton at the scene's parameter.
    const FullEquilibriumProblem problem(sf.scene, q);
    const double p0 = problem.start_parameter();
    const bool rest_high = std::any_of(sf.scene.rest_delta_l.begin(), sf.scene.rest_delta_l.end(),
                                       [](const auto& kv) { return kv.second > 0; });
    const NewtonResult start = solve_fixed_parameter(
        problem, rest_high ? problem.relaxed_state(o.relax_T) : problem.ellipsoidal_state(p0), p0);
    if (!start.converged) {
      std::cerr << "rbcstab: no full-model equilibrium near the " << (rest_high ? "relaxed state" : "ellipsoid")
                << " (Newton residual " << start.residual_norm << " after " << start.iterations
                << " iterations); try a longer --relax-T\n";
      return kRunFailed;
    }
    const Branch b = continue_branch(problem, start.x, p0, o.engine);
    if (!o.curve.empty()) return run_curve(o, sf, b);
    std::optional<BranchSwitchResult> sw;
    if (o.switch_at_bp) sw = switch_at_first_bp(problem, b, o.engine);
    const BranchSwitchResult* swp = sw ? &*sw : nullptr;
    return report(o, sf, b, modal_csv(b, swp, o.parameter, problem),
                  [&](const Eigen::VectorXd& x, double p) { return modal_json(problem, x, p); }, "eigenvalues", swp);
  }
  if (modal) {
    // Start on the ellipsoidal branch (a_l = 0) at its closed form; Newton polishes it.
    const ModalEquilibriumProblem problem(sf.scene, q);
    const double p0 = problem.start_parameter();
    const Branch b = continue_branch(problem, problem.ellipsoidal_state(p0), p0, o.engine);
    if (!o.curve.empty()) return run_curve(o, sf, b);
    std::optional<BranchSwitchResult> sw;
    if (o.switch_at_bp) sw = switch_at_first_bp(problem, b, o.engine);
    const BranchSwitchResult* swp = sw ? &*sw : nullptr;
    return report(o, sf, b, modal_csv(b, swp, o.parameter, problem),
                  [&](const Eigen::VectorXd& x, double p) { return modal_json(problem, x, p); }, "eigenvalues", swp);
  }
  if (!orbit) {
    const ReducedEquilibriumProblem problem(sf.scene, q);
    const Branch b = continue_branch(problem, problem.relaxed_state(o.relax_T), problem.start_parameter(), o.engine);
    if (!o.curve.empty()) return run_curve(o, sf, b);
    std::optional<BranchSwitchResult> sw;
    if (o.switch_at_bp) sw = switch_at_first_bp(problem, b, o.engine);
    return report(o, sf, b, branch_csv(b, o.parameter), [](const Eigen::VectorXd& y, double) { return polar_json(y); },
                  "eigenvalues", sw ? &*sw : nullptr);
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
  if (!o.curve.empty()) return run_curve(o, sf, b);
  return report(o, sf, b, orbit_csv(b, o.parameter, problem),
                [&](const Eigen::VectorXd& X, double p) { return orbit_json(problem, X, p); }, "multipliers");
}
}  // namespace

static Runner add_continue(CLI::App& app) {
  auto o = std::make_shared<ContinueOptions>();
  o->scene.add_to(app);
  app.add_option("--kind", o->kind,
                 "what to continue: equilibrium (reduced system, out-of-plane rest shape), modal (modal-model "
                 "equilibria with every Delta_l, out-of-plane rest shape: the ellipsoidal branch and its BPs where "
                 "Upsilon_l(sigma) = 0) or orbit (periodic orbits "
                 "of the forced in-plane reduced system: swinging/tumbling, Floquet multipliers, LPC/PD/NS, UZ "
                 "swing_tumble) or modal-orbit (periodic orbits of the forced modal model relaxed from the scene, "
                 "e.g. the in-plane post-instability state, with every Delta_l) or full (full-model equilibria, "
                 "L <= 16, for stress-free shapes with l >= 3 content, initial.rest_delta_l in a scene file; "
                 "beta = 0 or C = inf)")
      ->capture_default_str();
  app.add_option("--segments", o->orbit.segments, "orbit: number of multiple-shooting segments")->capture_default_str();
  app.add_flag("--switch-at-bp", o->switch_at_bp,
               "equilibrium, modal, full: also continue the branch that bifurcates at the first BP (modal: the "
               "post-instability state); JSON key switched_branch, CSV rows with branch = switched");
  app.add_option("--parameter", o->parameter,
                 "free parameter: lambda, Delta, Delta0, B, C, Lambda, S or beta (the rest shape's orientation, "
                 "[0, pi]; equilibria exist only at beta = 0 unless Delta0 = 0 or C = inf)")
      ->capture_default_str();
  app.add_option("--min", o->p_min,
                 "lower bound of the free parameter (the branch ends there exactly; default: none, 0 for lambda and beta)");
  app.add_option("--max", o->p_max, "upper bound of the free parameter (the branch ends there exactly; default: none, pi for beta)");
  app.add_option("--direction", o->direction, "forward (parameter increasing), backward or both")
      ->check(CLI::IsMember({"forward", "backward", "both"}))
      ->capture_default_str();
  app.add_option("--step", o->engine.initial_step, "first arclength step, > 0")->check(positive())->capture_default_str();
  app.add_option("--max-step", o->engine.max_step, "largest arclength step, > 0")->check(positive())->capture_default_str();
  app.add_option("--max-points", o->engine.max_points, "points per direction, integer >= 2")->check(CLI::Range(2, 100000000))->capture_default_str();
  app.add_option("--relax-T", o->relax_T,
                 "relaxation time that gives the start state from the scene's shape, > 0 (orbits: rounded up to a "
                 "multiple of 2 pi)")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--curve", o->curve,
                 "continue the curve of a special point of the one-parameter branch in (--parameter, --parameter2): "
                 "LP, BP, HB (equilibrium, modal, full; modal BP: the symmetry-breaking curve Upsilon_l(sigma) = 0) or LPC, "
                 "PD, NS, BP (orbit, modal-orbit; BP: the generic BP system over the shooting problem, e.g. the "
                 "modal orbit's symmetry-breaking BPs); default: none (one-parameter run)")
      ->check(CLI::IsMember({"LP", "BP", "HB", "LPC", "PD", "NS"}));
  app.add_option("--parameter2", o->parameter2,
                 "--curve: second free parameter (lambda, Delta, Delta0, B, C, Lambda, S or beta; independent of "
                 "--parameter: not Lambda with Delta or lambda, not S with C or Delta0)");
  app.add_option("--min2", o->p2_min, "--curve: lower bound of --parameter2 (the curve ends there exactly; default: none)");
  app.add_option("--max2", o->p2_max, "--curve: upper bound of --parameter2 (the curve ends there exactly; default: none)");
  app.add_option("--point", o->point, "--curve: start from the K-th located special point of that type, integer >= 1")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  app.add_flag("--json", o->json, "print one JSON object (branch, special_points) on stdout");
  app.add_option("--csv", o->csv, "write the branch as CSV to this file");
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegister{"continue", "Continue an equilibrium or periodic-orbit branch in one parameter (LP/BP/HB, LPC/PD/NS), or a special point's curve in two",
                                add_continue, 40};
}  // namespace

}  // namespace rbcstab::cli
