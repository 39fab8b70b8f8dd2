#include "rbcstab/inverse/fit.hpp"

#include <Eigen/Dense>
#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "rbcstab/continuation/complementarity.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/inverse/detail/profile_refit.hpp"

namespace rbcstab {

namespace {

using Ipopt::Index;
using Ipopt::Number;

bool numeric(const ObservedRow& o) { return o.observable != Observable::regime; }

using detail::cell_at;
using detail::residuals_at;

std::vector<FitParameterInfo> infos_of(std::span<const FitParameter> free, const CellModel& cell) {
  std::vector<FitParameterInfo> info;
  for (FitParameter q : free) info.push_back(fit_parameter_info(q, cell));
  return info;
}

std::vector<double> coordinates(const CellModel& cell, std::span<const FitParameterInfo> info) {
  std::vector<double> x;
  for (const FitParameterInfo& i : info) {
    const double v = get_value(cell, i.id);
    x.push_back(i.log_scale ? std::log(v) : v);
  }
  return x;
}

double coordinate_bound(const FitParameterInfo& i, double v) {
  if (i.log_scale) return v > 0 ? std::log(v) : -1e19;
  return std::isfinite(v) ? v : (v > 0 ? 1e19 : -1e19);
}

// FitOptions::stop and on_progress for one fit: the counts so far, reported after each Ipopt iteration, start and
// profile point; the stop flag read at the same places.
class FitMonitor {
 public:
  explicit FitMonitor(const FitOptions& o) : stop_(o.stop), on_progress_(o.on_progress) { p_.starts = o.starts; }
  bool stopped() const { return stop_ && stop_->load(); }
  bool iteration() {  // false: stop the solve
    ++p_.iterations;
    report();
    return !stopped();
  }
  void start_done() {
    ++p_.starts_done;
    report();
  }
  void profile_point_done() {
    ++p_.profile_points;
    report();
  }

 private:
  void report() const {
    if (on_progress_) on_progress_(p_);
  }
  const std::atomic<bool>* stop_;
  const std::function<void(const FitProgress&)>& on_progress_;
  FitProgress p_;
};

// 1/2 chi^2 over the numeric rows: Ipopt's NLP with the Gauss-Newton Hessian J^T J (exact up to the residuals'
// curvature, which vanishes at a zero-residual fit and is what the Fisher information uses too).
class LeastSquaresNlp final : public Ipopt::TNLP {
 public:
  LeastSquaresNlp(std::vector<ObservedRow> rows, std::vector<FitParameter> free, const CellModel& cell,
                  const FitOptions& options, std::vector<double> start, int held, FitMonitor* monitor,
                  std::vector<RegimeConstraint> constraints = {})
      : rows_(std::move(rows)),
        free_(std::move(free)),
        cell_(cell),
        options_(options),
        info_(infos_of(free_, cell)),
        start_(std::move(start)),
        held_(held),
        monitor_(monitor),
        constraints_(std::move(constraints)) {}

  std::vector<double> solution, multipliers;
  Ipopt::SolverReturn solver_status = Ipopt::UNASSIGNED;
  int evaluations = 0;

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag, IndexStyleEnum& index_style) override {
    n = static_cast<Index>(free_.size());
    m = static_cast<Index>(constraints_.size());
    nnz_jac_g = m * n;
    nnz_h_lag = n * (n + 1) / 2;
    index_style = TNLP::C_STYLE;
    return true;
  }
  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l, Number* g_u) override {
    for (Index k = 0; k < m; ++k) g_l[k] = 0, g_u[k] = 1e19;  // regime margins >= 0
    for (Index j = 0; j < n; ++j) {
      x_l[j] = coordinate_bound(info_[j], info_[j].lo);
      x_u[j] = coordinate_bound(info_[j], info_[j].hi);
      // A profile's held coordinate: equal bounds, which Ipopt turns into a parameter (fixed_variable_treatment).
      if (j == held_) x_l[j] = x_u[j] = start_[j];
    }
    return true;
  }
  bool get_starting_point(Index n, bool, Number* x, bool, Number*, Number*, Index, bool, Number*) override {
    for (Index j = 0; j < n; ++j) x[j] = start_[j];
    return true;
  }
  bool eval_f(Index n, const Number* x, bool, Number& f) override {
    if (!update(n, x, false)) return false;
    f = 0;
    for (double v : lin_.r) f += 0.5 * v * v;
    return true;
  }
  bool eval_grad_f(Index n, const Number* x, bool, Number* g) override {
    if (!update(n, x, true)) return false;
    for (Index j = 0; j < n; ++j) {
      g[j] = 0;
      for (std::size_t i = 0; i < lin_.r.size(); ++i) g[j] += lin_.J[i][j] * lin_.r[i];
    }
    return true;
  }
  bool eval_g(Index n, const Number* x, bool, Index m, Number* g) override {
    if (!update_constraints(n, x)) return false;
    for (Index k = 0; k < m; ++k) g[k] = con_.margin[k];
    return true;
  }
  bool eval_jac_g(Index n, const Number* x, bool, Index m, Index, Index* iRow, Index* jCol, Number* values) override {
    for (Index k = 0, e = 0; k < m; ++k)
      for (Index j = 0; j < n; ++j, ++e) {
        if (values == nullptr) {
          iRow[e] = k;
          jCol[e] = j;
        } else {
          if (e == 0 && !update_constraints(n, x)) return false;
          values[e] = con_.J[k][j];
        }
      }
    return true;
  }
  bool eval_h(Index n, const Number* x, bool, Number obj_factor, Index, const Number*, bool, Index, Index* iRow,
              Index* jCol, Number* values) override {
    Index k = 0;
    if (values == nullptr) {
      for (Index i = 0; i < n; ++i)
        for (Index j = 0; j <= i; ++j) {
          iRow[k] = i;
          jCol[k++] = j;
        }
      return true;
    }
    if (!update(n, x, true)) return false;
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j <= i; ++j) {
        double s = 0;
        for (std::size_t r = 0; r < lin_.r.size(); ++r) s += lin_.J[r][i] * lin_.J[r][j];
        values[k++] = obj_factor * s;
      }
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number*, const Number*, Index m,
                         const Number*, const Number* lambda, Number, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    solver_status = status;
    solution.assign(x, x + n);
    multipliers.assign(lambda, lambda + m);
  }
  bool intermediate_callback(Ipopt::AlgorithmMode, Index, Number, Number, Number, Number, Number, Number, Number,
                             Number, Index, const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    return monitor_ == nullptr || monitor_->iteration();
  }

 private:
  // The residuals (and the Jacobian when asked) at x, cached for the last x.
  bool update(Index n, const Number* x, bool with_jacobian) {
    const std::vector<double> at(x, x + n);
    if (at == x_ && (have_J_ || !with_jacobian)) return lin_.ok;
    x_ = at;
    have_J_ = with_jacobian;
    ++evaluations;
    if (with_jacobian) {
      lin_ = linearise(rows_, free_, cell_at(cell_, info_, at), options_, options_.fd_step);
    } else {
      lin_ = {};
      lin_.ok = residuals_at(rows_, cell_at(cell_, info_, at), options_.forward, lin_.r, lin_.reason);
    }
    return lin_.ok;
  }
  // The regime margins and their Jacobian at x (inverse/constraints.hpp), cached for the last x.
  bool update_constraints(Index n, const Number* x) {
    const std::vector<double> at(x, x + n);
    if (at == con_x_) return con_.ok;
    con_x_ = at;
    con_ = constraint_values(constraints_, free_, cell_at(cell_, info_, at), options_.forward, options_.fd_step);
    return con_.ok;
  }
  std::vector<ObservedRow> rows_;
  std::vector<FitParameter> free_;
  CellModel cell_;
  FitOptions options_;
  std::vector<FitParameterInfo> info_;
  std::vector<double> start_;
  Index held_;
  FitMonitor* monitor_;
  std::vector<double> x_;
  bool have_J_ = false;
  Linearisation lin_;
  std::vector<RegimeConstraint> constraints_;
  std::vector<double> con_x_;
  ConstraintValues con_;
};

