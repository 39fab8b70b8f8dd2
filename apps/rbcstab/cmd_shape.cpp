// rbcstab shape: the cell's 3-D shape at chosen times as VTK / VTP / PLY / CSV (no python needed).
#include <cmath>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "checks.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/report/report.hpp"
#include "scene_options.hpp"

namespace rbcstab::cli {

namespace {
struct ShapeCliOptions {
  SceneOptions scene;
  std::string output;
  std::vector<double> at;
  std::vector<std::string> formats{"vtk"};
  int n_theta = 64;
  bool json = false;
};

int run(const ShapeCliOptions& o) {
  const SceneFile sf = o.scene.resolve(TruncationUse::simulation);
  std::vector<double> times = o.at.empty() ? std::vector<double>{sf.scene.T} : o.at;
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  const ShapeGridOptions grid_options{o.n_theta, 2 * o.n_theta};
  grid_options.validate();
  const AmplitudeSeries series = amplitudes_at(sf, times);
  ShapeExport result{series.level.level, series.status, series.reason, {}};
  std::vector<OutputFile> outputs;
  for (std::size_t k = 0; k < series.t.size(); ++k) {
    const ShapeGrid g = shape_on_grid(series.f[k], grid_options);
    const SurfaceMesh mesh = surface_mesh(g);
    std::ostringstream stem;
    stem << o.output;
    if (times.size() > 1) stem << "_t" << series.t[k];
    const std::string title = "rbcstab shape of scene " + sf.scene.name + " at t = " + format_value(series.t[k]);
    for (const auto& f : o.formats) {
      const std::string path = stem.str() + "." + f;
      const std::string text = f == "vtk"   ? to_vtk_legacy(mesh, title)
                               : f == "vtp" ? to_vtk_xml(mesh)
                               : f == "ply" ? to_ply(mesh, title)
                                            : to_csv(g);
      outputs.push_back({path, text, "--output"});
      result.files.push_back({series.t[k], path, g.rho_min, g.rho_max});
    }
  }
  write_files_atomic(outputs);
  if (o.json) {
    nlohmann::json j = to_json(result);
    put_truncation(j, sf);
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << to_text(result);
  }
  if (series.status != IntegrationStatus::success) {
    std::cerr << "rbcstab: run stopped: " << run_reason(series.status, series.reason, sf.scene.parameters)
              << " (shapes written up to that time)\n";
    return kRunFailed;
  }
  return kOk;
}
}  // namespace

static Runner add_shape(CLI::App& app) {
  auto o = std::make_shared<ShapeCliOptions>();
  o->scene.add_to(app);
  app.add_option("--output,-o", o->output,
                 "file stem: writes STEM.vtk etc. (STEM_t<time>.vtk when several --at times are given)")
      ->required();
  app.add_option("--at", o->at, "times in [0, T] at which to write the shape (repeatable; default: T)");
  app.add_option("--format", o->formats, "formats, any of vtk (legacy), vtp (VTK XML), ply, csv (theta, phi grid)")
      ->check(CLI::IsMember({"vtk", "vtp", "ply", "csv"}))
      ->capture_default_str();
  app.add_option("--resolution", o->n_theta, "polar grid points n_theta (n_phi = 2 n_theta), integer in [2, 4096]")
      ->check(integer_in(2, 4096))
      ->capture_default_str();
  app.add_flag("--json", o->json, "print one JSON object (files, rho range, status) on stdout");
  return [o] { return run(*o); };
}

namespace {
const RegisterCommand kRegisterShape{"shape", "Write the cell's 3-D shape rho(theta, phi) at chosen times (VTK, VTP, PLY, CSV)",
                                add_shape, 61};
}  // namespace

}  // namespace rbcstab::cli
