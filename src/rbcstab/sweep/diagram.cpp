#include "rbcstab/sweep/diagram.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <iomanip>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>
#include <tuple>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/detail/journal.hpp"
#include "rbcstab/sweep/point_record.hpp"
#include "rbcstab/verdict/certified_run.hpp"

namespace rbcstab {

const std::vector<std::string>& axis_names() {
  static const std::vector<std::string> names = parameter_names(ParameterUse::axis);
  return names;
}

Axis axis_from_string(const std::string& name) { return parameter_from_string(name, ParameterUse::axis); }

double AxisRange::value(int i) const {
  if (count <= 1) return min;
  if (i == count - 1) return max;
  // A geometric axis (shear_rate) spans decades: even steps in ln. Its range is checked > 0 (validate_plane).
  if (parameter_row(axis).scale == AxisScale::geometric)
    return min * std::pow(max / min, double(i) / double(count - 1));
  return min + (max - min) * double(i) / double(count - 1);
}

void DiagramSpec::validate() const {
  for (const AxisRange* a : {&x, &y}) {
    const std::string n = a == &x ? "x" : "y";
    require(std::isfinite(a->min), "diagram." + n + "_range", a->min, "finite");
    require(std::isfinite(a->max), "diagram." + n + "_range", a->max, "finite");
    require(std::isfinite(a->max - a->min), "diagram." + n + "_range", a->max,
            "finite, with a finite width max - min (min = " + format_value(a->min) + ")");
    require(a->count >= 1 && a->count <= 1'000'000, "diagram.counts", a->count, "an integer in [1, 1000000]");
    if (!usable_as(a->axis, ParameterUse::axis)) {
      std::string list;
      for (const std::string& name : axis_names()) list += (list.empty() ? "" : ", ") + name;
      throw InvalidArgument("diagram.axes",
                            "diagram.axes: " + to_string(a->axis) + " is not a diagram axis (allowed: " + list + ")");
    }
  }
  const long long points = 1LL * x.count * y.count;
  if (points > kMaxDiagramPoints) {
    std::ostringstream m;
    m << "diagram.counts = " << x.count << "," << y.count << " is " << points << " points (about "
      << format_bytes(double(points) * double(sizeof(PointResult))) << " of results, before any work): must be at most "
      << kMaxDiagramPoints << " points (4096 x 4096)";
    throw InvalidArgument("diagram.counts", m.str());
  }
  require(std::isfinite(alpha) && alpha >= 0, "diagram.alpha", alpha, "finite and >= 0 (0: alpha not held fixed)");
  if (alpha > 0 && (x.axis == Axis::alpha || y.axis == Axis::alpha))
    throw InvalidArgument("diagram.alpha", "diagram.alpha cannot be held fixed while alpha is an axis");
  if (x.axis == y.axis)
    throw InvalidArgument("diagram.axes",
                          "diagram.axes must name two different axes (both are '" + to_string(x.axis) + "')");
  // alpha is applied last and keeps the other axis's move (plane_scene); any other pair must not move each other.
  if (x.axis != Axis::alpha && y.axis != Axis::alpha && !independent(x.axis, y.axis))
    throw InvalidArgument("diagram.axes", "diagram.axes = " + to_string(x.axis) + "," + to_string(y.axis) +
                                              ": setting one moves the other (they share an input; shear_rate moves "
                                              "B and C): choose two independent axes");
}

void Shard::validate() const {
  require(n >= 1, "shard", n, "k/n with n >= 1");
  require(k >= 0 && k < n, "shard", k, "k/n with 0 <= k < n");
}

std::string shard_suffix(const Shard& s) {
  return s.n > 1 ? ".shard" + std::to_string(s.k) + "of" + std::to_string(s.n) : "";
}

Shard shard_from_string(const std::string& text) {
  const auto slash = text.find('/');
  Shard s;
  try {
    if (slash == std::string::npos) throw std::invalid_argument(text);
    std::size_t p1 = 0, p2 = 0;
    s.k = std::stoi(text.substr(0, slash), &p1);
    s.n = std::stoi(text.substr(slash + 1), &p2);
    if (p1 != slash || p2 != text.size() - slash - 1) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw InvalidArgument("shard", "shard = '" + text + "' must have the form k/n, e.g. 0/4");
  }
  s.validate();
  return s;
}

void DiagramOptions::validate() const {
  require(threads >= 0 && threads <= 4096, "threads", threads, "an integer in [0, 4096] (0: all cores)");
  shard.validate();
  require(std::isfinite(sync_interval) && sync_interval >= 0, "sync_interval", sync_interval, "finite and >= 0");
  require(std::isfinite(progress_interval) && progress_interval > 0, "progress_interval", progress_interval,
          "finite and > 0");
}

Scene plane_scene(const Scene& base, const DiagramSpec& spec, double x, double y) {
  Scene s = base;
  double alpha = spec.alpha > 0 ? spec.alpha : -1;
  for (const auto& [a, v] : {std::pair{&spec.x, x}, std::pair{&spec.y, y}}) {
    if (a->axis == Axis::alpha)
      alpha = v;
    else
      set_parameter(s, a->axis, v);
  }
  if (alpha != -1) {
    require(std::isfinite(alpha) && alpha > 0, "alpha", alpha, "finite and > 0 on an alpha axis");
    bool keep_B = false;
    for (Axis a : {spec.x.axis, spec.y.axis})
      keep_B = keep_B || (a != Axis::alpha && (parameter_row(a).inputs & parameter_row(Axis::B).inputs) != 0);
    if (keep_B)
      s.parameters.C = s.parameters.B / alpha;
    else
      set_parameter(s, Axis::alpha, alpha);
  }
  return s;
}

void validate_plane(const Scene& base, const DiagramSpec& spec) {
  spec.validate();
  base.validate();
  for (Axis a : {spec.x.axis, spec.y.axis}) require_usable(a, base);
  // Each axis alone at its ends with the other at its min, then the corners (held alpha couples the axes).
  const std::pair<double, double> corners[] = {
      {spec.x.min, spec.y.min}, {spec.x.max, spec.y.min}, {spec.x.min, spec.y.max}, {spec.x.max, spec.y.max}};
  for (const auto& [x, y] : corners) {
    try {
      plane_scene(base, spec, x, y).validate();
    } catch (const InvalidArgument& e) {
      // The axis that moves the parameter named, else the one away from its min.
      auto moves = [](Axis a) { return to_string(moved_parameter(a)); };
      const bool x_moved = x != spec.x.min, y_moved = y != spec.y.min;
      const bool blame_y =
          e.parameter() == moves(spec.y.axis) ? e.parameter() != moves(spec.x.axis) || !x_moved : y_moved && !x_moved;
      const AxisRange& a = blame_y ? spec.y : spec.x;
      const std::string key = std::string("diagram.") + (blame_y ? "y" : "x") + "_range";
      std::string at = to_string(a.axis) + " = " + format_value(blame_y ? y : x);
      if (x_moved && y_moved) at += " with " + to_string(spec.y.axis) + " = " + format_value(y);
      throw InvalidArgument(
          key, key + " = " + format_value(a.min) + "," + format_value(a.max) + ": at " + at + ", " + e.what());
    }
  }
}

Scene point_scene(const Scene& base, const DiagramSpec& spec, std::size_t index) {
  require(index < spec.size(), "index", double(index), "below the number of grid points");
  const int i = int(index % std::size_t(spec.x.count));
  const int j = int(index / std::size_t(spec.x.count));
  Scene s = plane_scene(base, spec, spec.x.value(i), spec.y.value(j));
  std::ostringstream name;
  name << base.name << "[" << index << "]";
  s.name = name.str();
  return s;
}

namespace {
// argmax_l [X_l - Delta_l(0)] and its value (index l - 2 in the vectors).
std::pair<int, double> argmax_growth(const std::vector<double>& X, const std::vector<double>& X0) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < X.size(); ++k)
    if (X[k] - X0[k] > X[best] - X0[best]) best = k;
  return {int(best) + 2, X.empty() ? 0.0 : X[best] - X0[best]};
}
}  // namespace

