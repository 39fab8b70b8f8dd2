// rbcstab fit: membrane properties from observed motion (inverse/fit.hpp, docs/inverse.md). Flags -> fit() -> the
// result's text or JSON; --save writes the JSON, --report the page (report/fit_page.hpp). Progress and Ctrl-C as
// the other long commands.
#include <iostream>
#include <memory>

#include "checks.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/inverse/fit.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/report/fit_page.hpp"
#include "rbcstab/report/report.hpp"

namespace rbcstab::cli {

namespace {
struct FitCliOptions {
  std::string data, free, fixed, save, jacobian = "variational", profile_method = "gauss_newton";
  FitOptions fit;
  FitReportOptions report;
  bool json = false;
  ProgressOutput progress;
};

int run(FitCliOptions& o) {
  const ObservationData data = read_observation_data(o.data);
  CellModel cell;
  apply_assignments(cell, o.fixed, "fixed");
  const bool page = !o.report.output.empty();
  if (o.report.script_dir.empty()) o.report.script_dir = find_script_dir(executable_path());
  if (page) o.report = check_fit_report(o.report);  // before the fit: nothing computed for a folder refused
  const ProgressCallback starts = o.progress.callback("fit:", "starts done"),
                         points = o.progress.callback("fit: profiles:", "points done");
  if (starts)
    o.fit.on_progress = [=, profiles = o.fit.profiles.enabled](const FitProgress& p) {
      p.starts_done < p.starts || !profiles ? starts(p.starts_done, p.starts) : points(p.profile_points, 0);
    };
  const StopOnSignal interrupt;
  o.fit.stop = interrupt.flag();
  o.fit.jacobian = from_string<JacobianMethod>(o.jacobian, "jacobian");
  o.fit.profiles.method = from_string<ProfileMethod>(o.profile_method, "profile_method");
  const FitResult r = fit(data, comma_items(o.free), cell, o.fit);
  nlohmann::json doc = to_json(r);
  doc["data"] = o.data;
  if (!o.save.empty()) write_file_atomic(o.save, doc.dump(1) + "\n", "--save");
  const bool drawn = page && r.status != FitStatus::failed && r.status != FitStatus::interrupted;
  if (drawn) doc["report"] = write_fit_report(r, data, o.report).output;
  if (page && !drawn) std::cerr << "rbcstab: no report written: the fit is " << to_string(r.status) << "\n";
  if (r.status == FitStatus::interrupted) std::cerr << "rbcstab: stopped by a signal: " << r.message << "\n";
  if (o.json)
    std::cout << doc.dump(2) << "\n";
  else
    std::cout << fit_text(r) << (drawn ? "report: " + doc["report"].get<std::string>() + "\n" : "");
  return r.status == FitStatus::converged ? kOk : kRunFailed;
}

// "bending_modulus (kappa), shear_modulus (mu), ...": the fit's parameter names from its table.
std::string parameter_list() {
  std::string out;
  const CellModel cell;
  for (const auto& e : EnumTable<FitParameter>::entries) {
    const FitParameterInfo i = fit_parameter_info(e.value, cell);
    out += (out.empty() ? "" : ", ") + i.name + (i.alias.empty() ? "" : " (" + i.alias + ")");
  }
  return out;
}

Runner add_fit(CLI::App& app) {
  auto o = std::make_shared<FitCliOptions>();
  app.add_option("--data", o->data,
                 "observations CSV (docs/inverse.md: observable, shear_rate, viscosity, value, "
                 "uncertainty, unit[, regime, note])")
      ->required();
  app.add_option("--free", o->free, "comma list of the parameters to fit: " + parameter_list())->required();
  app.add_option("--fixed", o->fixed,
                 "comma list name=value: the fixed values and the free ones' start (moduli, radius and inner viscosity "
                 "with units as the scene's [physical] keys: shear_modulus=6uN/m, radius=2.8um; the numbers bare: "
                 "Delta=0.1); default: the red cell's typical values and the parameter table's defaults");
  add_integer(app, "--starts", o->fit.starts, 1, 64, "Ipopt starts: the given one, then spread ones");
  add_integer(app, "--max-iterations", o->fit.max_iterations, 1, 10000, "Ipopt iterations per start");
  add_integer(app, "--seed", o->fit.seed, 0, 4294967295LL, "seed of the spread starts");
  app.add_flag("--profiles", o->fit.profiles.enabled,
               "profile likelihoods: each free parameter held on a grid while the others are re-fitted; 95 % "
               "intervals where Delta chi^2 crosses 3.84, flat ones named (docs/inverse.md)");
  add_integer(app, "--profile-points", o->fit.profiles.points, 1, 50,
              "profile grid points on each side of the estimate within --profile-span");
  app.add_option("--profile-span", o->fit.profiles.span,
                 "reach of the profile grid in Fisher standard errors, in (0, 50] (beyond it doubling steps to the "
                 "bound)")
      ->check(number_above(0, true))
      ->capture_default_str();
  app.add_option("--profile-method", o->profile_method,
                 "profile re-fits: gauss_newton (Ipopt where it fails or a regime row is active) or ipopt")
      ->check(CLI::IsMember(enum_names<ProfileMethod>()))
      ->capture_default_str();
  app.add_option("--jacobian", o->jacobian,
                 "the in-plane rows' sensitivities: variational equations of the orbit, or finite_difference")
      ->check(CLI::IsMember(enum_names<JacobianMethod>()))
      ->capture_default_str();
  app.add_option("--save", o->save, "write the result as JSON to this file")->check(output_name());
  app.add_option("--report", o->report.output,
                 "write the fit's page to this folder (index.html, figures, parameters.csv; docs/report.md)");
  app.add_flag("--overwrite", o->report.overwrite, "--report: replace an existing folder (swapped in whole)");
  app.add_flag("--json", o->json, "print one JSON object on stdout");
  o->progress.add_flags(app);
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterFit{"fit",
                                   "Membrane properties (moduli, excess areas, viscosity ratio) from observed "
                                   "motion, with 95 % intervals",
                                   add_fit, 97};
}  // namespace

}  // namespace rbcstab::cli
