// rbcstab trace: the stability boundary in a parameter plane as curves (asymptotic criterion
// mu_l = Upsilon_l(sigma_R^eq) = 0, out-of-plane scenes), one record per curve with its mode, plus the
// corners where the mode changes; CSV and JSON. With --diagram FILE.json (an `rbcstab diagram`
// output of the same plane) it also measures the agreement of the criterion with the simulations.
#include <iostream>
#include <memory>
#include <sstream>

#include "checks.hpp"
#include "commands.hpp"
#include "plane_options.hpp"
#include "exit_codes.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/sweep/diagram_file.hpp"
#include "rbcstab/sweep/diagram_output.hpp"
#include "rbcstab/sweep/point_io.hpp"
#include "rbcstab/sweep/trace.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct TraceCliOptions {
  SceneOptions scene;
  std::vector<std::string> axes;
  std::vector<double> x_range, y_range;
  double alpha_fixed = -1;
  TraceOptions trace;
  std::string out = "trace", diagram;
  bool json = false;
};

int run(const TraceCliOptions& o) {
  const SceneFile sf = o.scene.resolve();
  DiagramSpec spec = plane_spec(o.scene, o.axes, o.x_range, o.y_range, o.alpha_fixed);
  spec.validate();
  const TraceResult t = trace_boundary(sf.scene, spec, o.trace);

  std::ostringstream csv;
  csv << "curve,l," << to_string(spec.x.axis) << ',' << to_string(spec.y.axis) << ",sigma_R,sigma_c,mu\n";
  nlohmann::json curves = nlohmann::json::array();
  for (std::size_t c = 0; c < t.curves.size(); ++c) {
    const TraceCurve& tc = t.curves[c];
    nlohmann::json xs = nlohmann::json::array(), ys = nlohmann::json::array(), mus = nlohmann::json::array();
    for (const TracePoint& p : tc.points) {
      csv << c << ',' << tc.l << ',' << exact(p.x) << ',' << exact(p.y) << ',' << exact(p.sigma_R) << ','
          << exact(p.sigma_c) << ',' << exact(p.mu) << '\n';
      xs.push_back(p.x);
      ys.push_back(p.y);
      mus.push_back(p.mu);
    }
    curves.push_back({{"curve", c}, {"l", tc.l}, {"criterion", tc.criterion}, {"x", xs}, {"y", ys}, {"mu", mus}});
  }
  nlohmann::json corners = nlohmann::json::array();
  for (const auto& k : t.corners) corners.push_back({{"x", k.x}, {"y", k.y}, {"l_from", k.l_from}, {"l_to", k.l_to}});
  nlohmann::json overlays = nlohmann::json::array();
  for (const Overlay& ov : analytic_overlays(sf.scene, spec, o.trace.lines))
    overlays.push_back({{"name", ov.name}, {"x", ov.x}, {"y", ov.y}});
  nlohmann::json doc{{"format", "rbcstab-trace"},
                     {"version", 1},
                     {"scene", to_json(sf.scene)},
                     {"plane", {{"x", to_string(spec.x.axis)}, {"x_range", {spec.x.min, spec.x.max}},
                                {"y", to_string(spec.y.axis)}, {"y_range", {spec.y.min, spec.y.max}},
                                {"alpha", spec.alpha}}},
                     {"options", {{"lines", o.trace.lines}, {"samples", o.trace.samples}, {"bisections", o.trace.bisections}}},
                     {"curves", curves},
                     {"corners", corners},
                     {"analytic_lines", overlays},
                     {"evaluations", t.evaluations},
                     {"seconds", t.seconds}};
  if (!o.diagram.empty()) {
    nlohmann::json dj;
    try {
      dj = nlohmann::json::parse(read_file(o.diagram));
    } catch (const nlohmann::json::exception& e) {
      throw InvalidArgument("--diagram", "'" + o.diagram + "' is not JSON: " + e.what());
    }
    const DiagramSpec ds = spec_from_json(dj);
    if (ds.x.axis != spec.x.axis || ds.y.axis != spec.y.axis || ds.alpha != spec.alpha)
      throw InvalidArgument("--diagram", "the diagram's plane differs from the traced plane");
    const SceneFile dsf = parse_scene(dj.at("scene_toml").get<std::string>(), o.diagram);
    doc["agreement"] = agreement_json(dsf.scene, ds, points_from_json(dj, ds));
  }
  try {
    write_file_atomic(o.out + ".csv", csv.str());
    write_file_atomic(o.out + ".json", doc.dump(1) + "\n");
  } catch (const std::runtime_error& e) {
    std::cerr << "rbcstab: error: " << e.what() << "\n";
    return kOutputError;
  }
  std::cerr << "rbcstab: traced " << t.curves.size() << " curve pieces, " << t.corners.size() << " corners, "
            << t.evaluations << " criterion evaluations in " << t.seconds << " s; wrote " << o.out << ".csv and "
            << o.out << ".json\n";
  if (o.json) {
    nlohmann::json j{{"csv", o.out + ".csv"},          {"json", o.out + ".json"},
                     {"pieces", t.curves.size()},       {"corners", corners},
                     {"evaluations", t.evaluations},    {"seconds", t.seconds},
                     {"analytic_lines", overlays.size()}};
    if (doc.contains("agreement")) j["agreement"] = doc["agreement"];
    std::cout << j.dump(2) << "\n";
  }
  if (doc.contains("agreement"))
    std::cerr << "rbcstab: agreement with the simulations: verdict " << doc["agreement"]["verdict_fraction"]
              << ", mode " << doc["agreement"]["mode_fraction"] << ", disagreements beyond one grid step "
              << doc["agreement"]["beyond_one_grid_step"] << "\n";
  return kOk;
}
}  // namespace

static Runner add_trace(CLI::App& app) {
  auto o = std::make_shared<TraceCliOptions>();
  o->scene.add_to(app);
  app.add_option("--axes", o->axes, "plane axes x,y from lnB lnC lambda Delta Delta0 alpha beta (default: the scene's [diagram] or lnB,lnC)")->delimiter(',');
  app.add_option("--x-range", o->x_range, "min,max of x, finite (default: the scene's [diagram] or -1,6)")->delimiter(',')->expected(2);
  app.add_option("--y-range", o->y_range, "min,max of y, finite (default: the scene's [diagram] or -5.5,2)")->delimiter(',')->expected(2);
  app.add_option("--alpha-fixed", o->alpha_fixed, "hold alpha = B/C fixed over the plane, >= 0 (0: off; default: the scene's [diagram] or off)")
      ->check(non_negative());
  app.add_option("--lines", o->trace.lines, "lines across the plane (x fixed on each), integer in [2, 100000]")->capture_default_str();
  app.add_option("--samples", o->trace.samples, "brackets per line, integer in [2, 100000]")->capture_default_str();
  app.add_option("--diagram", o->diagram, "diagram JSON of the same plane: measure the criterion's agreement")
      ->check(CLI::ExistingFile);
  app.add_option("--out", o->out, "output prefix: PREFIX.csv and PREFIX.json")->capture_default_str();
  app.add_flag("--json", o->json, "print one JSON object on stdout (output files, pieces, corners, agreement)");
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegister{"trace", "Trace the stability boundary of a parameter plane as curves", add_trace, 42};
}  // namespace

}  // namespace rbcstab::cli
