#pragma once
// Phase diagrams by direct simulation (paper Fig. 4, Fig. 5, Appendix E): a regular grid over two
// axes (the parameter table's, model/parameter_table.hpp: lambda, Delta, Delta0, alpha, ln B, ln C, beta, and
// shear_rate on a physical scene); every point is one modal-level `simulate`
// classified by l_Delta. Points are independent and deterministic, so the result does not depend
// on the thread count, the scheduling, the shard split, MPI ranks or on resuming from a journal.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

using Axis = SceneParameter;  // one of the rows usable_as(q, ParameterUse::axis); to_string gives its name
Axis axis_from_string(const std::string& name);  // throws InvalidArgument("axis", ...)
const std::vector<std::string>& axis_names();

struct AxisRange {
  Axis axis = Axis::lnB;
  double min = -1, max = 6;  // inclusive ends (Fig. 4: ln B in [-1, 6])
  int count = 64;            // grid values; 1 gives the single value min
  // min + (max - min) i / (count - 1), exactly max at the end; a geometric axis (shear_rate) steps evenly in
  // ln: min (max/min)^(i/(count - 1)).
  double value(int i) const;
};

// How l_Delta = argmax_l [X_l - Delta_l(0)] picks X_l.
enum class Classifier {
  automatic,  // simulate's rule: tail mean when Delta_2 oscillates over the tail window, else Delta_l(T)
  final,      // X = Delta_l(T): the paper's out-of-plane rule (Fig. 4)
  tail_mean,  // X = mean over [T - tail_window, T]: the paper's in-plane rule (Appendix E)
};
template <>
struct EnumTable<Classifier> {
  static constexpr EnumName<Classifier> entries[] = {
      {Classifier::automatic, "auto"}, {Classifier::final, "final"}, {Classifier::tail_mean, "tail"}};
};
// Throws InvalidArgument("classifier", ...) naming the allowed classifiers.
inline Classifier classifier_from_string(std::string_view name) { return from_string<Classifier>(name, "classifier"); }

// The largest grid (4096 x 4096): every point's result is held in memory (sizeof(PointResult) = 160 bytes,
// about 2.7 GB at the bound) and journaled, so a larger grid is refused before any work starts.
constexpr long long kMaxDiagramPoints = 4096LL * 4096LL;

struct DiagramSpec {
  AxisRange x{Axis::lnB, -1, 6, 64};              // fastest-varying axis: index = j * x.count + i
  AxisRange y{Axis::lnC, -5.5, 2, 64};            // Fig. 4: ln C in [-5.5, 2]
  Classifier classifier = Classifier::automatic;  // see Classifier
  double alpha = 0;  // > 0: hold alpha = B/C fixed over the plane (Fig. 5: ln C - lambda at alpha = 40, 100, 500)
  // Distinct axes that do not move each other (independent(); alpha is applied last), finite ranges, counts in
  // [1, 10^6] with at most kMaxDiagramPoints points, alpha >= 0.
  void validate() const;
  std::size_t size() const { return std::size_t(x.count) * std::size_t(y.count); }
};

// spec.validate(), base.validate(), each axis usable on base (require_usable: shear_rate needs a physical scene,
// InvalidArgument("shear_rate", ...)), and every corner of the plane a valid scene: each axis range's ends lie in
// its axis's domain at the base scene (ln B = 800 gives B = inf), so every point between them does (the axes
// map monotonically onto interval domains). Throws InvalidArgument("diagram.x_range" | "diagram.y_range", ...)
// naming the axis, the end and the parameter that left its domain.
void validate_plane(const Scene& base, const DiagramSpec& spec);

// The scene of grid point `index`: base with the two axis values applied (set_parameter, unchecked: the
// diagram validates every point's scene). alpha = B/C (an axis value, or spec.alpha > 0) is applied last and
// keeps the other axis's B fixed when it moves B (ln B: C = B/alpha), otherwise keeps C (B = alpha C).
Scene point_scene(const Scene& base, const DiagramSpec& spec, std::size_t index);
// The same mapping at continuous axis values (x, y) (boundary tracing); the scene name is kept.
Scene plane_scene(const Scene& base, const DiagramSpec& spec, double x, double y);

enum class Verdict { stable, unstable, failed };  // failed: the integrator did not reach T
template <>
struct EnumTable<Verdict> {
  static constexpr EnumName<Verdict> entries[] = {
      {Verdict::stable, "stable"}, {Verdict::unstable, "unstable"}, {Verdict::failed, "failed"}};
};