Verdict verdict_of(IntegrationStatus status, int l_Delta) {
  if (status != IntegrationStatus::success) return Verdict::failed;
  return l_Delta >= 3 ? Verdict::unstable : Verdict::stable;
}

PointResult run_point(const Scene& base, const SimulationOptions& options, const DiagramSpec& spec, std::size_t index) {
  const Scene scene = point_scene(base, spec, index);
  SimulationOptions o = options;
  o.record_trajectory = false;
  // The final classifier reads no tail means; the tail classifier reads them, not oscillating, so quadratures
  // give them without the fine grid. The auto classifier (its l_Delta depends on oscillating) and the
  // full-horizon reference keep the grid.
  if (options.tail_means == TailMeans::grid && !options.full_horizon) {
    if (spec.classifier == Classifier::final) o.tail_means = TailMeans::none;
    if (spec.classifier == Classifier::tail_mean && !is_implicit(options.integrator.stepper))
      o.tail_means = TailMeans::quadrature;
  }
  const SimulationResult r = simulate_certified(scene, o);
  PointResult p;
  p.index = index;
  p.i = int(index % std::size_t(spec.x.count));
  p.j = int(index / std::size_t(spec.x.count));
  p.x = spec.x.value(p.i);
  p.y = spec.y.value(p.j);
  const bool tail =
      spec.classifier == Classifier::tail_mean || (spec.classifier == Classifier::automatic && r.oscillating);
  std::tie(p.l_Delta, p.growth) = argmax_growth(tail ? r.Delta_tail_mean : r.Delta_final, r.Delta_initial);
  p.oscillating = r.oscillating;
  p.sigma_final = r.sigma_final;
  p.status = r.status;
  p.reason = r.reason;
  p.t_reached = r.t_reached;
  p.steps = r.counters.steps;
  p.failed_steps = r.counters.failed_steps;
  p.rhs_evaluations = r.counters.rhs_evaluations;
  p.seconds = r.seconds;
  if (r.early.terminated) {
    p.terminated_at = r.early.terminated_at;
    p.margin = r.early.margin;
  }
  p.verdict = verdict_of(p.status, p.l_Delta);
  return p;
}

