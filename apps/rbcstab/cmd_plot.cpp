// rbcstab plot: a bifurcation diagram from one or more branch JSONs, as a PNG with the JSON of what was
// drawn beside it. The library decides what is drawn (report/bifurcation_plot.hpp); this file maps flags.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "rbcstab/report/bifurcation_plot.hpp"
#include "rbcstab/report/report.hpp"
#include "rbcstab/report/report_io.hpp"

namespace rbcstab::cli {

namespace {
struct PlotCliOptions {
  std::vector<std::string> files;
  PlotOptions plot;
  PlotDrawOptions draw;
  bool json = false;
};

int run(const PlotCliOptions& o) {
  PlotDrawOptions draw = o.draw;
  draw.validate();  // before reading anything: a bad --output writes nothing
  std::vector<PlotInput> inputs;
  for (const std::string& f : o.files) inputs.push_back(read_plot_input(f));
  const PlotSpec spec = plot_spec(inputs, o.plot);
  if (draw.script_dir.empty()) draw.script_dir = find_script_dir(executable_path());
  const PlotFiles files = draw_plot(spec, draw);
  for (const std::string& note : spec.notes) std::cerr << "rbcstab: warning: " << note << "\n";
  std::cout << (o.json ? plot_json(spec, files).dump(2) + "\n" : plot_text(spec, files));
  return kOk;
}

Runner add_plot(CLI::App& app) {
  auto o = std::make_shared<PlotCliOptions>();
  app.add_option("files", o->files,
                 "branch JSONs (`rbcstab continue --json > F.json` or a --save branch file), drawn overlaid; "
                 "a switched branch in a file is drawn as its own series")
      ->required();
  app.add_option("--output,-o", o->draw.output,
                 "the PNG to write; the JSON of what was drawn goes beside it (fig.json)")
      ->required();
  app.add_option("--x", o->plot.x,
                 "x axis: a parameter or measure of every file (default: the free parameter; a two-parameter "
                 "curve: its first parameter)");
  app.add_option("--y", o->plot.y,
                 "y axis: a parameter or measure of every file, e.g. r, Psi, sigma, Delta_3, r_min, r_max, period, "
                 "max_abs_multiplier, max_Re_eig, norm_Delta, norm_x (default: Psi for reduced-system equilibria, "
                 "r_max for orbits, r otherwise; a two-parameter curve: its second parameter)");
  app.add_option("--title", o->plot.title, "title above the diagram (default: the parameters held fixed)");
  app.add_flag("--all-labels", o->plot.all_labels,
               "also mark the labelled regular points (every N-th point of a branch file), not only special points");
  app.add_option("--width", o->draw.width, "width in pixels, integer in [200, 4000]")->capture_default_str();
  app.add_option("--height", o->draw.height, "height in pixels, integer in [200, 4000]")->capture_default_str();
  app.add_option("--python", o->draw.python, "python3 interpreter with matplotlib (Debian python3-matplotlib)")
      ->capture_default_str();
  app.add_option("--data-dir", o->draw.script_dir,
                 "folder holding rbcstab_report.py (default: $RBCSTAB_DATA_DIR, <prefix>/share/rbcstab/python)");
  app.add_flag("--json", o->json, "print one JSON object (files, axes, series) on stdout");
  app.footer(
      "Stable parts solid, unstable dashed, uncertain dotted; special points marked with their type and "
      "label (BP 3). Exit codes: 0 ok, 2 invalid input (unknown --x/--y, a file that is not a branch JSON: "
      "nothing written), 3 output error (python3/matplotlib missing, plotting failed). docs/plot.md.");
  return [o] { return run(*o); };
}

const RegisterCommand kRegisterPlot{
    "plot", "Draw a bifurcation diagram (PNG + JSON of what was drawn) from branch JSONs of `continue`", add_plot, 45};
}  // namespace

}  // namespace rbcstab::cli
