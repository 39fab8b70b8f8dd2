// rbcstab shape: the cell's 3-D shape at chosen times as VTK / VTP / PLY / CSV (no python needed).
#include <iostream>
#include <memory>

#include "checks.hpp"
#include "commands.hpp"
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
  const ShapeExportRun e = export_shapes(sf, {o.output, o.at, o.formats, {o.n_theta, 2 * o.n_theta}}, "--output");
  write_files_atomic(e.files);
  if (o.json) {
    nlohmann::json j = to_json(e.result);
    put_truncation(j, sf);
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << to_text(e.result);
  }
  if (e.result.status != IntegrationStatus::success) {
    std::cerr << "rbcstab: run stopped: " << run_reason(e.result.status, e.result.reason, sf.scene.parameters)
              << " (shapes written up to that time)\n";
    return kRunFailed;
  }
  return kOk;
}

Runner add_shape(CLI::App& app) {
  auto o = std::make_shared<ShapeCliOptions>();
  o->scene.add_to(app);
  app.add_option("--output,-o", o->output,
                 "file stem: writes STEM.vtk etc. (STEM_t<time>.vtk when several --at times are given)")
      ->required();
  app.add_option("--at", o->at, "times in [0, T] at which to write the shape (repeatable; default: T)");
  app.add_option("--format", o->formats, "formats, any of vtk (legacy), vtp (VTK XML), ply, csv (theta, phi grid)")
      ->check(CLI::IsMember({"vtk", "vtp", "ply", "csv"}))
      ->capture_default_str();
  add_integer(app, "--resolution", o->n_theta, 2, 4096, "polar grid points n_theta (n_phi = 2 n_theta)");
  app.add_flag("--json", o->json, "print one JSON object (files, rho range, status) on stdout");
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterShape{
    "shape", "Write the cell's 3-D shape rho(theta, phi) at chosen times (VTK, VTP, PLY, CSV)", add_shape, 61};
}  // namespace

}  // namespace rbcstab::cli
