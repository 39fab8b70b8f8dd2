#include "scene_options.hpp"

#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"

namespace rbcstab::cli {

void SceneOptions::add_to(CLI::App& app) {
  const Scene d;
  const IntegratorOptions io;
  app.add_option("--scene", scene_path, "Scene file (TOML, keys in docs/scenes.md); flags below override it")
      ->check(CLI::ExistingFile);
  auto num = [&](const char* name, auto& field, const std::string& help) {
    return app.add_option(name, field, help)->default_val(field)->capture_default_str();
  };
  flags = d;
  o_lambda = num("--lambda", flags.parameters.lambda, "viscosity ratio lambda, >= 0");
  o_Delta = num("--Delta", flags.parameters.Delta, "excess area Delta of the current shape, in (0, 4 pi)");
  o_Delta0 = num("--Delta0", flags.parameters.Delta0, "excess area Delta0 of the stress-free shape, in [0, Delta]");
  o_B = num("--B", flags.parameters.B, "bending number B, > 0");
  o_C = num("--C", flags.parameters.C, "capillary number C, > 0 ('inf': vesicle limit)");
  o_beta = num("--beta", flags.beta, "initial rotation beta about y (0: out of plane, pi/2 = 1.5707963267948966: in plane)");
  o_delta = num("--delta", flags.delta, "perturbation Delta_l(0) of every l = 3..L, in [0, Delta]");
  o_delta_l = app.add_option("--delta-l", delta_l, "per-mode perturbation override, l=value (repeatable)");
  o_rest_delta_l = app.add_option("--rest-delta-l", rest_delta_l,
                                  "stress-free l >= 3 content Delta0_l, l=value (repeatable; needs the full level)");
  o_L = num("--L", flags.L,
            "truncation: modes l = 2..L, integer in [2, 100] (simulate, summary, report: without --L or run.L, "
            "the smallest L whose dropped modes gain < 1e-4 Delta)");
  o_T = num("--T", flags.T, "horizon T, in (0, 1e7]");
  o_dt = num("--dt", flags.dt, "output sampling interval, in (0, T]");
  o_model = app.add_option("--model", model, "model level")
                ->check(CLI::IsMember(enum_names<ModelLevel>()))
                ->capture_default_str();
  o_stepper = app.add_option("--stepper", stepper, "time stepper")->check(CLI::IsMember(stepper_names()))->capture_default_str();
  o_rtol = app.add_option("--rtol", rtol, "relative tolerance, in [1e-15, 0.1]")->default_val(io.rtol)->capture_default_str();
  o_atol = app.add_option("--atol", atol, "absolute tolerance, in [0, 1]")->default_val(io.atol)->capture_default_str();
}

namespace {
void parse_mode_values(const std::vector<std::string>& items, const char* flag, std::map<int, double>& out) {
  for (const auto& item : items) {
    const auto eq = item.find('=');
    try {
      if (eq == std::string::npos) throw std::invalid_argument(item);
      std::size_t pos = 0;
      const int l = std::stoi(item.substr(0, eq), &pos);
      const double v = std::stod(item.substr(eq + 1));
      out[l] = v;
    } catch (const std::exception&) {
      throw InvalidArgument(flag, std::string(flag) + " = '" + item + "' must have the form l=value, e.g. 3=1e-3");
    }
  }
}
}  // namespace

SceneFile SceneOptions::resolve() const {
  SceneFile f;
  if (!scene_path.empty()) f = load_scene(scene_path);
  Scene& s = f.scene;
  auto take = [](const CLI::Option* o, auto& dst, const auto& src) {
    if (o && o->count() > 0) dst = src;
  };
  take(o_lambda, s.parameters.lambda, flags.parameters.lambda);
  take(o_Delta, s.parameters.Delta, flags.parameters.Delta);
  take(o_Delta0, s.parameters.Delta0, flags.parameters.Delta0);
  take(o_B, s.parameters.B, flags.parameters.B);
  take(o_C, s.parameters.C, flags.parameters.C);
  take(o_beta, s.beta, flags.beta);
  take(o_delta, s.delta, flags.delta);
  take(o_L, s.L, flags.L);
  take(o_T, s.T, flags.T);
  take(o_dt, s.dt, flags.dt);
  if (o_model && o_model->count() > 0) s.model = model_level_from_string(model);
  if (o_stepper && o_stepper->count() > 0) f.options.integrator.stepper = stepper_from_string(stepper);
  take(o_rtol, f.options.integrator.rtol, rtol);
  take(o_atol, f.options.integrator.atol, atol);
  parse_mode_values(delta_l, "--delta-l", s.delta_l);
  parse_mode_values(rest_delta_l, "--rest-delta-l", s.rest_delta_l);
  s.validate();
  f.options.validate();
  return f;
}

SceneFile SceneOptions::resolve_with_default_L(std::string& L_reason) const {
  SceneFile f = resolve();
  if (o_L && o_L->count() > 0) {
    L_reason = "L = " + std::to_string(f.scene.L) + ": given by --L";
    return f;
  }
  if (!scene_path.empty() && scene_sets_L(read_file(scene_path), scene_path)) {
    L_reason = "L = " + std::to_string(f.scene.L) + ": given by the scene file's run.L";
    return f;
  }
  const TruncationChoice c = choose_truncation(f.scene);
  f.scene.L = c.L;
  L_reason = c.reason;
  f.scene.validate();
  return f;
}

}  // namespace rbcstab::cli
