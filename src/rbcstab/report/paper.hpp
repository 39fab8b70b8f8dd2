#pragma once
// The paper, composed as the paper composes it: every figure (Figs. 2-6 and the appendix figures) drawn from
// its runs as one matplotlib figure with the paper's panels and overlays, beside its caption's quantitative
// claims and a check of each claim computed here from the runs' data. One folder: index.html (each figure,
// its claims with measured value, expectation and verdict, links to its data), paper.json (the drawing spec
// python/paper_draw.py renders), claims.json, and the data behind every panel (CSV/JSON). The folder
// appears whole or not at all, as a report's.
//
// Runs come from the scene files in scenes/ (find_scene_dir); the runs drawn as curves are integrated to T
// (no certified early termination: the whole trajectory is plotted), the phase diagrams run as
// `rbcstab report` runs their panels (certified early termination on).
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "rbcstab/model/amplitudes.hpp"
#include "rbcstab/sweep/diagram.hpp"

namespace rbcstab {

struct PaperOptions {
  std::string output;                       // folder to create (its parent must exist)
  bool overwrite = false;                   // replace an existing folder (swapped in whole at the end)
  bool quick = false;                       // coarse grids: 12 x 12 phase diagrams, a 3 x 2 Fig. 6e grid per lambda
  int threads = 0;                          // worker threads for runs and diagram points; 0 = all cores
  std::string python = "/usr/bin/python3";  // with python3-matplotlib
  std::string script_dir;                   // folder of paper_draw.py; empty: find_script_dir("")
  std::string scene_dir;                    // folder of the paper's scene files; empty: find_scene_dir("")
  // Progress: each step as it starts (figure k of n), and the diagram points of the phase diagrams.
  std::function<void(const std::string& step, int figure, int figures)> on_step;
  std::function<void(const Progress&)> on_progress;
  const std::atomic<bool>* stop = nullptr;  // set to stop early (then nothing is written)
  void validate() const;                    // throws InvalidArgument naming the field
};

// One quantitative claim of a caption (or of the text about the figure) and its check on the computed data.
struct ClaimCheck {
  std::string figure;    // "Fig. 2", "Fig. app3", ...
  std::string claim;     // what the paper says
  std::string measured;  // the value computed from the runs
  std::string expected;  // the condition the value must meet
  bool passed = false;
  std::string how;    // how the value is measured (window, tolerance, which runs)
  std::string check;  // the check applied (paper_check::names(), paper_checks.hpp)
  // Set on a failed claim where the model, run as the paper states, contradicts the paper: the evidence.
  std::string inconsistency;
};

struct PaperFigure {
  std::string id;                 // "fig2", ... (also the PNG's name)
  std::string title;              // "Fig. 2: reduced system dynamics with different excess areas"
  std::vector<std::string> data;  // files behind it, relative to the output folder
  double seconds = 0;             // its computation (drawing excluded)
};

struct PaperResult {
  std::vector<PaperFigure> figures;
  std::vector<ClaimCheck> claims;
  std::size_t passed = 0, failed = 0;
  std::size_t inconsistent = 0;    // of the failed: paper/model inconsistencies (ClaimCheck::inconsistency)
  std::size_t failed_runs = 0;     // runs or diagram points that did not reach T
  bool complete = true;            // false: stopped (options.stop) and nothing was written
  std::vector<std::string> files;  // relative to the output folder
  double seconds = 0;
};

// Computes and draws every figure. Bad options throw InvalidArgument; missing python/matplotlib, failed drawing
// or an unwritable folder throw ReportError, leaving no partial folder. Claims that fail are reported as failed.
PaperResult build_paper(const PaperOptions& options);

// Where the paper's scene files are: $RBCSTAB_DATA_DIR/scenes, <exe>/../share/rbcstab/scenes (installed), then
// the source tree this library was built from. Empty if none holds them.
std::string find_scene_dir(const std::string& executable_path);

// The measures the claim checks apply to sampled series x(t) (t ascending, same length), exposed for tests.
namespace paper_measure {
// Mean of x over t in [t_end - window, t_end] (trapezoidal; the samples inside the window).
double tail_mean(const std::vector<double>& t, const std::vector<double>& x, double window);
// max - min of x over that window.
double tail_range(const std::vector<double>& t, const std::vector<double>& x, double window);
// The last time |x - x_end| exceeds tol (x_end = tail_mean over the last 5% of the run); t.front() if never.
double settle_time(const std::vector<double>& t, const std::vector<double>& x, double tol);
// The maximum of x is at an interior sample and x at the end has fallen below `drop` times that maximum,
// which exceeds x at the start: "first grows, then decays".
bool grows_then_decays(const std::vector<double>& x, double drop);
// The net turn of Psi over the run with each step taken modulo pi (into (-pi/2, pi/2]): r -> -r, Psi -> Psi + pi
// is the same shape (f_{2,2} ~ r e^{-i Psi}), so the jump by pi when r passes through 0 (a vesicle tumbling
// through a nearly axisymmetric shape) is no turn. A tumbling cell turns Psi by -2 pi per tumble.
double net_turn(const std::vector<double>& Psi);
// The share of each |m| = 0..l in sum_m |f_{l,m}|^2 (m about the vorticity axis z): where mode l's area lies
// azimuthally. m = 0 alone is a shape axisymmetric about z; |m| = l puts l lobes around z, in the shear plane.
// All zeros when the mode is empty.
std::vector<double> azimuthal_shares(const ModeAmplitudes& f, int l);
// Largest |x(t) - y(t)| / |y(t)| over t <= t_max for two series on the same samples.
double max_relative_gap(const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& y,
                        double t_max);
}  // namespace paper_measure

}  // namespace rbcstab
