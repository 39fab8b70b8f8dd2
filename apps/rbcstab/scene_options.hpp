#pragma once
// Scene flags shared by every subcommand that runs a scene: --scene FILE plus one flag per scene key that has
// one (io's scene_flags(): the parameter table's stored parameters, L, T, dt, model, stepper, rtol, atol and
// the per-mode perturbations), the [physical] keys' unit flags (--shear-rate, ...), and --full-horizon, which sets
// the scene key run.full_horizon. The parameter-plane flags of `diagram` and `trace` (PlaneFlags), registered and
// read one way for both (the plane itself: the library's plane_spec, sweep/diagram_table.hpp).
#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "checks.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/verdict/certified_run.hpp"
#include "rbcstab/verdict/shear_rate.hpp"

namespace rbcstab::cli {

// --shear-rate-range LO,HI (summary, report): the shear-rate threshold search of a physical scene
// (shear_rate_search, verdict/shear_rate.hpp).
void add_shear_rate_range(CLI::App& app, std::string& text);

struct SceneOptions {
  std::string scene_path;

  void add_to(CLI::App& app);  // the options bind to this object: it must not move afterwards
  // The default scene (paper Fig. 3, out of plane), then the scene file, then the flags; SceneFile::origins
  // records which. L as they give it.
  SceneFile read() const;
  // read() without its final check (validate_scene_file), for a library entry that checks the file itself.
  SceneFile read_unchecked() const;
  // The file read, then the truncation policy for this use (apply_scene_truncation, which checks it once: a
  // simulation's automatic L as simulate_scene decides it): scene.L and L_reason.
  SceneFile resolve(TruncationUse use) const;
  // The scene flags given on the command line, by name (e.g. "--lambda").
  std::vector<std::string> given_flags() const;

 private:
  struct Flag {
    const SceneKey* key = nullptr;
    CLI::Option* option = nullptr;
  };
  std::vector<Flag> flags_;
  // The values CLI11 parses into, by scene key path (std::map: the references stay valid).
  std::map<std::string, double> numbers_;
  std::map<std::string, long long> integers_;
  std::map<std::string, std::string> names_;
  std::map<std::string, std::vector<std::string>> modes_;
  std::map<std::string, bool> booleans_;
  bool full_horizon_ = false;
  CLI::Option* full_horizon_option_ = nullptr;
};

struct PlaneFlags {
  std::vector<std::string> axes, x_range, y_range, counts;  // comma lists (checks.hpp list_items, counts_of)
  std::string classifier;
  double alpha_fixed = -1;

  // --axes, --x-range, --y-range, for a grid (diagram) --counts and --classifier, then --alpha-fixed.
  void add_to(CLI::App& app, bool grid) {
    std::string names;
    for (const std::string& n : axis_names()) names += (names.empty() ? "" : " ") + n;
    const DiagramSpec d;
    app.add_option("--axes", axes,
                   "two axes x,y from " + names + " (default: the scene's [diagram] or " + to_string(d.x.axis) + "," +
                       to_string(d.y.axis) + ")")
        ->check(each_item({}, "two axis names x,y"));
    auto range = [&](const std::string& flag, std::vector<std::string>& values, const std::string& axis,
                     const std::string& fallback) {
      const std::string what = "min,max of the " + axis + " axis";
      app.add_option(flag, values, what + " (inclusive, finite; default: the scene's [diagram] or " + fallback + ")")
          ->check(each_item({number_text(what + ", finite")}, "two numbers min,max"))
          ->expected(1, 2);
    };
    range("--x-range", x_range, "x", "-1,6");
    range("--y-range", y_range, "y", "-5.5,2");
    if (grid) {
      add_counts(app, counts,
                 "grid values nx,ny (or NxM), integers in [1, 1000000] (default: the scene's [diagram] or 64,64)");
      app.add_option("--classifier", classifier,
                     "l_Delta rule: auto (tail mean if oscillating), final (Fig. 4), tail (App. E) (default: the "
                     "scene's [diagram] or auto)")
          ->check(CLI::IsMember(enum_names<Classifier>()));
    }
    app.add_option("--alpha-fixed", alpha_fixed,
                   "hold alpha = B/C at this value over the plane, >= 0 (0: off; Fig. 5; default: the scene's "
                   "[diagram] or off)")
        ->check(non_negative());
  }
  PlaneChoice choice() const {
    PlaneChoice c{list_items(axes), numbers_of(x_range), numbers_of(y_range), counts_of(counts), classifier, {}};
    if (alpha_fixed >= 0) c.alpha_fixed = alpha_fixed;
    return c;
  }
};

}  // namespace rbcstab::cli