// A point's verdict: failed unless the integrator reached T, else unstable iff l_Delta >= 3.
Verdict verdict_of(IntegrationStatus status, int l_Delta);

struct PointResult {
  std::size_t index = 0;
  int i = 0, j = 0;     // grid position (x, y)
  double x = 0, y = 0;  // axis values
  Verdict verdict = Verdict::stable;
  int l_Delta = 2;           // per the spec's classifier (2: stable)
  double growth = 0;         // X_{l_Delta} - Delta_{l_Delta}(0)
  bool oscillating = false;  // Delta_2 not monotonic over the tail window (classifiers final and tail: on
                             // the run's accepted steps there, SimulationOptions::tail_means)
  double sigma_final = 0;    // sigma(T)
  IntegrationStatus status = IntegrationStatus::success;
  std::string reason;  // integrator message when not success
  double t_reached = 0;
  std::size_t steps = 0, failed_steps = 0, rhs_evaluations = 0;  // cost (deterministic)
  double seconds = 0;                                            // cost (wall clock; the only non-deterministic field)
  // Certified early termination (SimulationResult::early): where the run stopped integrating and its
  // certificate's margin 1 - max |mu|; NaN when the run was integrated to T.
  double terminated_at = std::numeric_limits<double>::quiet_NaN();
  double margin = std::numeric_limits<double>::quiet_NaN();
};

// One grid point (throws InvalidArgument if the point's scene is invalid).
PointResult run_point(const Scene& base, const SimulationOptions& options, const DiagramSpec& spec, std::size_t index);

struct Shard {
  int k = 0, n = 1;  // this job computes the points with index % n == k (interleaved: balances cost)
  bool contains(std::size_t index) const { return index % std::size_t(n) == std::size_t(k); }
  void validate() const;
};
Shard shard_from_string(const std::string& text);  // "k/n", 0 <= k < n
// The file-name suffix of a shard's outputs and journal: ".shardKofN", "" for the whole grid.
std::string shard_suffix(const Shard& s);

struct Progress {
  std::size_t done = 0;     // finished points of this job, resumed ones included
  std::size_t total = 0;    // points of this job
  std::size_t resumed = 0;  // taken from the journal
  double elapsed = 0;       // seconds since the start of this run
  double rate = 0;          // computed points per second in this run
  double eta = 0;           // seconds left at that rate (0 when unknown)
};

struct DiagramOptions {
  int threads = 1;                 // worker threads; 0 = std::thread::hardware_concurrency()
  bool dynamic_schedule = true;    // dynamic: next free point; static: worker w takes every threads-th point
  Shard shard;                     // the slice of the grid this job owns
  std::string journal;             // append-only checkpoint file, locked for the run; empty = none (no resume)
  double sync_interval = 1.0;      // fdatasync the journal at most this often [s]; every line is write()n at once,
                                   // so a killed process loses nothing, only a power cut could lose <= this much
  double progress_interval = 1.0;  // seconds between on_progress calls
  std::function<void(const Progress&)> on_progress;  // called on the calling thread
  const std::atomic<bool>* stop = nullptr;           // set (e.g. by SIGINT) to stop picking new points
  void validate() const;
};

struct DiagramRun {
  std::vector<PointResult> points;    // this job's points in index order (all of them unless interrupted)
  std::size_t computed = 0;           // simulated in this run
  std::size_t resumed = 0;            // read back from the journal
  std::vector<std::string> rejected;  // "journal:line: why" of each journal record dropped and recomputed
  bool complete = false;              // every point of the job is in `points`
  std::string config_hash;            // hash of everything that determines the points
  double seconds = 0;
};

// 16 hex digits (FNV-1a 64) of the canonical text of base, options and spec; shards of the same
// diagram share it (the shard is not part of it).
std::string config_hash(const Scene& base, const SimulationOptions& options, const DiagramSpec& spec);

// Runs (or resumes) this job's points with a thread pool. A journal written for another
// configuration, by an older format, or being written by another process (it names that process)
// is refused (InvalidArgument("journal", ...)); a corrupt, foreign or duplicated record in it is
// listed in DiagramRun::rejected and its point recomputed.
DiagramRun run_diagram(const Scene& base, const SimulationOptions& options, const DiagramSpec& spec,
                       const DiagramOptions& run_options);

}  // namespace rbcstab
