#pragma once
// The parameter-plane flags shared by `diagram` and `trace`, registered and read one way for both (the plane
// itself: the library's plane_spec, sweep/diagram_file.hpp).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "checks.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_file.hpp"

namespace rbcstab::cli {

struct PlaneFlags {
  std::vector<std::string> axes, x_range, y_range, counts;  // comma lists (checks.hpp list_items, counts_of)
  std::string classifier;
  double alpha_fixed = -1;

  // --axes, --x-range, --y-range, for a grid (diagram) --counts and --classifier, then --alpha-fixed.
  void add_to(CLI::App& app, bool grid) {
    std::string names;
    for (const std::string& n : axis_names()) names += (names.empty() ? "" : " ") + n;
    const DiagramSpec d;
    app.add_option("--axes", axes, "two axes x,y from " + names + " (default: the scene's [diagram] or " +
                                       to_string(d.x.axis) + "," + to_string(d.y.axis) + ")")
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
