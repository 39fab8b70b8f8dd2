#pragma once
// Convergence shown, not assumed: every number a scene report states about its run, re-measured by running the
// scene again with one refinement at a time (L -> L + 2, T -> 2T, delta -> delta/10, rtol -> rtol/100), and
// flagged where a refinement moves it by more than its tolerance (the rule: tolerance(), docs/report.md).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

enum class Refinement { L_plus_2, T_twice, delta_tenth, rtol_hundredth };
template <>
struct EnumTable<Refinement> {
  static constexpr EnumName<Refinement> entries[] = {{Refinement::L_plus_2, "L+2"},
                                                     {Refinement::T_twice, "2T"},
                                                     {Refinement::delta_tenth, "delta/10"},
                                                     {Refinement::rtol_hundredth, "rtol/100"}};
};

struct ConvergenceOptions {
  bool enabled = true;  // rbcstab report --no-convergence: false (the page then says it was not checked)
  std::vector<Refinement> refinements{Refinement::L_plus_2, Refinement::T_twice, Refinement::delta_tenth,
                                      Refinement::rtol_hundredth};
  void validate() const;  // throws InvalidArgument("refinements", ...): empty or repeated
};

// The scene and run options with one refinement applied. L + 2 beyond kMaxL throws InvalidArgument("L", ...).
struct RefinedRun {
  Scene scene;
  SimulationOptions options;
};
RefinedRun refine(const Scene& scene, const SimulationOptions& options, Refinement refinement);

// How a reported quantity is compared: a discrete one (l_Delta, oscillating) must not change at all; a real one
// may move by sqrt(rtol) times its scale: max(1, |value|) for sigma, r and Psi, max(|value|, Delta_total(0)) for
// an excess area (a mode's area below that fraction of the cell's total is below what the report claims).
enum class QuantityKind { discrete, order_one, excess_area };
double convergence_tolerance(QuantityKind kind, double value, double rtol, double Delta_total);

struct RefinementRun {
  Refinement refinement = Refinement::L_plus_2;
  std::string change;  // "L = 10 -> 12"
  bool ran = true;     // false: the refined run could not be set up (L + 2 beyond kMaxL, ...); reason says why
  IntegrationStatus status = IntegrationStatus::success;
  std::string reason;
  double seconds = 0;
};

struct ConvergenceRow {
  std::string quantity;         // the summary's key ("sigma_final", "Delta_3(T)")
  double value = 0;             // the run's value
  std::vector<double> changes;  // refined - value, one per refinement of the check (NaN: that run failed)
  double tolerance = 0;
  std::vector<Refinement> moved_by;   // refinements whose |change| > tolerance
  std::vector<Refinement> failed_by;  // refinements whose run stopped early: convergence not shown
  bool flagged() const { return !moved_by.empty() || !failed_by.empty(); }
};

struct ConvergenceCheck {
  double rtol = 0;         // the run's, behind every tolerance
  double Delta_total = 0;  // sum_l Delta_l(0), the excess areas' scale
  std::vector<RefinementRun> runs;
  std::vector<ConvergenceRow> rows;
  double seconds = 0;  // the extra runs' wall time
  std::size_t flagged() const;
};

// Runs each refinement of the scene (validated; the run `base` is simulate(scene, options)) and compares the
// quantities the report states: l_Delta, l_Delta_final, oscillating, sigma(T), sigma tail mean, r(T), Psi(T), and
// Delta_l(T), Delta_l tail mean for l = 2..L. A base run that stopped early throws InvalidArgument("run", ...).
ConvergenceCheck convergence_check(const Scene& scene, const SimulationOptions& options, const SimulationResult& base,
                                   const ConvergenceOptions& check = {});

// A scene report's check: its run, and its reduced companion under the refinements that apply to it (2T and
// rtol/100: it has no l >= 3 modes and no seeds). Each is empty when not asked for or when its run stopped early.
struct ReportConvergence {
  std::optional<ConvergenceCheck> run, reduced;
  std::size_t flagged() const;
};
// reduced_scene/reduced: the companion and its run, or nullptr when there is none.
ReportConvergence report_convergence(const Scene& scene, const SimulationOptions& options, const SimulationResult& run,
                                     const Scene* reduced_scene, const SimulationResult* reduced,
                                     const ConvergenceOptions& asked);

nlohmann::json to_json(const ConvergenceCheck& c);
// A report's "convergence" entry: the run's check (its companion's under "reduced_companion"), or {"checked": false,
// "reason"} (not asked for, or the run stopped before T).
nlohmann::json convergence_json(const ReportConvergence& c, const ConvergenceOptions& asked);
// The rule behind the tolerances, as docs/report.md and the page state it.
extern const char* const kConvergenceRule;

}  // namespace rbcstab