FitStatus status_of(Ipopt::ApplicationReturnStatus s) {
  switch (s) {
    case Ipopt::Solve_Succeeded:
    case Ipopt::Solved_To_Acceptable_Level:
      return FitStatus::converged;
    case Ipopt::Infeasible_Problem_Detected:
      return FitStatus::infeasible;
    case Ipopt::Maximum_Iterations_Exceeded:
    case Ipopt::Maximum_CpuTime_Exceeded:
      return FitStatus::maximum_iterations;
    case Ipopt::User_Requested_Stop:  // FitOptions::stop, the only user stop
      return FitStatus::interrupted;
    default:
      return FitStatus::failed;
  }
}

std::string coordinate_name(const FitParameterInfo& i) { return i.log_scale ? "ln " + i.name : i.name; }

double chi2_of(std::span<const double> r) {
  double c = 0;
  for (double v : r) c += v * v;
  return c;
}

// One Ipopt solve from `start` (coordinate `held` fixed at its start when >= 0) and chi^2 at its end.
struct Solve {
  FitStatus status = FitStatus::failed;
  std::string ipopt_status;
  std::vector<double> end;
  double chi2 = kNotGiven;
  int iterations = 0, evaluations = 0;
  std::vector<double> multipliers;  // of the regime constraints
};
Solve solve(const std::vector<ObservedRow>& rows, const std::vector<FitParameter>& free, const CellModel& cell,
            const FitOptions& options, const std::vector<double>& start, int held, FitMonitor& monitor,
            const std::vector<RegimeConstraint>& constraints = {}) {
  Solve out;
  Ipopt::SmartPtr<LeastSquaresNlp> nlp =
      new LeastSquaresNlp(rows, free, cell, options, start, held, &monitor, constraints);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetNumericValue("tol", options.tol);
  app->Options()->SetIntegerValue("max_iter", options.max_iterations);
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");  // no banner: only apps/ print
  if (held >= 0) {
    // A profile point starts at its neighbour's optimum: a small initial barrier and bound push keep Ipopt there
    // instead of first pushing the point into the interior and walking the barrier down from 0.1.
    app->Options()->SetNumericValue("mu_init", 1e-7);
    app->Options()->SetNumericValue("bound_push", 1e-9);
    app->Options()->SetNumericValue("bound_frac", 1e-9);
  }
  if (app->Initialize() != Ipopt::Solve_Succeeded) {
    out.ipopt_status = "Ipopt could not be initialised";
    out.end = start;
    return out;
  }
  const Ipopt::ApplicationReturnStatus rs = app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(GetRawPtr(nlp)));
  out.evaluations = nlp->evaluations;
  out.status = status_of(rs);
  out.ipopt_status = ipopt_status_name(static_cast<int>(rs));
  if (Ipopt::IsValid(app->Statistics())) out.iterations = app->Statistics()->IterationCount();
  out.end = nlp->solution.empty() ? start : nlp->solution;
  out.multipliers = nlp->multipliers;
  std::vector<double> r;
  std::string why;
  if (!nlp->solution.empty() &&
      residuals_at(rows, cell_at(cell, infos_of(free, cell), out.end), options.forward, r, why)) {
    out.chi2 = chi2_of(r);
  } else {
    out.status = FitStatus::failed;
    if (!why.empty()) out.ipopt_status += " (" + why + ")";
  }
  return out;
}

