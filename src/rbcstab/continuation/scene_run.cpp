// A run as a front end asks for it: a fresh run from a scene file, a curve by names, and how a run ended.
#include "rbcstab/continuation/scene_run.hpp"

#include <cmath>
#include <utility>
#include <variant>

#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

bool ended_normally(ContinuationStatus status) {
  return status == ContinuationStatus::completed || status == ContinuationStatus::outside_domain;
}

RunOutcome outcome(const SceneBranch& r) {
  RunOutcome o;
  if (!r.start.converged || r.start.refused) return {false, "", r.start.message};
  o.note = r.start.message;
  const std::string level = unmoved_level_note(r.spec.parameter, model_level(r.spec.kind));
  if (!level.empty()) o.note += (o.note.empty() ? "" : "; ") + level;
  const Branch& b = r.branch.branch;
  if (r.switched && !r.switched->switched)
    o.failure = "branch switching failed: " + r.switched->message;
  else if (!ended_normally(b.status))
    o.failure = "continuation stopped: " + to_string(b.status) + ": " + b.message;
  return o;
}

RunOutcome outcome(const SceneCurve& r) {
  RunOutcome o;
  if (!r.started) return {false, "", r.message};
  const ModelLevel level = model_level(r.one.spec.kind);
  for (ContinuationParameter q : {r.one.spec.parameter, r.spec.parameter2.value_or(r.one.spec.parameter)})
    if (const std::string note = unmoved_level_note(q, level); !note.empty() && o.note.find(note) == std::string::npos)
      o.note += (o.note.empty() ? "" : "; ") + note;
  const Branch& c = r.curve.branch;
  if (!ended_normally(c.status)) o.failure = "curve continuation stopped: " + to_string(c.status) + ": " + c.message;
  return o;
}

RunOutcome outcome(const ContinuationRun& run) {
  return std::visit([](const auto& r) { return outcome(r); }, run);
}

int run_L(const SceneBranch& r) { return r.spec.scene.L; }
int run_L(const SceneCurve& r) { return r.one.spec.scene.L; }
int run_L(const ContinuationRun& run) {
  return std::visit([](const auto& r) { return run_L(r); }, run);
}

CurveSpec curve_spec(const std::string& type, const std::string& parameter2, double p2_min, double p2_max, int point,
                     const std::string& min2_name, const std::string& max2_name) {
  CurveSpec c;
  c.type = curve_kind_from_string(type);
  if (!parameter2.empty()) {
    try {
      c.parameter2 = continuation_parameter_from_string(parameter2);
    } catch (const InvalidArgument& e) {
      // The table's message ("parameter = 'x' is not ...: must be one of ...") names the second parameter.
      const std::string message = e.what();
      throw InvalidArgument("parameter2", "parameter2" + message.substr(e.parameter().size()));
    }
  }
  if (c.parameter2) require_bounds_in_domain(*c.parameter2, p2_min, p2_max, min2_name, max2_name);
  require(!std::isnan(p2_min), min2_name, p2_min, "a number (-inf: no bound)");
  require(!std::isnan(p2_max), max2_name, p2_max, "a number (inf: no bound)");
  c.p2_min = p2_min;
  c.p2_max = p2_max;
  c.point = point;
  return c;
}

SceneRun scene_run(SceneFile file, BranchSpec spec, std::optional<CurveSpec> curve, const std::string& min_name,
                   const std::string& max_name) {
  apply_truncation(file, truncation_use(spec.kind));
  if (file.origin("initial.beta") == Origin::default_value) file.scene.beta = default_beta(spec.kind);
  spec.scene = file.scene;
  require_bounds_in_domain(spec.parameter, spec.engine.p_min, spec.engine.p_max, min_name, max_name);
  require(!std::isnan(spec.engine.p_min), min_name, spec.engine.p_min, "a number (-inf: no bound)");
  require(!std::isnan(spec.engine.p_max), max_name, spec.engine.p_max, "a number (inf: no bound)");
  return {std::move(spec), std::move(curve), file.L_reason};
}

ContinuationRun continue_run(const SceneRun& run) {
  if (run.curve) return continue_curve(run.spec, *run.curve);
  return continue_scene(run.spec);
}

std::string saved_run_L_reason(const ContinuationRun& run) {
  return "L = " + std::to_string(run_L(run)) + ": the branch file's scene (--restart)";
}

}  // namespace rbcstab
