#include "rbcstab/continuation/continuation_parameter.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

const std::vector<std::string>& continuation_parameter_names() {
  static const std::vector<std::string> names = parameter_names(ParameterUse::continuation);
  return names;
}

std::string continuation_parameter_list() {
  std::string names;
  for (const auto& n : continuation_parameter_names()) names += (names.empty() ? "" : ", ") + n;
  return names;
}

ContinuationParameter continuation_parameter_from_string(const std::string& name) {
  return parameter_from_string(name, ParameterUse::continuation);
}

namespace {
// Throws unless q is a function of the material Parameters alone (beta lives in the Scene).
void require_material(ContinuationParameter q) {
  if (!is_material(q))
    throw InvalidArgument(
        "parameter",
        "parameter = " + to_string(q) + " is a scene parameter, not a material one (internal: use the Scene overload)");
}

Scene scene_of(const Parameters& p) {
  Scene s;
  s.parameters = p;
  return s;
}
}  // namespace

double get_parameter(const Parameters& p, ContinuationParameter q) {
  require_material(q);
  return get_parameter(scene_of(p), q);
}

Parameters with_parameter(Parameters p, ContinuationParameter q, double value) {
  require_material(q);
  return with_parameter(scene_of(p), q, value).parameters;
}

Scene with_parameter(Scene s, ContinuationParameter q, double value) {
  require_in(q, continuation_domain(q, s.parameters), value);
  set_parameter(s, q, value);
  s.parameters.validate();
  return s;
}

void require_independent(ContinuationParameter p1, ContinuationParameter p2, const std::string& name) {
  // Lambda is moved through Delta and depends on lambda; S is moved through C and depends on Delta0:
  // setting one of a pair that shares an input would undo the other.
  if (independent(p1, p2)) return;
  std::string stored, composite;
  for (const ParameterRow& r : parameter_table()) {
    if (!r.continuation) continue;
    std::string& list = r.table ? stored : composite;
    list += (list.empty() ? "" : ", ") + std::string(r.name);
  }
  throw InvalidArgument(name, name + " = " + to_string(p2) + " is not independent of the first parameter " +
                                  to_string(p1) + ": choose two of " + stored + ", or a composite (" + composite +
                                  ") with a parameter it does not depend on");
}

InitialState oriented_initial_state(Scene s) {
  for (const auto& [l, d] : s.rest_delta_l)
    if (d > 0)
      throw InvalidArgument("rest_delta_l", "rest_delta_l[" + std::to_string(l) + "] = " + std::to_string(d) +
                                                ": the stress-free shape has l >= 3 content, which only the full model "
                                                "holds; the reduced and modal problems would drop it (use the full "
                                                "level: FullEquilibriumProblem, rbcstab continue --kind full)");
  s.parameters.Delta0 = s.parameters.Delta;
  return initial_state(s);
}

std::string unmoved_level_note(ContinuationParameter q, ModelLevel level) {
  const ParameterRow& row = parameter_row(q);
  if (row.levels & level_bit(level)) return "";
  std::string moved;
  for (ModelLevel m : {ModelLevel::reduced, ModelLevel::modal, ModelLevel::full})
    if (row.levels & level_bit(m)) moved += (moved.empty() ? "" : " and ") + to_string(m);
  return std::string(row.name) + " does not enter the " + to_string(level) +
         " model: every point in it is the same state (" + row.name + " moves the " + moved + " models)";
}

void rhs_parameter_derivative(const Scene& scene, ContinuationParameter q, double t, std::span<const double> y,
                              std::span<double> dfdq) {
  if (scene.model == ModelLevel::automatic)
    throw std::logic_error("rhs_parameter_derivative: the scene's level must be concrete (the system's own)");
  // A step relative to q (C, B and the others act as scales: a step of 1 + |q| would be 25x too coarse at C = 0.04).
  const double p = get_parameter(scene, q);
  const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * (p != 0 ? std::abs(p) : 1.0);
  const std::size_t n = y.size();
  // F at q = v on the same state layout, or false where v leaves q's domain.
  auto rhs_at = [&](double v, std::vector<double>& f) {
    Scene s;
    try {
      s = with_parameter(scene, q, v);
    } catch (const InvalidArgument&) {
      return false;
    }
    const SceneSystem built = make_scene_system(s);
    if (built.system->dimension() != n)
      throw InvalidArgument("y", "y has " + std::to_string(n) + " components: the system at " + to_string(q) + " = " +
                                     std::to_string(v) + " has " + std::to_string(built.system->dimension()));
    f.assign(n, 0.0);
    built.system->rhs(t, y, f);
    return true;
  };
  if (dfdq.size() != n) throw std::logic_error("rhs_parameter_derivative: dfdq and y differ in size");
  std::vector<double> plus, minus, f0, f2;
  const bool up = rhs_at(p + h, plus), down = rhs_at(p - h, minus);
  if (up && down) {
    for (std::size_t i = 0; i < n; ++i) dfdq[i] = (plus[i] - minus[i]) / (2 * h);
    return;
  }
  const double s = up ? 1.0 : -1.0;  // one-sided, into the domain: (-3 f0 + 4 f1 - f2) / (2 h s)
  if (!(up || down) || !rhs_at(p, f0) || !rhs_at(p + 2 * s * h, f2))
    throw InvalidArgument(to_string(q), to_string(q) + " = " + std::to_string(p) +
                                            " leaves room for no difference on either side within its domain");
  const std::vector<double>& f1 = up ? plus : minus;
  for (std::size_t i = 0; i < n; ++i) dfdq[i] = (-3 * f0[i] + 4 * f1[i] - f2[i]) / (2 * s * h);
}

}  // namespace rbcstab
