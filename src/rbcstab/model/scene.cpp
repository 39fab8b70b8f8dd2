#include "rbcstab/model/scene.hpp"

#include <cmath>
#include <cstdio>

#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/full_model.hpp"
#include "rbcstab/model/modal_model.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/reduced_model.hpp"

namespace rbcstab {

void require_L(long long L, int min_L, int max_L, std::string_view why, std::string_view name) {
  std::string range = "an integer in [" + std::to_string(min_L) + ", " + std::to_string(max_L) + "]";
  if (!why.empty()) range += " (" + std::string(why) + ")";
  require(L >= min_L && L <= max_L, name, double(L), range);
}

void Scene::validate() const {
  // The name is a label in outputs (CSV comment lines, JSON, figure titles, scene files): one line of text.
  for (std::size_t k = 0; k < name.size(); ++k) {
    const unsigned char c = static_cast<unsigned char>(name[k]);
    if (c < 0x20 || c == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "U+%04X", c);
      throw InvalidArgument("name", "name holds the control character " + std::string(code) + " at position " +
                                        std::to_string(k) + ": must be one line of printable text");
    }
  }
  parameters.validate();
  if (physical) physical->validate_complete();
  require_L(L);
  validate_table(*this, "initial");
  for (const auto& [l, d] : delta_l) {
    require(l >= 3 && l <= L, "delta_l", l, "a mode l in [3, L] with L = " + std::to_string(L));
    require(std::isfinite(d) && d >= 0 && d <= parameters.Delta, "delta_l." + std::to_string(l), d,
            "in [0, Delta] with Delta = " + format_value(parameters.Delta));
  }
  for (const auto& [l, d] : rest_delta_l) {
    require(l >= 3 && l <= L, "rest_delta_l", l, "a mode l in [3, L] with L = " + std::to_string(L));
    require(std::isfinite(d) && d >= 0 && d <= parameters.Delta0 + parameters.Delta,
            "rest_delta_l." + std::to_string(l), d, "finite, >= 0 and small against Delta");
  }
  require(std::isfinite(T) && T > 0 && T <= 1e7, "T", T, "in (0, 1e7]");
  require(std::isfinite(dt) && dt > 0 && dt <= T, "dt", dt, "in (0, T] with T = " + format_value(T));
  require(T / dt <= 1e7, "dt", dt,
          "at least T/1e7 = " + format_value(T / 1e7) + " (T/dt = " + format_value(T / dt) +
              " output samples: at most 1e7)");
}

double Scene::perturbation(int l) const {
  const auto it = delta_l.find(l);
  return it != delta_l.end() ? it->second : delta;
}

double Scene::rest_perturbation(int l) const {
  const auto it = rest_delta_l.find(l);
  return it != rest_delta_l.end() ? it->second : 0.0;
}

ValidScene validated(const Scene& scene) {
  scene.validate();
  return ValidScene(scene);
}

ValidScene validated_at_L(const ValidScene& valid, Scene& copy, int L) {
  require_L(L);
  for (const auto* modes : {&valid->delta_l, &valid->rest_delta_l})
    for (const auto& [l, d] : *modes)
      require(l <= L, "L", L, "at least " + std::to_string(l) + ": the scene sets the mode l = " + std::to_string(l));
  copy = *valid;
  copy.L = L;
  return ValidScene(copy);
}

InitialState initial_state(const Scene& scene) { return initial_state(validated(scene)); }

InitialState initial_state(const ValidScene& valid) {
  const Scene& scene = *valid;
  const Parameters& p = scene.parameters;
  InitialState s{ModeAmplitudes(scene.L), ModeAmplitudes(scene.L)};
  for (int l = 2; l <= scene.L; ++l) {
    const std::vector<double> D = wigner_column(l, scene.beta);
    // Axisymmetric shapes before rotation: all area of l = 2 in f_{2,0} < 0 (oblate), and the
    // perturbation Delta_l = delta in f_{l,0} > 0 (paper Sec. IV).
    const double f_axial = l == 2 ? -std::sqrt(p.Delta / a_l(2)) : std::sqrt(scene.perturbation(l) / a_l(l));
    const double g_axial = l == 2 ? -std::sqrt(p.Delta0 / a_l(2)) : std::sqrt(scene.rest_perturbation(l) / a_l(l));
    for (int m = -l; m <= l; ++m) {
      s.f.at(l, m) = f_axial * D[m + l];
      s.g.at(l, m) = g_axial * D[m + l];
    }
  }
  return s;
}