// Which observation would pin a flat direction, from what the forward model's observables depend on (docs/inverse.md
// "What would pin a flat direction"): the reduced l = 2 motion holds Lambda(lambda, Delta) and S = C sqrt(15 pi /
// (2 Delta0)), C = eta gamma R / mu, and nothing else.
std::string what_would_pin(const std::vector<FitParameter>& involved) {
  auto has = [&](FitParameter q) { return std::find(involved.begin(), involved.end(), q) != involved.end(); };
  auto only = [&](std::initializer_list<FitParameter> set) {
    return std::all_of(involved.begin(), involved.end(),
                       [&](FitParameter q) { return std::find(set.begin(), set.end(), q) != set.end(); });
  };
  if (has(FitParameter::bending_modulus))
    return "What would pin it: no in-plane observable depends on bending_modulus (B = eta gamma R^3/kappa enters "
           "only the l >= 3 modes, which stay zero for an ellipsoidal cell until a shape instability grows); an "
           "observation of the shape-instability onset or of the excited mode, whose criterion holds B, would, but "
           "this model does not predict it yet; or a direct measurement of kappa (e.g. flicker spectroscopy)";
  if (only({FitParameter::shear_modulus, FitParameter::Delta0, FitParameter::radius}))
    return "What would pin it: these enter the motion only through S = C sqrt(15 pi/(2 Delta0)) with C = eta "
           "gamma R/mu, i.e. through R/(mu sqrt(Delta0)), at every shear rate and viscosity, so no observable of "
           "this model separates them; a direct measurement of the radius (images) or of the shear modulus "
           "(micropipette aspiration, optical tweezers) would, or the shape-instability onset (its criterion holds C "
           "and Delta0 separately), which this model does not "
           "predict yet";
  if (only({FitParameter::lambda, FitParameter::Delta}))
    return "What would pin it: lambda and Delta enter the motion only through Lambda = sqrt(Delta) (23 lambda + "
           "32)/(8 sqrt(30 pi)); with lambda held at one value for every viscosity no observable separates them. "
           "Fitting inner_viscosity instead of lambda with rows at two or more outer viscosities would (lambda = "
           "eta_in/eta then changes with eta at fixed Delta), as would a direct measurement of Delta (the cell's "
           "area and volume)";
  if (only({FitParameter::inner_viscosity, FitParameter::Delta}))
    return "What would pin it: inner_viscosity and Delta enter the motion only through Lambda = sqrt(Delta) (23 "
           "eta_in/eta + 32)/(8 sqrt(30 pi)); rows at two or more outer viscosities separate them, one viscosity "
           "does not";
  return "What would pin it: the flat direction mixes parameters of Lambda(lambda, Delta) and of S; rows at more "
         "shear rates (S is proportional to the shear rate at fixed Lambda) separate the two groups";
}

constexpr double kAtBoundFraction = 1e-3;            // FitEstimate::at_bound: within this fraction of the box's width
constexpr double kChi2OneDof95 = 3.841458820694124;  // the 0.95 quantile of chi^2 with 1 degree of freedom
constexpr double kZ95 = 1.959963984540054;

// Every regime margin at `c` at least kActiveMargin (none: true).
bool regime_margins_clear(const std::vector<RegimeConstraint>& constraints, std::span<const FitParameter> free,
                          const CellModel& c, const ForwardOptions& options) {
  if (constraints.empty()) return true;
  const ConstraintValues v = constraint_values(constraints, free, c, options, 0.0);
  return v.ok && std::all_of(v.margin.begin(), v.margin.end(), [](double m) { return m >= kActiveMargin; });
}

