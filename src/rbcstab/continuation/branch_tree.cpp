// Recursive branch switching on one problem: the dispatch of special points to switchers, the duplicate and
// symmetry checks of an emanating branch's first point, and the breadth-first growth of the tree.
#include "rbcstab/continuation/branch_tree.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/continuation/autonomous_orbit.hpp"
#include "rbcstab/continuation/dense.hpp"
#include "rbcstab/continuation/orbit_switch.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

Eigen::VectorXd packed(const Eigen::VectorXd& x, double p) {
  Eigen::VectorXd X(x.size() + 1);
  X << x, p;
  return X;
}

double max_norm_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>();
}

bool same_point(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double tol) {
  return a.size() == b.size() && max_norm_distance(a, b) <= tol * (1 + a.lpNorm<Eigen::Infinity>());
}

template <class Orbit>
bool same_shooting(const Orbit& a, const Orbit& b) {
  return &a.system() == &b.system() && a.segments() == b.segments() && a.options().rtol == b.options().rtol &&
         a.options().atol == b.options().atol;
}

// Whether two problems solve the same equations in the same unknowns, so that their branches can be compared point
// by point: the same object, or orbit problems that HB or PD switches built separately (each brings its own) on one
// system with the same shooting (segments, tolerances), phase component (autonomous) and periods (forced).
bool same_equations(const ContinuationProblem& a, const ContinuationProblem& b) {
  if (&a == &b) return true;
  const auto *aa = dynamic_cast<const AutonomousOrbitProblem*>(&a),
             *ab = dynamic_cast<const AutonomousOrbitProblem*>(&b);
  if (aa && ab) return same_shooting(*aa, *ab) && aa->phase_component() == ab->phase_component();
  const auto *fa = dynamic_cast<const PeriodicOrbitProblem*>(&a), *fb = dynamic_cast<const PeriodicOrbitProblem*>(&b);
  return fa && fb && same_shooting(*fa, *fb) && fa->periods() == fb->periods();
}

// Two orbit problems on one system with the same shooting that may represent one orbit differently: another phase
// component, or the same one (an orbit has two extrema of each component).
const AutonomousOrbitProblem* other_representation(const ContinuationProblem& a, const ContinuationProblem& b) {
  const auto *aa = dynamic_cast<const AutonomousOrbitProblem*>(&a),
             *ab = dynamic_cast<const AutonomousOrbitProblem*>(&b);
  return aa && ab && same_shooting(*aa, *ab) ? aa : nullptr;
}

// The orbit X of problem b at p in problem a's representation: each point of the orbit where a's phase condition
// f_k(x, p) = 0 holds (a sign change among kRephaseSamples states along it, the nearer one taken), its segment
// starts sampled from there (shooting_guess) and corrected by Newton on a's equations at the same p. The samples
// bound the start's phase error by T / kRephaseSamples, well inside Newton's reach for a smooth orbit.
constexpr int kRephaseSamples = 64;
std::vector<Eigen::VectorXd> rephased(const AutonomousOrbitProblem& a, const AutonomousOrbitProblem& b,
                                      const Eigen::VectorXd& X, double p) {
  const Eigen::Index n = a.system().dimension();
  const double T = AutonomousOrbitProblem::period(X);
  std::vector<Eigen::VectorXd> out;
  if (!(std::isfinite(T) && T > 0)) return out;
  OrbitOptions fine_options = a.options();
  fine_options.segments = kRephaseSamples;
  const AutonomousOrbitProblem fine(a.system(), a.phase_component(), fine_options);
  const Eigen::VectorXd S = fine.shooting_guess(b.state_at_zero(X), T, p);
  std::vector<double> g(kRephaseSamples);
  Eigen::VectorXd f(n);
  for (int j = 0; j < kRephaseSamples; ++j) {
    a.system().rhs(std::span<const double>(S.data() + j * n, static_cast<std::size_t>(n)), p,
                   std::span<double>(f.data(), static_cast<std::size_t>(n)));
    g[static_cast<std::size_t>(j)] = f[a.phase_component()];
  }
  Eigen::VectorXd along = Eigen::VectorXd::Zero(a.dimension() + 1);
  along[a.dimension()] = 1;  // Newton at fixed p: on the hyperplane p = const
  for (int j = 0; j < kRephaseSamples; ++j) {
    const int next = (j + 1) % kRephaseSamples;
    const double g0 = g[static_cast<std::size_t>(j)], g1 = g[static_cast<std::size_t>(next)];
    if (g0 != 0 && (g0 > 0) == (g1 > 0)) continue;
    const int at = std::abs(g0) <= std::abs(g1) ? j : next;
    const Eigen::VectorXd x0 = S.segment(at * n, n);
    Eigen::VectorXd Y = packed(a.shooting_guess(x0, T, p), p);
    const Eigen::VectorXd base = Y;
    if (newton_on_hyperplane(a, base, along, 0.0, 1e-12, 30, Y)) out.push_back(std::move(Y));
  }
  return out;
}