namespace {
// Content of m = +-1 relative to the l = 2 area: below 1e-28 it is rounding of beta (e.g. cos(pi/2)).
bool has_m1_content(const ModeAmplitudes& a) {
  const double total = a.excess_area(2);
  return total > 0 && 2 * a_l(2) * 2 * std::norm(a.at(2, 1)) > 1e-28 * total;
}
}  // namespace

LevelChoice choose_level(const Scene& scene, const InitialState& init) {
  bool rest_high = false, cur_high = false;
  for (int l = 3; l <= scene.L; ++l) {
    rest_high = rest_high || init.g.excess_area(l) > 0;
    cur_high = cur_high || init.f.excess_area(l) > 0;
  }
  const bool m1 = has_m1_content(init.f) || has_m1_content(init.g);
  LevelChoice c{ModelLevel::full, true, ""};
  if (scene.model == ModelLevel::automatic) {
    if (rest_high) {
      c = {ModelLevel::full, true, "the stress-free shape has l >= 3 content, which only the full level holds"};
    } else if (!cur_high && !m1) {
      c = {ModelLevel::reduced, true, "only l = 2, m in {0, +-2} hold area: the reduced (r, Psi) system is exact"};
    } else {
      c = {ModelLevel::modal, true, "the stress-free shape is ellipsoidal: the modal reduction is exact"};
    }
    return c;
  }
  c.level = scene.model;
  switch (scene.model) {
    case ModelLevel::full:
      c.reason = "forced (full is exact for every scene)";
      break;
    case ModelLevel::modal:
      if (rest_high)
        throw InvalidArgument("model",
                              "model = modal cannot hold a stress-free shape with l >= 3 content: use full or auto");
      c.reason = "forced (exact: the stress-free shape is ellipsoidal)";
      break;
    case ModelLevel::reduced:
      c.exact = !rest_high && !cur_high && !m1;
      c.reason = c.exact
                     ? "forced (exact for this scene)"
                     : "forced: drops the l >= 3 perturbations and the m = +-1 content, so it approximates this scene";
      break;
    case ModelLevel::automatic:
      break;
  }
  return c;
}

std::unique_ptr<System> make_system(const Parameters& p, const InitialState& init, ModelLevel level) {
  switch (level) {
    case ModelLevel::full:
      return std::make_unique<FullModel>(p, init);
    case ModelLevel::modal:
      return std::make_unique<ModalModel>(p, init);
    case ModelLevel::reduced:
      return std::make_unique<ReducedModel>(p, init);
    case ModelLevel::automatic:
      break;
  }
  throw InvalidArgument("model", "make_system needs a concrete level (full, modal or reduced), not auto");
}

SceneSystem make_scene_system(const Scene& scene) { return make_scene_system(validated(scene)); }

SceneSystem make_scene_system(const ValidScene& valid) {
  const Scene& scene = *valid;
  SceneSystem s{initial_state(valid), {}, nullptr, scene.parameters.warnings()};
  s.level = choose_level(scene, s.init);
  if (!s.level.exact) s.warnings.push_back("model level " + to_string(s.level.level) + " " + s.level.reason);
  s.system = make_system(scene.parameters, s.init, s.level.level);
  return s;
}

Scene reduced_scene(const Scene& s) {
  Scene r = s;
  r.name = s.name + "_reduced";
  r.model = ModelLevel::reduced;
  r.L = 2;
  r.delta_l.clear();
  r.rest_delta_l.clear();
  return r;
}

}  // namespace rbcstab