// The profile of coordinate j through the estimate xhat (chi^2 = chi2_min): a side walks outward on the grid
// (span * se / points per step within the span, then doubling steps to the bound; a flat parameter: points steps
// to the bound), each point re-optimised from its neighbour's optimum; between the last point below 3.84 and the
// first above, the crossing is found by the Illinois secant to |Delta chi^2 - 3.84| < 1e-3.
Profile profile_of(const std::vector<ObservedRow>& rows, const std::vector<FitParameter>& free, const CellModel& cell,
                   const FitOptions& options, std::span<const FitParameterInfo> info, std::span<const double> lo,
                   std::span<const double> hi, const std::vector<double>& xhat, double chi2_min, std::size_t j,
                   double se, int& evaluations, FitMonitor& monitor, const std::vector<RegimeConstraint>& constraints) {
  Profile p;
  p.computed = true;
  const ProfileOptions& po = options.profiles;
  struct Point {
    double delta = kNotGiven;
    std::vector<double> x;
    bool ok = false;
    std::string why;
  };
  auto at = [&](double value, const std::vector<double>& warm) {
    Point q;
    q.x = warm;
    q.x[j] = value;
    if (monitor.stopped()) {
      q.why = "interrupted";
      return q;
    }
    ++p.solves;
    if (free.size() == 1) {
      std::vector<double> r;
      ++evaluations;
      q.ok = residuals_at(rows, cell_at(cell, info, q.x), options.forward, r, q.why);
      if (q.ok) q.delta = chi2_of(r) - chi2_min;
      monitor.profile_point_done();
      return q;
    }
    if (po.method == ProfileMethod::gauss_newton) {
      const detail::LeastSquaresRefit g = detail::least_squares_refit(
          rows, free, cell, options, q.x, static_cast<int>(j), lo, hi, [&] { return monitor.iteration(); });
      evaluations += g.evaluations;
      p.iterations += g.iterations;
      // Kept unless a regime row is active or violated there: then Ipopt re-fits with the constraints.
      if (g.converged && std::isfinite(g.chi2) &&
          regime_margins_clear(constraints, free, cell_at(cell, info, g.x), options.forward)) {
        monitor.profile_point_done();
        q.ok = true;
        q.x = g.x;
        q.delta = g.chi2 - chi2_min;
        return q;
      }
      ++p.fallbacks;
    }
    const Solve s = solve(rows, free, cell, options, q.x, static_cast<int>(j), monitor, constraints);
    monitor.profile_point_done();
    evaluations += s.evaluations;
    p.iterations += s.iterations;
    q.ok = s.status != FitStatus::failed && s.status != FitStatus::interrupted && std::isfinite(s.chi2);
    q.why = s.ipopt_status;
    if (q.ok) {
      q.x = s.end;
      q.delta = s.chi2 - chi2_min;
    }
    return q;
  };
  std::vector<std::pair<double, double>> curve{{xhat[j], 0.0}};
  double ends[2] = {kNotGiven, kNotGiven};
  std::string side_reason[2];
  bool reached[2] = {false, false};  // walked to the bound without crossing
  const bool identifiable = std::isfinite(se) && se > 0;
  for (int side = 0; side < 2; ++side) {
    const double dir = side == 0 ? -1.0 : 1.0;
    const double bound = side == 0 ? lo[j] : hi[j];
    const double room = std::abs(bound - xhat[j]);
    if (room < 1e-12) {
      reached[side] = true;
      continue;
    }
    double step = identifiable ? std::min(po.span * se / po.points, room) : room / po.points;
    Point prev{0.0, xhat, true, ""};
    double travelled = 0;
    for (int k = 0; k < 200 && travelled < room - 1e-12; ++k) {
      if (identifiable && travelled >= po.span * se - 1e-12) step *= 2;
      const double d = std::min(travelled + step, room);
      const Point q = at(xhat[j] + dir * d, prev.x);
      if (!q.ok) {
        side_reason[side] =
            "no fit at " + coordinate_name(info[j]) + " = " + format_value(xhat[j] + dir * d) + " (" + q.why + ")";
        break;
      }
      curve.emplace_back(xhat[j] + dir * d, q.delta);
      if (q.delta >= kChi2OneDof95) {
        // Illinois: regula falsi on g = Delta chi^2 - 3.84 over [travelled, d], the retained end's g halved.
        double a = travelled, ga = prev.delta - kChi2OneDof95, b = d, gb = q.delta - kChi2OneDof95;
        std::vector<double> wa = prev.x, wb = q.x;
        double c = b;
        for (int it = 0; it < 30 && std::abs(gb) > 1e-3 && std::abs(b - a) > 1e-10; ++it) {
          c = b - gb * (b - a) / (gb - ga);
          const Point m = at(xhat[j] + dir * c, wa);
          if (!m.ok) break;
          curve.emplace_back(xhat[j] + dir * c, m.delta);
          const double gc = m.delta - kChi2OneDof95;
          if ((gc > 0) == (gb > 0)) {
            ga *= 0.5;
          } else {
            a = b;
            ga = gb;
            wa = wb;
          }
          b = c;
          gb = gc;
          wb = m.x;
        }
        ends[side] = xhat[j] + dir * b;
        break;
      }
      prev = q;
      travelled = d;
    }
    reached[side] = !std::isfinite(ends[side]) && side_reason[side].empty();
    if (reached[side])
      side_reason[side] = "Delta chi^2 stays below 3.84 up to the " + std::string(side == 0 ? "lower" : "upper") +
                          " bound " + coordinate_name(info[j]) + " = " + format_value(bound);
  }
  std::sort(curve.begin(), curve.end());
  for (const auto& [x, d] : curve) {
    p.coordinate.push_back(x);
    p.delta_chi2.push_back(d);
  }
  auto si = [&](double x) { return info[j].log_scale ? std::exp(x) : x; };
  if (std::isfinite(ends[0])) p.lo95 = si(ends[0]);
  if (std::isfinite(ends[1])) p.hi95 = si(ends[1]);
  p.flat = reached[0] && reached[1];
  for (int side = 0; side < 2; ++side)
    if (!side_reason[side].empty()) p.reason += (p.reason.empty() ? "" : "; ") + side_reason[side];

  std::ostringstream s;
  const std::string unit = info[j].unit.empty() ? "" : " " + info[j].unit;
  s << "profile of " << info[j].name << ": ";
  double lowest = 0;
  for (double d : p.delta_chi2) lowest = std::min(lowest, d);
  if (p.flat) {
    double top = 0;
    for (double d : p.delta_chi2) top = std::max(top, d);
    s << "flat: Delta chi^2 stays below 3.84 (at most " << format_value(top) << ") over the whole range ["
      << format_value(info[j].lo) << ", " << format_value(info[j].hi) << "]" << unit
      << ": not identifiable from these data";
    s << (identifiable ? "; the Fisher information called it identifiable: its quadratic approximation misleads here"
                       : ", as the Fisher information says");
  } else {
    s << "95 % interval [" << (std::isfinite(p.lo95) ? format_value(p.lo95) : "none") << ", "
      << (std::isfinite(p.hi95) ? format_value(p.hi95) : "none") << "]" << unit;
    if (!p.reason.empty()) s << " (" << p.reason << ")";
    if (!identifiable) {
      s << "; the Fisher information called it not identifiable, but the profile rises: the data bound it through "
           "the model's nonlinearity";
    } else {
      const double half = kZ95 * se;
      double shift = 0;
      if (std::isfinite(ends[0])) shift = std::max(shift, std::abs(ends[0] - (xhat[j] - half)) / half);
      if (std::isfinite(ends[1])) shift = std::max(shift, std::abs(ends[1] - (xhat[j] + half)) / half);
      p.max_shift = shift;
      p.nonlinear = shift > po.nonlinearity_tolerance || !std::isfinite(ends[0]) || !std::isfinite(ends[1]);
      if (p.nonlinear)
        s << "; it differs from the Fisher interval [" << format_value(si(xhat[j] - half)) << ", "
          << format_value(si(xhat[j] + half)) << "] by " << format_value(std::round(shift * 1000) / 10)
          << " % of its half-width (tolerance " << format_value(po.nonlinearity_tolerance * 100)
          << " %): the model is nonlinear over the interval, use the profile's";
      else
        s << "; agrees with the Fisher interval to " << format_value(std::round(shift * 1000) / 10)
          << " % of its half-width";
    }
  }
  if (lowest < -1e-6 * std::max(1.0, chi2_min))
    s << "; the profile reached chi^2 " << format_value(chi2_min + lowest) << " below the fit's "
      << format_value(chi2_min) << ": the fit stopped at a local minimum";
  p.statement = s.str();
  return p;
}