std::string config_hash(const Scene& base, const SimulationOptions& options, const DiagramSpec& spec) {
  std::ostringstream text;
  SceneFile f{base, options};
  f.scene.name = "";                     // the label does not change any number
  f.options.integrator.max_seconds = 0;  // a wall-clock budget is not part of the configuration
  text << to_toml(f) << "x " << to_string(spec.x.axis) << ' ' << exact(spec.x.min) << ' ' << exact(spec.x.max) << ' '
       << spec.x.count << "\ny " << to_string(spec.y.axis) << ' ' << exact(spec.y.min) << ' ' << exact(spec.y.max)
       << ' ' << spec.y.count << "\nclassifier " << to_string(spec.classifier) << "\nalpha " << exact(spec.alpha)
       << "\n";
  return fnv1a_hex(text.str());
}

DiagramRun run_diagram(const Scene& base, const SimulationOptions& options, const DiagramSpec& spec,
                       const DiagramOptions& run_options) {
  validate_plane(base, spec);
  run_options.validate();
  options.validate();
  const auto t_start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count(); };

  // Every point's scene is checked before any work, so bad input fails fast and whole.
  std::vector<std::size_t> mine;
  for (std::size_t idx = 0; idx < spec.size(); ++idx)
    if (run_options.shard.contains(idx)) {
      try {
        point_scene(base, spec, idx).validate();
      } catch (const InvalidArgument& e) {
        throw InvalidArgument(e.parameter(), std::string(e.what()) + " (at diagram point " + std::to_string(idx) + ")");
      }
      mine.push_back(idx);
    }

  DiagramRun run;
  run.config_hash = config_hash(base, options, spec);
  std::unique_ptr<detail::Journal> journal;
  if (!run_options.journal.empty()) {
    journal = std::make_unique<detail::Journal>(run_options.journal, run.config_hash, spec, base.L,
                                                run_options.sync_interval);
    run.rejected = journal->rejected();
  }

  std::map<std::size_t, PointResult> results;
  std::vector<std::size_t> pending;
  for (std::size_t idx : mine) {
    if (journal) {
      auto it = journal->finished().find(idx);
      if (it != journal->finished().end()) {
        results.emplace(idx, it->second);
        continue;
      }
    }
    pending.push_back(idx);
  }
  run.resumed = results.size();

  std::mutex mutex;
  std::condition_variable cv;
  std::size_t computed = 0, running = 0;
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  int nthreads =
      run_options.threads == 0 ? int(std::max(1u, std::thread::hardware_concurrency())) : run_options.threads;
  nthreads = int(std::min<std::size_t>(std::size_t(nthreads), std::max<std::size_t>(1, pending.size())));
  auto stopped = [&] { return run_options.stop && run_options.stop->load(); };

  auto worker = [&](int w) {
    std::size_t k_static = std::size_t(w);
    for (;;) {
      std::size_t k;
      if (run_options.dynamic_schedule) {
        k = next.fetch_add(1);
      } else {
        k = k_static;
        k_static += std::size_t(nthreads);
      }
      if (k >= pending.size() || stopped()) break;
      {
        std::lock_guard lock(mutex);
        if (error) break;
      }
      try {
        PointResult p = run_point(base, options, spec, pending[k]);
        std::lock_guard lock(mutex);
        if (journal) journal->append(p);
        results.emplace(p.index, std::move(p));
        ++computed;
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
      }
      cv.notify_all();
    }
    std::lock_guard lock(mutex);
    --running;
    cv.notify_all();
  };

  std::vector<std::thread> pool;
  running = std::size_t(nthreads);
  for (int w = 0; w < nthreads; ++w) pool.emplace_back(worker, w);
  {
    std::unique_lock lock(mutex);
    auto report = [&] {
      if (!run_options.on_progress) return;
      Progress pr;
      pr.done = results.size();
      pr.total = mine.size();
      pr.resumed = run.resumed;
      pr.elapsed = elapsed();
      pr.rate = pr.elapsed > 0 ? double(computed) / pr.elapsed : 0;
      pr.eta = pr.rate > 0 ? double(pr.total - pr.done) / pr.rate : 0;
      lock.unlock();
      run_options.on_progress(pr);
      lock.lock();
    };
    double last_report = 0;
    while (running > 0) {
      cv.wait_for(lock, std::chrono::duration<double>(run_options.progress_interval));
      if (running > 0 && elapsed() - last_report >= run_options.progress_interval) {
        last_report = elapsed();
        report();
      }
    }
    report();
  }
  for (auto& t : pool) t.join();
  if (journal) journal->sync();
  if (error) std::rethrow_exception(error);

  run.computed = computed;
  run.points.reserve(results.size());
  for (auto& [idx, p] : results) run.points.push_back(std::move(p));
  run.complete = run.points.size() == mine.size();
  run.seconds = elapsed();
  return run;
}

}  // namespace rbcstab