std::vector<EmanatingStart> bp_switcher(const ContinuationProblem& problem, const Branch& branch,
                                        const SpecialPoint& bp, const BranchSwitchOptions& options) {
  std::vector<EmanatingStart> out;
  for (int side : {1, -1}) {
    BranchSwitchOptions o = options;
    o.side = side;
    BranchSwitchStart s = switch_start(problem, branch, bp, o);
    EmanatingStart e;
    e.found = s.found;
    e.message = std::move(s.message);
    e.side = side;
    e.x = std::move(s.x);
    e.p = s.p;
    e.away = s.away;
    out.push_back(std::move(e));
  }
  return out;
}

// HB and PD: the one orbit branch born there (its other "half" is the same orbit shifted in phase), side +1.
Switcher orbit_switcher(const OrbitOptions& orbit) {
  return [orbit](const ContinuationProblem& problem, const Branch& branch, const SpecialPoint& sp,
                 const BranchSwitchOptions& options) {
    OrbitSwitchOptions o;
    o.amplitude = options.amplitude;
    o.max_newton = options.max_newton;
    o.orbit = orbit;
    o.continuation = options.continuation;
    OrbitSwitchStart s = orbit_switch_start(problem, branch, sp, o);
    EmanatingStart e;
    e.found = s.found;
    e.refused = s.refused;
    e.message = std::move(s.message);
    e.side = s.refused ? 0 : 1;  // a refusal concerns the point, not one of its branches
    e.x = std::move(s.x);
    e.p = s.p;
    e.away = s.away;
    e.problem = std::move(s.problem);
    e.rotating_wave_of = s.rotating_wave_of;
    return std::vector<EmanatingStart>{std::move(e)};
  };
}

// Why a branching type has no switcher (the text of its not_available outcome).
std::string no_switcher_text(SpecialPointType type) {
  if (type == SpecialPointType::NS)
    return "switching at NS is not available: an NS point starts an invariant torus, and tori are not continued";
  return "switching at " + std::string(to_string(type)) + " is not available";
}

constexpr const char* kClosedMessage = "closed: back at its first point";

// One emanating branch continued from its start, away from its point, with the tree's engine options and events.
Branch follow(const ContinuationProblem& child_problem, const EmanatingStart& s, const TreeOptions& options) {
  ContinuationOptions o = options.switching.continuation;
  o.direction = s.away;
  if (options.events)
    for (UserEvent& e : options.events(s.x, s.p)) o.events.push_back(std::move(e));
  // A closed branch (a loop through BPs) comes back through its first point: it ends there instead of going
  // round to max_points. Its chord passes within the sagitta bound (a tangent turn <= 60 degrees per step)
  // of the first point, once it has gone farther than the switching amplitude.
  struct Loop {
    Eigen::VectorXd X0, prev;
    double travelled = 0;
    bool closed = false;
  };
  const auto loop = std::make_shared<Loop>(Loop{packed(s.x, s.p), packed(s.x, s.p)});
  const double far = 4 * options.switching.amplitude;
  const auto returned = [loop, far](const Eigen::VectorXd& x, double p) {
    const Eigen::VectorXd X = packed(x, p), d = X - loop->prev;
    const double len = d.norm();
    const double at = len > 0 ? std::clamp(d.dot(loop->X0 - loop->prev) / (len * len), 0.0, 1.0) : 0.0;
    loop->closed = loop->closed || (loop->travelled > far && (loop->prev + at * d - loop->X0).norm() <= 0.15 * len);
    loop->travelled += len;
    loop->prev = X;
    return loop->closed;
  };
  auto user_stop = o.stop;
  o.stop = [flag = options.stop, user_stop, returned](const Eigen::VectorXd& x, double p) {
    return (flag && flag->load()) || returned(x, p) || (user_stop && user_stop(x, p));
  };
  Branch child = continue_branch(child_problem, s.x, s.p, o);
  if (loop->closed) child.message = kClosedMessage;
  return child;
}

}  // namespace