// Residuals per row at the estimate, regime rows included (compared, not fitted).
std::vector<RowResidual> row_residuals(const ObservationData& data, const CellModel& cell,
                                       const ForwardOptions& forward) {
  std::vector<RowResidual> out;
  const std::vector<Prediction> pred = predict_all(cell, data.rows, forward);
  for (std::size_t i = 0; i < data.rows.size(); ++i) {
    const ObservedRow& o = data.rows[i];
    RowResidual rr;
    rr.line = o.line;
    rr.observable = o.observable;
    rr.observed = o.value;
    rr.uncertainty = o.uncertainty;
    rr.predicted = pred[i].value;
    rr.reason = pred[i].reason;
    rr.predicted_regime = pred[i].regime;
    if (o.has_regime) rr.observed_regime = o.regime;
    if (numeric(o)) rr.residual = (rr.predicted - rr.observed) / rr.uncertainty;
    // A regime row, or a numeric row that names the regime it was seen in (a transition row's regime is the
    // swinging side of the transition).
    if (o.has_regime) rr.regime_agrees = pred[i].regime == o.regime;
    out.push_back(rr);
  }
  return out;
}

}  // namespace

void FitOptions::validate() const {
  require(starts >= 1 && starts <= 64, "starts", starts, "an integer in [1, 64]");
  require(start_spread > 0 && start_spread <= 10, "start_spread", start_spread, "in (0, 10]");
  require(max_iterations >= 1 && max_iterations <= 10000, "max_iterations", max_iterations, "an integer in [1, 10000]");
  require(tol > 0 && tol <= 1e-2, "tol", tol, "in (0, 1e-2]");
  require(fd_step > 0 && fd_step <= 0.1, "fd_step", fd_step, "in (0, 0.1]");
  require(identifiability_ratio > 0 && identifiability_ratio < 1, "identifiability_ratio", identifiability_ratio,
          "in (0, 1)");
  forward.validate();
  profiles.validate();
}

void ProfileOptions::validate() const {
  require(points >= 1 && points <= 50, "profile_points", points, "an integer in [1, 50]");
  require(span > 0 && span <= 50, "profile_span", span, "in (0, 50] Fisher standard errors");
  require(nonlinearity_tolerance > 0 && nonlinearity_tolerance <= 1, "profile_tolerance", nonlinearity_tolerance,
          "in (0, 1] of the Fisher half-width");
}

Linearisation linearise(std::span<const ObservedRow> rows, std::span<const FitParameter> free, const CellModel& cell,
                        const FitOptions& options, double step) {
  if (options.jacobian == JacobianMethod::variational) return variational_linearise(rows, free, cell, options, step);
  Linearisation lin;
  std::vector<ObservedRow> numeric_rows;
  for (const ObservedRow& o : rows)
    if (numeric(o)) numeric_rows.push_back(o);
  const std::vector<FitParameterInfo> info = infos_of(free, cell);
  const std::vector<double> x = coordinates(cell, info);
  if (!residuals_at(numeric_rows, cell, options.forward, lin.r, lin.reason)) return lin;
  lin.J.assign(lin.r.size(), std::vector<double>(free.size(), 0.0));
  std::vector<double> plus, minus;
  for (std::size_t j = 0; j < free.size(); ++j) {
    std::vector<double> xp = x, xm = x;
    xp[j] += step;
    xm[j] -= step;
    std::string why;
    if (!residuals_at(numeric_rows, cell_at(cell, info, xp), options.forward, plus, why) ||
        !residuals_at(numeric_rows, cell_at(cell, info, xm), options.forward, minus, why)) {
      lin.reason =
          "the sensitivity to " + coordinate_name(info[j]) + " needs the model at +-" + format_value(step) + ": " + why;
      return lin;
    }
    for (std::size_t i = 0; i < lin.r.size(); ++i) lin.J[i][j] = (plus[i] - minus[i]) / (2 * step);
  }
  lin.ok = true;
  return lin;
}

