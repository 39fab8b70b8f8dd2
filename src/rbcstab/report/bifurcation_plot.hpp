#pragma once
// Bifurcation diagrams from branch JSONs (`rbcstab continue --json` and the branch files of
// `--save`; schema in continuation/branch_io.hpp): which quantity goes on each axis, the series and their
// stability segments, the marked and labelled points. Everything drawn is decided here, as a plain
// PlotSpec; rbcstab_report.py only renders it. `rbcstab plot`, `report --bifurcation` and the report's
// [continuation] panel all go through plot_spec.
//
// Axes: x defaults to the free parameter, y to Psi (reduced-system equilibria), r_max (orbits) or r; a
// two-parameter curve is drawn in its plane (p1, p2). Any parameter or numeric measure the points carry
// can be chosen, plus measures derived here:
//   period              orbits: the forcing period 2 pi the shooting closes over
//   max_abs_multiplier  orbits: max |mu| over the Floquet multipliers ("multipliers")
//   max_Re_eig          equilibria: max Re lambda over the eigenvalues ("eigenvalues")
//   norm_Delta          kinds with Delta_l: (sum_l Delta_l^2)^(1/2)
//   norm_x              branch files: |x|_2 of the full state
// and the scene's parameters the input holds fixed (constant along it: a one-parameter branch drawn in
// the plane of a two-parameter curve crosses the curve at its special point).
// Stability per point: "stability" (stable, unstable, uncertain) when the point has it, else from the
// boolean "stable". Stable parts are solid, unstable dashed, uncertain dotted; two-parameter curves are
// solid (each of their points has a critical eigenvalue or multiplier on the boundary by construction).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rbcstab {

// One branch JSON and the name it is known by (its file: messages, legend).
struct PlotInput {
  std::string source;
  nlohmann::json branch;
};
// Throws InvalidArgument("file", ...) naming `source` unless j is a branch JSON (an object with a
// "branch" array of point objects and "free_parameter"; a two-parameter curve with "curve").
PlotInput plot_input(nlohmann::json j, const std::string& source);
// Reads a branch JSON file: InvalidArgument("file", ...) naming the file if it is unreadable, not JSON
// (e.g. truncated) or not a branch JSON.
PlotInput read_plot_input(const std::string& path);

struct PlotOptions {
  std::string x;            // "" = the free parameter (curves: their first parameter)
  std::string y;            // "" = Psi (reduced equilibria), r_max (orbits), r (other kinds), p2 (curves)
  std::string title;        // "" = the kind and the parameters the inputs share and do not vary
  bool all_labels = false;  // also mark labelled regular points (AUTO's every N-th label), not only special ones
};

// A run of consecutive vertices of one stability; neighbouring segments share their boundary vertex
// (the located special point where stability changes, else the midpoint of the two points).
struct PlotSegment {
  std::string stability;     // stable, unstable, uncertain; "curve" for two-parameter curves
  std::string style;         // solid, dashed, dotted
  std::vector<double> x, y;  // NaN where the quantity is undefined (the line breaks there)
};

struct PlotSeries {
  std::string name;                    // legend text
  std::string kind;                    // equilibrium, orbit, curve
  std::string problem;                 // the input's kind: equilibrium, modal, full, orbit, modal-orbit
  std::string level;                   // reduced, modal, full
  std::string role;                    // primary, switched
  std::string source;                  // the input it came from
  std::vector<double> x, y;            // the branch's points (NaN: undefined)
  std::vector<std::string> stability;  // per point
  std::vector<PlotSegment> segments;   // what is drawn: the points with the special points inserted
};

struct PlotPoint {
  double x = 0, y = 0;
  std::string type;          // LP, BP, HB, LPC, PD, NS, UZ, EP, codimension-two types; "" for a regular point
  std::optional<int> label;  // the point's label when the input has one
  std::string stability;     // as the input says ("" when it does not)
  std::size_t series = 0;    // index into PlotSpec::series
  std::string marker;        // special, end (EP), regular
  std::string text;          // drawn beside the marker ("BP 3"; coinciding points share one: "LP 2, BP 3"; "" none)
  std::string criticality;   // a special point's normal form: supercritical or subcritical ("" otherwise)
};

struct PlotAxis {
  std::string name;   // the parameter or measure
  std::string label;  // the axis label (matplotlib mathtext)
};

struct PlotSpec {
  PlotAxis x, y;
  std::string title;
  std::vector<PlotSeries> series;
  std::vector<PlotPoint> points;
  std::vector<std::string> measures;  // the names x and y accept for these inputs
  std::vector<std::string> notes;     // what was not drawn and why (a switched branch that failed)
};

// The names x and y accept for one input: its parameter(s), the numeric measures of its points and the
// derived measures that apply.
std::vector<std::string> plot_measures(const PlotInput& input);

// The diagram of one or more inputs, overlaid (each input's branch and its switched branch, if any).
// Throws InvalidArgument("x" / "y", ...) naming the value and the available measures when an input
// lacks the quantity, InvalidArgument("inputs", ...) without inputs.
PlotSpec plot_spec(const std::vector<PlotInput>& inputs, const PlotOptions& options = {});

// The axis label of a parameter or measure in the paper's symbols (mathtext), or the name itself.
std::string tex_symbol(const std::string& name);

// "what was drawn": {"format": "rbcstab-plot", "version": 1, "x", "y", "title", "series", "points",
// "measures", "notes"} (docs/plot.md).
nlohmann::json to_json(const PlotSpec& spec);

struct PlotDrawOptions {
  std::string output;                       // the PNG; its folder must exist; the JSON is written beside it
  int width = 900, height = 675;            // pixels, each in [200, 4000]
  std::string python = "/usr/bin/python3";  // with python3-matplotlib
  std::string script_dir;                   // folder of rbcstab_report.py; empty: find_script_dir("")
  void validate() const;                    // InvalidArgument naming output, width or height
};

// fig.json for fig.png: where the JSON of what was drawn goes.
std::string plot_json_path(const std::string& png);

// Draws the spec into options.output and writes to_json(spec) beside it (plot_json_path). Both appear
// whole or not at all: InvalidArgument for bad options, ReportError (report.hpp) when python or
// matplotlib is missing, the script fails or the folder is not writable.
struct PlotFiles {
  std::string png, json;
};
PlotFiles draw_plot(const PlotSpec& spec, const PlotDrawOptions& options);

}  // namespace rbcstab