std::map<SpecialPointType, Switcher> default_switchers(const OrbitOptions& hb_orbit) {
  return {{SpecialPointType::BP, bp_switcher},
          {SpecialPointType::HB, orbit_switcher(hb_orbit)},
          {SpecialPointType::PD, orbit_switcher(hb_orbit)}};
}

bool is_branching(SpecialPointType type) {
  return type == SpecialPointType::BP || type == SpecialPointType::HB || type == SpecialPointType::PD ||
         type == SpecialPointType::NS;
}

void TreeOptions::validate() const {
  require(depth >= 0 && depth <= 20, "depth", depth, "an integer in [0, 20]");
  switching.validate();
  require(std::isfinite(duplicate_tol) && duplicate_tol > 0 && duplicate_tol <= switching.amplitude / 10,
          "duplicate_tol", duplicate_tol, "in (0, amplitude / 10 = " + format_value(switching.amplitude / 10) + "]");
  require(max_branches >= 1 && max_branches <= 10000, "max_branches", static_cast<double>(max_branches),
          "an integer in [1, 10000]");
}

bool lies_on(const ContinuationProblem& problem, const Branch& b, const Eigen::VectorXd& X, double tol) {
  const auto& pts = b.points;
  if (pts.empty() || pts.front().x.size() + 1 != X.size()) return false;
  // The nearest segment [A, A + u] of the polyline (2-norm), and the foot of X on it.
  double best = std::numeric_limits<double>::infinity(), along = 0;
  Eigen::VectorXd foot, A, u;
  for (std::size_t k = 0; k + 1 < std::max<std::size_t>(pts.size(), 2); ++k) {
    Eigen::VectorXd a = packed(pts[k].x, pts[k].p);
    const Eigen::VectorXd d =
        pts.size() > 1 ? Eigen::VectorXd(packed(pts[k + 1].x, pts[k + 1].p) - a) : Eigen::VectorXd::Zero(X.size());
    const double dd = d.squaredNorm();
    const double s = dd > 0 ? std::clamp(d.dot(X - a) / dd, 0.0, 1.0) : 0.0;
    const Eigen::VectorXd f = a + s * d;
    const double dist = (X - f).norm();
    if (dist < best) best = dist, foot = f, along = s * std::sqrt(dd), A = std::move(a), u = d;
  }
  if (same_point(X, foot, tol)) return true;
  // A curve between two accepted points (its tangent turns by <= 60 degrees per step) stays within half a chord
  // of it: farther away, X is on another curve.
  const double length = u.norm();
  if (!(length > 0) || best > 0.5 * length) return false;
  // Nearer, the branch is followed from its point A along the chord to the hyperplane through X normal to it
  // (which holds the foot), in steps that shrink by 4 towards it: near a BP close to X another branch crosses
  // within ~ the distance to the BP, so Newton from the chord's foot alone could land on either.
  const Eigen::VectorXd t = u / length;
  Eigen::VectorXd Y = A;
  const auto correct = [&](double at) { return newton_on_hyperplane(problem, A, t, at, 1e-12, 30, Y); };
  const double last = 100 * tol * (1 + X.lpNorm<Eigen::Infinity>());
  double at = 0;
  for (double rest = along; rest > 0;) {
    rest = rest > last ? rest / 4 : 0.0;
    Y += (along - rest - at) * t;  // predictor along the chord
    at = along - rest;
    if (!correct(at)) return false;
  }
  return same_point(X, Y, tol);
}