FitResult fit(const ObservationData& data, const std::vector<std::string>& free_names, const CellModel& cell,
              const FitOptions& given) {
  given.validate();
  // The transition's warm starts live for this fit only: its value never depends on what ran before it.
  FitOptions options = given;
  if (!options.forward.transition_memo) options.forward.transition_memo = make_transition_memo();
  cell.validate();
  std::vector<FitParameter> free;
  for (const std::string& name : free_names) {
    const FitParameter q = fit_parameter_from_string(name, "free");
    if (std::find(free.begin(), free.end(), q) != free.end())
      throw InvalidArgument("free", "free = '" + name + "' is named twice");
    free.push_back(q);
  }
  if (free.empty()) throw InvalidArgument("free", "no free parameter: name at least one (e.g. shear_modulus)");
  const bool has_lambda = std::find(free.begin(), free.end(), FitParameter::lambda) != free.end();
  if (has_lambda && !std::isnan(cell.inner_viscosity))
    throw InvalidArgument("free",
                          "lambda is free but inner_viscosity is given: lambda follows from it; free "
                          "inner_viscosity instead, or leave it out");
  if (std::find(free.begin(), free.end(), FitParameter::inner_viscosity) != free.end() &&
      std::isnan(cell.inner_viscosity))
    throw InvalidArgument("free",
                          "inner_viscosity is free but has no start value: fix inner_viscosity=<value> "
                          "(e.g. 6mPa s) as its start");
  std::vector<ObservedRow> rows;
  for (const ObservedRow& o : data.rows)
    if (numeric(o)) rows.push_back(o);
  if (rows.empty()) throw InvalidArgument("data", data.path + ": no numeric observations (regime rows alone)");

  const std::vector<FitParameterInfo> info = infos_of(free, cell);
  std::vector<double> x0 = coordinates(cell, info);
  std::vector<double> lo, hi;
  for (std::size_t j = 0; j < info.size(); ++j) {
    lo.push_back(coordinate_bound(info[j], info[j].lo));
    hi.push_back(coordinate_bound(info[j], info[j].hi));
    if (!(x0[j] >= lo[j] && x0[j] <= hi[j]))
      throw InvalidArgument(info[j].name, info[j].name + " = " + format_value(get_value(cell, info[j].id)) +
                                              " (the start) is outside the fit's bounds [" + format_value(info[j].lo) +
                                              ", " + format_value(info[j].hi) + "]");
  }
  FitResult res;
  res.cell = cell;
  res.rows = static_cast<int>(rows.size());
  res.dof = res.rows - static_cast<int>(free.size());

  FitMonitor monitor(options);
  const std::vector<RegimeConstraint> constraints =
      options.regime_constraints ? regime_constraints(data) : std::vector<RegimeConstraint>{};
  std::vector<std::vector<double>> multipliers;  // per start
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int best = -1;
  for (int s = 0; s < options.starts && !monitor.stopped(); ++s) {
    FitStart st;
    st.start = x0;
    if (s > 0)
      for (std::size_t j = 0; j < x0.size(); ++j) {
        // Linear coordinates (the excess areas) spread over a quarter of their range per unit of spread.
        const double width =
            info[j].log_scale ? options.start_spread : options.start_spread * 0.25 * (info[j].hi - info[j].lo);
        const double margin = 1e-3 * std::min(1.0, hi[j] - lo[j]);
        st.start[j] = std::clamp(x0[j] + width * unit(rng), lo[j] + margin, hi[j] - margin);
      }
    const Solve sv = solve(rows, free, cell, options, st.start, -1, monitor, constraints);
    multipliers.push_back(sv.multipliers);
    res.evaluations += sv.evaluations;
    st.status = sv.status;
    st.ipopt_status = sv.ipopt_status;
    st.iterations = sv.iterations;
    st.end = sv.end;
    st.chi2 = sv.chi2;
    res.starts.push_back(st);
    const int k = static_cast<int>(res.starts.size()) - 1;
    auto rank = [](FitStatus f) { return f == FitStatus::converged ? 0 : f == FitStatus::maximum_iterations ? 1 : 2; };
    if (std::isfinite(st.chi2) &&
        (best < 0 || rank(st.status) < rank(res.starts[best].status) ||
         (rank(st.status) == rank(res.starts[best].status) && st.chi2 < res.starts[best].chi2)))
      best = k;
    monitor.start_done();
  }
  const std::string stopped_after =
      "interrupted after " + std::to_string(res.starts.size()) + " of " + std::to_string(options.starts) + " starts";
  if (best < 0) {
    res.status = monitor.stopped() ? FitStatus::interrupted : FitStatus::failed;
    res.message = monitor.stopped() ? stopped_after + ": no estimate" : "no start gave a fit:";
    for (const FitStart& st : res.starts) res.message += " [" + st.ipopt_status + "]";
    return res;
  }
  const FitStart& b = res.starts[best];
  res.status = b.status;
  res.chi2 = b.chi2;
  res.cell = cell_at(cell, info, b.end);
  if (res.status != FitStatus::converged)
    res.message = "the best start did not converge (" + b.ipopt_status + "): the estimates are its last iterate";
  if (!constraints.empty()) apply_constraints(res, constraints, free, options.forward, multipliers[best]);
  if (monitor.stopped()) {
    res.status = FitStatus::interrupted;
    res.message = stopped_after + ": the estimates are the best start's so far (" + to_string(b.status) +
                  (b.status == FitStatus::converged ? "" : ", its last iterate") + "), without intervals";
  }

  // Fisher information J^T J at the estimate (uncertainties as given: no rescaling by chi^2/dof).
  const Linearisation lin = monitor.stopped() ? Linearisation{false, "interrupted", {}, {}}
                                              : linearise(rows, free, res.cell, options, options.fd_step);
  const std::size_t n = free.size();
  res.covariance.assign(n, std::vector<double>(n, kNotGiven));
  res.correlation.assign(n, std::vector<double>(n, kNotGiven));
  for (std::size_t j = 0; j < n; ++j) {
    FitEstimate e;
    e.parameter = info[j];
    e.value = get_value(res.cell, info[j].id);
    // An interior-point iterate stops short of an active bound by an amount set by the barrier and the slope
    // there (1.7e-4 in ln for a modulus the data do not see), so "at" is relative to the box's width.
    const double near = kAtBoundFraction * (hi[j] - lo[j]);
    e.at_bound = b.end[j] - lo[j] < near || hi[j] - b.end[j] < near;
    res.estimates.push_back(e);
  }
  if (!lin.ok) {
    if (!monitor.stopped())
      res.message += (res.message.empty() ? "" : "; ") + std::string("no intervals: ") + lin.reason;
    res.residuals = row_residuals(data, res.cell, options.forward);
    return res;
  }
  Eigen::MatrixXd J(lin.r.size(), n);
  for (std::size_t i = 0; i < lin.r.size(); ++i)
    for (std::size_t j = 0; j < n; ++j) J(i, j) = lin.J[i][j];
  const Eigen::MatrixXd F = J.transpose() * J;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(F);
  const Eigen::VectorXd ev = eig.eigenvalues();
  const Eigen::MatrixXd V = eig.eigenvectors();
  const double largest = ev.maxCoeff();
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd flat_weight = Eigen::VectorXd::Zero(n);
  for (std::size_t k = 0; k < n; ++k) {
    res.fisher_eigenvalues.push_back(ev(k));
    const bool flat = !(largest > 0) || ev(k) <= options.identifiability_ratio * largest;
    if (!flat) {
      cov += V.col(k) * V.col(k).transpose() / ev(k);
      continue;
    }
    flat_weight += V.col(k).cwiseAbs2();
    std::ostringstream s;
    s << "not identifiable from these data: the direction";
    bool first = true;
    for (std::size_t j = 0; j < n; ++j)
      if (std::abs(V(j, k)) > 1e-3) {
        s << (first ? " " : " + ") << format_value(std::round(V(j, k) * 1000) / 1000) << " "
          << coordinate_name(info[j]);
        first = false;
      }
    s << " changes no prediction (Fisher eigenvalue " << format_value(ev(k)) << ", largest " << format_value(largest)
      << ")";
    bool only_flat = false;
    for (std::size_t j = 0; j < n; ++j)
      if (std::abs(V(j, k)) > 0.999) {
        s << ": no observable given depends on " << info[j].name;
        only_flat = true;
      }
    if (!only_flat)
      s << ": only the combination orthogonal to it is measured; fix one of them or add an observable "
           "that separates them";
    std::vector<FitParameter> involved;
    for (std::size_t j = 0; j < n; ++j)
      if (std::abs(V(j, k)) > 1e-3) involved.push_back(info[j].id);
    s << ". " << what_would_pin(involved);
    res.unidentifiable.push_back(s.str());
  }
  for (std::size_t j = 0; j < n; ++j) {
    FitEstimate& e = res.estimates[j];
    e.identifiable = flat_weight(j) < 1e-2;
    for (std::size_t i = 0; i < n; ++i) res.covariance[j][i] = cov(j, i);
    if (!e.identifiable) continue;
    e.standard_error = std::sqrt(cov(j, j));
    const double x = b.end[j], d = kZ95 * e.standard_error;
    // An interval reaching past a bound: the box, not the data, limits the estimate there.
    if (x - d < lo[j] || x + d > hi[j]) e.at_bound = true;
    e.lo95 = info[j].log_scale ? std::exp(x - d) : x - d;
    e.hi95 = info[j].log_scale ? std::exp(x + d) : x + d;
  }
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i)
      if (res.estimates[j].identifiable && res.estimates[i].identifiable)
        res.correlation[j][i] = cov(j, i) / std::sqrt(cov(j, j) * cov(i, i));
  for (const std::string& s : res.unidentifiable) res.message += (res.message.empty() ? "" : "; ") + s;

  if (options.profiles.enabled)
    for (std::size_t j = 0; j < n; ++j) {
      if (!monitor.stopped())
        res.estimates[j].profile = profile_of(rows, free, cell, options, info, lo, hi, b.end, res.chi2, j,
                                              res.estimates[j].standard_error, res.evaluations, monitor, constraints);
      if (!monitor.stopped()) continue;
      res.estimates[j].profile = {};  // cut short or not begun: no interval to claim
      if (res.status == FitStatus::interrupted) continue;
      res.status = FitStatus::interrupted;
      res.message += (res.message.empty() ? "" : "; ") + std::string("interrupted before the profile of ") +
                     info[j].name + " was finished: the estimates and Fisher intervals stand; no profile from " +
                     info[j].name + " on";
    }

  res.residuals = row_residuals(data, res.cell, options.forward);
  return res;
}

