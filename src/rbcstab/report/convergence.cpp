#include "rbcstab/report/convergence.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/io/json.hpp"

namespace rbcstab {

const char* const kConvergenceRule =
    "tolerance = sqrt(rtol) x scale, rtol the run's relative tolerance: a reported number is claimed to about half "
    "the digits the integrator controls. Scale: max(1, |value|) for sigma, r and Psi; max(|value|, Delta_total(0)) "
    "for an excess area. l_Delta, l_Delta_final and oscillating must not change at all. A number is flagged when a "
    "refinement moves it by more than its tolerance, or when a refined run could not finish (convergence not shown).";

namespace {
// rtol / 100, kept at the integrator's floor (IntegratorOptions::validate: rtol >= 1e-15).
constexpr double kConvergenceRtolFloor = 1e-15;

struct ReportedNumber {
  std::string name;
  QuantityKind kind;
  std::function<double(const SimulationResult&)> of;
};

std::vector<ReportedNumber> reported_quantities(int L) {
  std::vector<ReportedNumber> q{
      {"l_Delta", QuantityKind::discrete, [](const SimulationResult& r) { return double(r.l_Delta); }},
      {"l_Delta_final", QuantityKind::discrete, [](const SimulationResult& r) { return double(r.l_Delta_final); }},
      {"oscillating", QuantityKind::discrete, [](const SimulationResult& r) { return r.oscillating ? 1.0 : 0.0; }},
      {"sigma_final", QuantityKind::order_one, [](const SimulationResult& r) { return r.sigma_final; }},
      {"sigma_tail_mean", QuantityKind::order_one, [](const SimulationResult& r) { return r.sigma_tail_mean; }},
      {"r_final", QuantityKind::order_one, [](const SimulationResult& r) { return r.r_final; }},
      {"Psi_final", QuantityKind::order_one, [](const SimulationResult& r) { return r.Psi_final; }}};
  for (int l = 2; l <= L; ++l) {
    const std::size_t k = std::size_t(l - 2);
    q.push_back({"excess_area_final[" + std::to_string(l) + "]", QuantityKind::excess_area,
                 [k](const SimulationResult& r) { return r.Delta_final.at(k); }});
    q.push_back({"excess_area_tail_mean[" + std::to_string(l) + "]", QuantityKind::excess_area,
                 [k](const SimulationResult& r) { return r.Delta_tail_mean.at(k); }});
  }
  return q;
}

std::string refinement_change_text(const Scene& from, const SimulationOptions& o, const RefinedRun& to, Refinement r) {
  TextStream s;
  switch (r) {
    case Refinement::L_plus_2:
      s << "L = " << from.L << " -> " << to.scene.L;
      break;
    case Refinement::T_twice:
      s << "T = " << from.T << " -> " << to.scene.T;
      break;
    case Refinement::delta_tenth:
      s << "delta = " << from.delta << " -> " << to.scene.delta << (from.delta_l.empty() ? "" : " (and each delta_l)");
      break;
    case Refinement::rtol_hundredth:
      s << "rtol = " << o.integrator.rtol << " -> " << to.options.integrator.rtol
        << (to.options.integrator.rtol == kConvergenceRtolFloor ? " (the integrator's floor)" : "");
      break;
  }
  return s.str();
}
}  // namespace

void ConvergenceOptions::validate() const {
  if (refinements.empty()) throw InvalidArgument("refinements", "refinements: at least one refinement is needed");
  for (std::size_t i = 0; i < refinements.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (refinements[i] == refinements[j])
        throw InvalidArgument("refinements", "refinements: '" + to_string(refinements[i]) + "' is listed twice");
}

RefinedRun refine(const Scene& scene, const SimulationOptions& options, Refinement refinement) {
  RefinedRun out{scene, options};
  switch (refinement) {
    case Refinement::L_plus_2:
      require_L(scene.L + 2, kMinL, kMaxL, "the refinement L + 2 of the convergence check");
      out.scene.L = scene.L + 2;
      break;
    case Refinement::T_twice:
      out.scene.T = 2 * scene.T;
      break;
    case Refinement::delta_tenth:
      out.scene.delta = scene.delta / 10;
      for (auto& [l, d] : out.scene.delta_l) d /= 10;
      break;
    case Refinement::rtol_hundredth:
      out.options.integrator.rtol = std::max(kConvergenceRtolFloor, options.integrator.rtol / 100);
      break;
  }
  return out;
}

double convergence_tolerance(QuantityKind kind, double value, double rtol, double Delta_total) {
  switch (kind) {
    case QuantityKind::discrete:
      return 0;
    case QuantityKind::order_one:
      return std::sqrt(rtol) * std::max(1.0, std::abs(value));
    case QuantityKind::excess_area:
      return std::sqrt(rtol) * std::max(std::abs(value), Delta_total);
  }
  return 0;
}

std::size_t ConvergenceCheck::flagged() const {
  return std::size_t(std::count_if(rows.begin(), rows.end(), [](const ConvergenceRow& r) { return r.flagged(); }));
}

ConvergenceCheck convergence_check(const Scene& scene, const SimulationOptions& options, const SimulationResult& base,
                                   const ConvergenceOptions& check) {
  check.validate();
  scene.validate();
  options.validate();
  if (base.status != IntegrationStatus::success)
    throw InvalidArgument("run", "run: the convergence check needs a run that reached T (status " +
                                     to_string(base.status) + " at t = " + format_value(base.t_reached) + ")");
  const auto start = std::chrono::steady_clock::now();
  ConvergenceCheck c;
  c.rtol = options.integrator.rtol;
  c.Delta_total = base.Delta_total_initial;
  SimulationOptions quiet = options;
  quiet.trajectory_text = false;
  std::vector<std::optional<SimulationResult>> refined;
  for (Refinement r : check.refinements) {
    RefinementRun run;
    run.refinement = r;
    try {
      const RefinedRun spec = refine(scene, quiet, r);
      run.change = refinement_change_text(scene, options, spec, r);
      SimulationResult res = simulate(spec.scene, spec.options);
      run.status = res.status;
      run.reason = res.reason;
      run.seconds = res.seconds;
      if (res.status == IntegrationStatus::success)
        refined.emplace_back(std::move(res));
      else
        refined.emplace_back();
    } catch (const InvalidArgument& e) {  // e.g. L + 2 beyond kMaxL: not run, so not shown
      run.ran = false;
      run.reason = e.what();
      refined.emplace_back();
    }
    c.runs.push_back(run);
  }
  for (const ReportedNumber& q : reported_quantities(scene.L)) {
    ConvergenceRow row;
    row.quantity = q.name;
    row.value = q.of(base);
    row.tolerance = convergence_tolerance(q.kind, row.value, c.rtol, c.Delta_total);
    for (std::size_t k = 0; k < refined.size(); ++k) {
      const Refinement r = check.refinements[k];
      if (!refined[k]) {
        row.changes.push_back(std::numeric_limits<double>::quiet_NaN());
        row.failed_by.push_back(r);
        continue;
      }
      const double d = q.of(*refined[k]) - row.value;
      row.changes.push_back(d);
      if (!(std::abs(d) <= row.tolerance)) row.moved_by.push_back(r);
    }
    c.rows.push_back(row);
  }
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

nlohmann::json to_json(const ConvergenceCheck& c) {
  auto names = [](const std::vector<Refinement>& v) {
    nlohmann::json a = nlohmann::json::array();
    for (Refinement r : v) a.push_back(to_string(r));
    return a;
  };
  nlohmann::json runs = nlohmann::json::array();
  for (const RefinementRun& r : c.runs)
    runs.push_back({{"refinement", to_string(r.refinement)},
                    {"change", r.change},
                    {"status", r.ran ? to_string(r.status) : "not run"},
                    {"reason", r.reason},
                    {"seconds", r.seconds}});
  nlohmann::json rows = nlohmann::json::array();
  for (const ConvergenceRow& row : c.rows) {
    nlohmann::json changes = nlohmann::json::object();
    for (std::size_t k = 0; k < c.runs.size(); ++k)
      changes[to_string(c.runs[k].refinement)] = number_or_null(row.changes[k]);
    rows.push_back({{"quantity", row.quantity},
                    {"value", number_or_null(row.value)},
                    {"changes", changes},
                    {"tolerance", number_or_null(row.tolerance)},
                    {"flagged", row.flagged()},
                    {"moved_by", names(row.moved_by)},
                    {"not_shown_by", names(row.failed_by)}});
  }
  return {{"checked", true},        {"rule", kConvergenceRule},
          {"rtol", c.rtol},         {"Delta_total", number_or_null(c.Delta_total)},
          {"runs", runs},           {"rows", rows},
          {"flagged", c.flagged()}, {"seconds", c.seconds}};
}

std::size_t ReportConvergence::flagged() const {
  return (run ? run->flagged() : 0) + (reduced ? reduced->flagged() : 0);
}

ReportConvergence report_convergence(const Scene& scene, const SimulationOptions& options, const SimulationResult& run,
                                     const Scene* reduced_scene, const SimulationResult* reduced,
                                     const ConvergenceOptions& asked) {
  ReportConvergence out;
  if (!asked.enabled || run.status != IntegrationStatus::success) return out;
  out.run = convergence_check(scene, options, run, asked);
  ConvergenceOptions companion = asked;
  std::erase_if(companion.refinements,
                [](Refinement r) { return r == Refinement::L_plus_2 || r == Refinement::delta_tenth; });
  if (reduced_scene && reduced && reduced->status == IntegrationStatus::success && !companion.refinements.empty())
    out.reduced = convergence_check(*reduced_scene, options, *reduced, companion);
  return out;
}

nlohmann::json convergence_json(const ReportConvergence& c, const ConvergenceOptions& asked) {
  if (c.run) {
    nlohmann::json j = to_json(*c.run);
    if (c.reduced) j["reduced_companion"] = to_json(*c.reduced);
    return j;
  }
  return {{"checked", false},
          {"reason", asked.enabled ? "the run stopped before T: there is no result to refine"
                                   : "not asked for (rbcstab report --no-convergence)"}};
}

}  // namespace rbcstab