BranchTree grow_tree(const ContinuationProblem& root_problem, Branch root, const TreeOptions& options) {
  options.validate();
  BranchTree tree;
  tree.branches.push_back({std::move(root), nullptr, -1, -1, 0, 0});
  const auto problem_of = [&](int k) -> const ContinuationProblem& {
    const auto& p = tree.branches[static_cast<std::size_t>(k)].problem;
    return p ? *p : root_problem;
  };
  const auto stopped = [&] { return options.stop && options.stop->load(); };
  tree.interrupted = stopped();
  // The branching points switched at so far: (branch, special point).
  std::vector<std::pair<int, std::size_t>> switched_at;
  const auto mark = [&](int b, std::size_t j, int side, EmanationOutcome o, int to = -1, int pt = -1,
                        std::string message = "") {
    tree.emanations.push_back({b, j, side, o, to, pt, std::move(message)});
  };
  // The earlier point (or its symmetric image) this one repeats: (branch, index), or (-1, -1).
  const auto seen_before = [&](int b, const SpecialPoint& sp) -> std::pair<int, std::size_t> {
    const Eigen::VectorXd X = packed(sp.x, sp.p);
    for (const auto& [k, j] : switched_at) {
      const SpecialPoint& q = tree.branches[static_cast<std::size_t>(k)].branch.special_points[j];
      if (q.type != sp.type || !same_equations(problem_of(k), problem_of(b))) continue;
      // HBs (PDs, NSs) at one point with different critical values are different points (the l >= 3 onset's pairs
      // i m / 2): each is switched at, or refused, on its own.
      if (sp.type != SpecialPointType::BP &&
          std::abs(q.eigenvalue - sp.eigenvalue) > options.duplicate_tol * (1 + std::abs(sp.eigenvalue)))
        continue;
      const Eigen::VectorXd Q = packed(q.x, q.p);
      if (same_point(Q, X, options.duplicate_tol)) return {k, j};
      for (const auto& g : options.symmetries)
        if (same_point(Q, packed(g(sp.x), sp.p), options.duplicate_tol)) return {k, j};
    }
    return {-1, 0};
  };
  // The earlier branch a start lies on (duplicate) or that a symmetry maps it onto (symmetric), never the
  // branch it leaves: that one passes within the switching amplitude, through the BP where both cross.
  const auto covered = [&](int from, const EmanatingStart& s, const ContinuationProblem& pr) {
    const Eigen::VectorXd X = packed(s.x, s.p);
    for (std::size_t k = 0; k < tree.branches.size(); ++k) {
      if (static_cast<int>(k) == from) continue;
      const ContinuationProblem& earlier = problem_of(static_cast<int>(k));
      if (same_equations(earlier, pr) && lies_on(pr, tree.branches[k].branch, X, options.duplicate_tol))
        return std::pair{EmanationOutcome::duplicate, static_cast<int>(k)};
      // The same orbit in another phase representation: compared in the earlier problem's.
      if (const AutonomousOrbitProblem* a = other_representation(earlier, pr))
        for (const Eigen::VectorXd& Y : rephased(*a, dynamic_cast<const AutonomousOrbitProblem&>(pr), s.x, s.p))
          if (lies_on(*a, tree.branches[k].branch, Y, options.duplicate_tol))
            return std::pair{EmanationOutcome::duplicate, static_cast<int>(k)};
    }
    for (const auto& g : options.symmetries) {
      const Eigen::VectorXd gX = packed(g(s.x), s.p);
      for (std::size_t k = 0; k < tree.branches.size(); ++k)
        if (static_cast<int>(k) != from && same_equations(problem_of(static_cast<int>(k)), pr) &&
            lies_on(pr, tree.branches[k].branch, gX, options.duplicate_tol))
          return std::pair{EmanationOutcome::symmetric, static_cast<int>(k)};
    }
    return std::pair{EmanationOutcome::followed, -1};
  };
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    const int b = static_cast<int>(i);
    const std::size_t n_special = tree.branches[i].branch.special_points.size();
    for (std::size_t j = 0; j < n_special; ++j) {
      const SpecialPoint sp = tree.branches[i].branch.special_points[j];  // a copy: branches grows below
      if (!is_branching(sp.type)) continue;
      if (tree.interrupted) {
        mark(b, j, 0, EmanationOutcome::interrupted);
        continue;
      }
      if (sp.status != LocationStatus::located) {
        mark(b, j, 0, EmanationOutcome::not_located, -1, -1, "not located: its bracket did not converge");
        continue;
      }
      if (const auto [k, jj] = seen_before(b, sp); k >= 0) {
        mark(b, j, 0, EmanationOutcome::already_switched, k, static_cast<int>(jj));
        continue;
      }
      if (tree.branches[i].depth >= options.depth) {
        mark(b, j, 0, EmanationOutcome::depth_limit);
        continue;
      }
      const auto sw = options.switchers.find(sp.type);
      if (sw == options.switchers.end() || !sw->second) {
        mark(b, j, 0, EmanationOutcome::not_available, -1, -1, no_switcher_text(sp.type));
        continue;
      }
      switched_at.emplace_back(b, j);
      const ContinuationProblem& pr = problem_of(b);
      int closed_sibling = -1;
      for (EmanatingStart& s : sw->second(pr, tree.branches[i].branch, sp, options.switching)) {
        if (!s.found && s.refused && s.rotating_wave_of >= 0) {
          mark(b, j, s.side, EmanationOutcome::rotating_wave, -1, s.rotating_wave_of, s.message);
          continue;
        }
        if (!s.found) {
          mark(b, j, s.side, s.refused ? EmanationOutcome::not_available : EmanationOutcome::failed, -1, -1, s.message);
          continue;
        }
        if (tree.interrupted || stopped()) {
          tree.interrupted = true;
          mark(b, j, s.side, EmanationOutcome::interrupted);
          continue;
        }
        if (tree.branches.size() >= options.max_branches) {
          mark(b, j, s.side, EmanationOutcome::branch_limit);
          continue;
        }
        const ContinuationProblem& child_problem = s.problem ? *s.problem : pr;
        // A closed branch from this point came back through it: the other half is the same loop.
        if (closed_sibling >= 0 && !s.problem) {
          mark(b, j, s.side, EmanationOutcome::duplicate, closed_sibling);
          continue;
        }
        if (const auto [outcome, k] = covered(b, s, child_problem); outcome != EmanationOutcome::followed) {
          mark(b, j, s.side, outcome, k);
          continue;
        }
        const std::size_t k = tree.branches.size();
        TreeBranch t{{},     s.problem ? s.problem : tree.branches[i].problem,
                     b,      static_cast<int>(j),
                     s.side, tree.branches[i].depth + 1,
                     false};
        if (!(options.recall && options.recall(k, t))) {
          t.branch = follow(child_problem, s, options);
          t.closed = t.branch.message == kClosedMessage;
          if (stopped()) {
            tree.interrupted = true;
            t.branch.message = "interrupted after " + std::to_string(t.branch.points.size()) + " points";
          } else if (options.on_followed) {
            options.on_followed(k, t);
          }
        }
        const bool closed = t.closed;
        tree.branches.push_back(std::move(t));
        if (closed) closed_sibling = static_cast<int>(k);
        mark(b, j, s.side, EmanationOutcome::followed, static_cast<int>(k));
        if (options.on_branch) options.on_branch(tree.branches.size(), tree.branches.size() - i - 1);
      }
    }
  }
  // A rotating wave's branch: the one followed (or found before) from its special point, whichever half.
  for (TreeEmanation& e : tree.emanations) {
    if (e.outcome != EmanationOutcome::rotating_wave) continue;
    for (const TreeEmanation& f : tree.emanations)
      if (f.branch == e.branch && static_cast<int>(f.point) == e.point_to && f.branch_to >= 0 &&
          (f.outcome == EmanationOutcome::followed || f.outcome == EmanationOutcome::duplicate ||
           f.outcome == EmanationOutcome::symmetric)) {
        e.branch_to = f.branch_to;
        if (f.outcome == EmanationOutcome::followed) break;
      }
  }
  return tree;
}

}  // namespace rbcstab