nlohmann::json to_json(const FitResult& r) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json out;
  out["status"] = to_string(r.status);
  out["message"] = r.message;
  out["chi2"] = num(r.chi2);
  out["rows"] = r.rows;
  out["dof"] = r.dof;
  out["evaluations"] = r.evaluations;
  nlohmann::json est = nlohmann::json::array();
  for (const FitEstimate& e : r.estimates) {
    nlohmann::json pj;
    if (e.profile.computed) {
      nlohmann::json xs = nlohmann::json::array(), ds = nlohmann::json::array();
      for (std::size_t k = 0; k < e.profile.coordinate.size(); ++k) {
        xs.push_back(num(e.profile.coordinate[k]));
        ds.push_back(num(e.profile.delta_chi2[k]));
      }
      pj = {{"coordinate", xs},
            {"delta_chi2", ds},
            {"lo95", num(e.profile.lo95)},
            {"hi95", num(e.profile.hi95)},
            {"flat", e.profile.flat},
            {"nonlinear", e.profile.nonlinear},
            {"max_shift", num(e.profile.max_shift)},
            {"statement", e.profile.statement},
            {"solves", e.profile.solves},
            {"iterations", e.profile.iterations},
            {"fallbacks", e.profile.fallbacks}};
      if (!e.profile.reason.empty()) pj["reason"] = e.profile.reason;
    }
    est.push_back({{"name", e.parameter.name},
                   {"symbol", e.parameter.unicode},
                   {"unit", e.parameter.unit},
                   {"scale", e.parameter.log_scale ? "log" : "linear"},
                   {"value", num(e.value)},
                   {"standard_error", num(e.standard_error)},
                   {"lo95", num(e.lo95)},
                   {"hi95", num(e.hi95)},
                   {"identifiable", e.identifiable},
                   {"at_bound", e.at_bound},
                   {"bounds", {num(e.parameter.lo), num(e.parameter.hi)}},
                   {"profile", pj}});
  }
  out["estimates"] = est;
  auto matrix = [&](const std::vector<std::vector<double>>& m) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& row : m) {
      nlohmann::json rj = nlohmann::json::array();
      for (double v : row) rj.push_back(num(v));
      a.push_back(rj);
    }
    return a;
  };
  out["covariance"] = matrix(r.covariance);
  out["correlation"] = matrix(r.correlation);
  out["fisher_eigenvalues"] = r.fisher_eigenvalues;
  out["unidentifiable"] = r.unidentifiable;
  nlohmann::json res = nlohmann::json::array();
  for (const RowResidual& x : r.residuals) {
    nlohmann::json j = {{"line", x.line},
                        {"observable", to_string(x.observable)},
                        {"observed", num(x.observed)},
                        {"predicted", num(x.predicted)},
                        {"uncertainty", num(x.uncertainty)},
                        {"residual", num(x.residual)},
                        {"predicted_regime", to_string(x.predicted_regime)}};
    if (x.observed_regime != Regime::undetermined) {
      j["observed_regime"] = to_string(x.observed_regime);
      j["regime_agrees"] = x.regime_agrees;
    }
    if (!x.reason.empty()) j["reason"] = x.reason;
    res.push_back(j);
  }
  out["residuals"] = res;
  out["constraints"] = nlohmann::json::array();
  for (const ConstraintResult& c : r.constraints) out["constraints"].push_back(to_json(c));
  nlohmann::json starts = nlohmann::json::array();
  for (const FitStart& s : r.starts)
    starts.push_back({{"start", s.start},
                      {"end", s.end},
                      {"status", to_string(s.status)},
                      {"ipopt", s.ipopt_status},
                      {"chi2", num(s.chi2)},
                      {"iterations", s.iterations}});
  out["starts"] = starts;
  return out;
}

std::string fit_text(const FitResult& r) {
  std::ostringstream s;
  s << "fit: " << to_string(r.status) << "   chi^2 = " << format_value(r.chi2) << " over " << r.rows << " rows ("
    << r.dof << " degrees of freedom)\n";
  if (!r.message.empty()) s << "  " << r.message << "\n";
  s << "parameter            estimate      95 % interval\n";
  for (const FitEstimate& e : r.estimates) {
    s << "  " << e.parameter.name << std::string(e.parameter.name.size() < 18 ? 18 - e.parameter.name.size() : 1, ' ')
      << format_value(e.value) << (e.parameter.unit.empty() ? "" : " " + e.parameter.unit) << "   ";
    if (!e.identifiable)
      s << "not identifiable";
    else if (std::isfinite(e.standard_error))
      s << "[" << format_value(e.lo95) << ", " << format_value(e.hi95) << "]";
    else
      s << "no interval (see the message above)";
    if (e.at_bound) s << "  (at a bound)";
    s << "\n";
  }
  for (const FitEstimate& e : r.estimates)
    if (e.profile.computed) s << "  " << e.profile.statement << "\n";
  if (r.estimates.size() > 1) {
    s << "correlation (fitted coordinates):\n";
    for (const auto& row : r.correlation) {
      s << " ";
      for (double v : row) s << " " << (std::isfinite(v) ? format_value(std::round(v * 1000) / 1000) : "n/a");
      s << "\n";
    }
  }
  if (!r.constraints.empty()) s << "regime constraints (observed regime against the transition shear rate):\n";
  for (const ConstraintResult& c : r.constraints) s << "  " << constraint_text(c) << "\n";
  s << "residuals (predicted - observed)/uncertainty:\n";
  for (const RowResidual& x : r.residuals) {
    s << "  line " << x.line << " " << to_string(x.observable) << ": ";
    if (x.observable == Observable::regime)
      s << "observed " << to_string(x.observed_regime) << ", predicted " << to_string(x.predicted_regime)
        << (x.regime_agrees ? "" : "  (disagrees)");
    else if (std::isfinite(x.residual))
      s << format_value(x.residual);
    else
      s << "n/a (" << x.reason << ")";
    if (x.observable != Observable::regime && !x.regime_agrees)
      s << "  (seen " << to_string(x.observed_regime) << ", predicted " << to_string(x.predicted_regime) << ")";
    s << "\n";
  }
  return s.str();
}

}  // namespace rbcstab
