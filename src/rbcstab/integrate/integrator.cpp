#include "rbcstab/integrate/integrator.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>

#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/detail/gsl_context.hpp"
#include "rbcstab/integrate/detail/prince_dormand.hpp"

namespace rbcstab {

namespace {
const gsl_odeiv2_step_type* gsl_type(Stepper s) {
  switch (s) {
    case Stepper::rk8pd:
      return gsl_odeiv2_step_rk8pd;  // not asked: integrate() steps rk8pd itself
    case Stepper::rkck:
      return gsl_odeiv2_step_rkck;
    case Stepper::rkf45:
      return gsl_odeiv2_step_rkf45;
    case Stepper::msadams:
      return gsl_odeiv2_step_msadams;
    case Stepper::rosenbrock:
      return detail::rosenbrock_step_type();
    case Stepper::msbdf:
      return gsl_odeiv2_step_msbdf;
    case Stepper::bsimp:
      return gsl_odeiv2_step_bsimp;
    case Stepper::rk4imp:
      return gsl_odeiv2_step_rk4imp;
  }
  return gsl_odeiv2_step_rk8pd;
}

// A non-finite F at a trial state (e.g. an implicit stepper's Newton iterate after an over-long
// step) rejects that trial: GSL_FAILURE makes the step be halved and retried, whereas GSL_EBADFUNC
// would end the run at once. A state that stays non-finite as h shrinks ends the run as
// non_finite_state (see integrate()).
int finite_or_reject(detail::GslContext* ctx, double t, const double dydt[], std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(dydt[i])) {
      ++ctx->nonfinite_rhs;
      ctx->nonfinite_t = t;
      return GSL_FAILURE;
    }
  return GSL_SUCCESS;
}

int gsl_rhs(double t, const double y[], double dydt[], void* params) {
  auto* ctx = static_cast<detail::GslContext*>(params);
  ++ctx->counters->rhs_evaluations;
  const std::size_t n = ctx->system->dimension();
  ctx->system->rhs(t, {y, n}, {dydt, n});
  return finite_or_reject(ctx, t, dydt, n);
}

int compact_rhs(double t, const double x[], double dxdt[], void* params) {
  auto* ctx = static_cast<detail::GslContext*>(params);
  ++ctx->counters->rhs_evaluations;
  const std::size_t n = ctx->form->x0.size();
  ctx->system->compact_rhs(t, {x, n}, *ctx->form, {dxdt, n});
  return finite_or_reject(ctx, t, dxdt, n);
}

int gsl_jac(double t, const double y[], double* dfdy, double dfdt[], void* params) {
  auto* ctx = static_cast<detail::GslContext*>(params);
  ++ctx->counters->jacobian_evaluations;
  const std::size_t n = ctx->system->dimension();
  ctx->system->jacobian(t, {y, n}, ctx->jacobian, {dfdt, n});
  ctx->jacobian.to_dense({dfdy, n * n});
  return GSL_SUCCESS;
}

struct DriverDeleter {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};

// One accepted step towards a target with gsl_odeiv2_evolve_apply's contract and status codes.
class Evolver {
 public:
  virtual ~Evolver() = default;
  virtual int apply(double& t, double t1, double& h, std::vector<double>& y) = 0;
  virtual std::size_t failed_steps() const = 0;
};

class GslEvolver final : public Evolver {
 public:
  GslEvolver(gsl_odeiv2_driver* driver, gsl_odeiv2_system* sys) : driver_(driver), sys_(sys) {}
  int apply(double& t, double t1, double& h, std::vector<double>& y) override {
    return gsl_odeiv2_evolve_apply(driver_->e, driver_->c, driver_->s, sys_, &t, t1, &h, y.data());
  }
  std::size_t failed_steps() const override { return driver_->e->failed_steps; }

 private:
  std::unique_ptr<gsl_odeiv2_driver, DriverDeleter> driver_;
  gsl_odeiv2_system* sys_;
};

// rk8pd (detail/prince_dormand.hpp), on the system's compact form when it has one: y is rebuilt from x after
// every step, so observers, stop conditions and the result see the system's own state.
class PrinceDormandEvolver final : public Evolver {
 public:
  PrinceDormandEvolver(detail::GslContext& ctx, std::optional<CompactForm> form, const IntegratorOptions& o)
      : form_(std::move(form)),
        x_(form_ ? form_->x0 : std::vector<double>{}),
        stepper_(form_ ? x_.size() : ctx.system->dimension(), form_ ? compact_rhs : gsl_rhs, &ctx, o.atol, o.rtol,
                 form_ ? &*form_ : nullptr) {
    ctx.form = form_ ? &*form_ : nullptr;
  }
  int apply(double& t, double t1, double& h, std::vector<double>& y) override {
    if (!form_) return stepper_.apply(t, t1, h, y);
    const int rc = stepper_.apply(t, t1, h, x_);
    if (rc == 0) form_->rebase(x_);
    form_->expand(x_, y);
    return rc;
  }
  std::size_t failed_steps() const override { return stepper_.failed_steps(); }

 private:
  std::optional<CompactForm> form_;
  std::vector<double> x_;
  detail::PrinceDormand87 stepper_;
};

// GSL's default error handler aborts; every GSL error here is a returned status instead. The handler is
// process-wide, so concurrent integrations (threaded sweeps) share one switch: the first to enter turns it off,
// the last to leave restores the caller's. A save/restore per call would let one thread put the aborting handler
// back while another is still inside GSL.
class GslErrorHandlerOff {
 public:
  GslErrorHandlerOff() {
    const std::lock_guard<std::mutex> lock(state().mutex);
    if (state().users++ == 0) state().previous = gsl_set_error_handler_off();
  }
  ~GslErrorHandlerOff() {
    const std::lock_guard<std::mutex> lock(state().mutex);
    if (--state().users == 0) gsl_set_error_handler(state().previous);
  }
  GslErrorHandlerOff(const GslErrorHandlerOff&) = delete;
  GslErrorHandlerOff& operator=(const GslErrorHandlerOff&) = delete;

 private:
  struct State {
    std::mutex mutex;
    int users = 0;
    gsl_error_handler_t* previous = nullptr;
  };
  static State& state() {
    static State s;
    return s;
  }
};
}  // namespace

bool is_implicit(Stepper s) {
  switch (s) {
    case Stepper::rk8pd:
    case Stepper::rkck:
    case Stepper::rkf45:
    case Stepper::msadams:
      return false;
    case Stepper::rosenbrock:
    case Stepper::msbdf:
    case Stepper::bsimp:
    case Stepper::rk4imp:
      return true;
  }
  return false;
}

int dense_matrices(Stepper s) {
  switch (s) {
    case Stepper::msbdf:
    case Stepper::bsimp:
      return 2;
    case Stepper::rk4imp:
      return 5;
    default:
      return 0;
  }
}

void require_dense_dimension(Stepper s, std::size_t n, const std::string& system) {
  const int k = dense_matrices(s);
  if (k == 0 || n <= kMaxDenseDimension) return;
  auto gb = [k](double dim) { return format_bytes(double(k) * dim * dim * 8); };
  throw InvalidArgument("stepper",
                        "stepper = " + to_string(s) + " on " + system + " keeps " + std::to_string(k) + " dense " +
                            std::to_string(n) + " x " + std::to_string(n) + " matrices, about " + gb(double(n)) +
                            ": it is allowed up to dimension " + std::to_string(kMaxDenseDimension) + " (" +
                            gb(double(kMaxDenseDimension)) +
                            "): use rosenbrock (O(n) structured solves), an explicit stepper, or the modal level");
}

void IntegratorOptions::validate() const {
  require(std::isfinite(rtol) && rtol >= 1e-15 && rtol <= 1e-1, "rtol", rtol, "in [1e-15, 0.1]");
  require(std::isfinite(atol) && atol >= 0 && atol <= 1, "atol", atol, "in [0, 1]");
  require(std::isfinite(h_init) && h_init > 0, "h_init", h_init, "finite and > 0");
  require(std::isfinite(h_min) && h_min > 0 && h_min <= h_init, "h_min", h_min,
          "in (0, h_init] with h_init = " + format_value(h_init));
  require(max_steps > 0, "max_steps", double(max_steps), "> 0");
  require(std::isfinite(max_seconds) && max_seconds >= 0, "max_seconds", max_seconds, "finite and >= 0 (0: no limit)");
}

IntegrationResult integrate(const System& system, std::span<const double> y0, double t0, std::span<const double> grid,
                            const IntegratorOptions& options, const StateObserver& on_sample,
                            const StateObserver& on_step, const StopCondition& stop) {
  options.validate();
  const std::size_t n = system.dimension();
  require(y0.size() == n, "y0", double(y0.size()), "of the system's dimension " + std::to_string(n));
  require_dense_dimension(options.stepper, n, "a system of dimension " + std::to_string(n));
  require_finite("t0", t0);
  for (std::size_t i = 0; i < grid.size(); ++i)
    require(std::isfinite(grid[i]) && grid[i] >= t0 && (i == 0 || grid[i] > grid[i - 1]), "grid", grid[i],
            "finite, increasing and >= t0");

  const auto start = std::chrono::steady_clock::now();
  const GslErrorHandlerOff handler_guard;
  IntegrationResult result;
  detail::GslContext ctx{&system, nullptr, &result.counters, {}};
  gsl_odeiv2_system sys{gsl_rhs, gsl_jac, n, &ctx};
  std::unique_ptr<Evolver> evolver;
  if (options.stepper == Stepper::rk8pd) {
    evolver = std::make_unique<PrinceDormandEvolver>(ctx, system.compact_form(y0), options);
  } else {
    gsl_odeiv2_driver* driver = gsl_odeiv2_driver_alloc_standard_new(&sys, gsl_type(options.stepper), options.h_init,
                                                                     options.atol, options.rtol, 1.0, 0.0);
    if (!driver) {
      result.status = IntegrationStatus::solver_error;
      result.reason = "GSL could not allocate the " + to_string(options.stepper) + " driver";
      return result;
    }
    evolver = std::make_unique<GslEvolver>(driver, &sys);
  }

  std::vector<double> y(y0.begin(), y0.end());
  double t = t0, h = options.h_init;
  auto fail = [&](IntegrationStatus status, std::string reason) {
    result.status = status;
    result.reason = std::move(reason);
  };
  if (!std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); }))
    fail(IntegrationStatus::non_finite_state, "the initial state is not finite");

  for (std::size_t k = 0; k < grid.size() && result.status == IntegrationStatus::success; ++k) {
    const double target = grid[k];
    while (t < target) {
      const std::size_t nonfinite_before = ctx.nonfinite_rhs;
      const int rc = evolver->apply(t, target, h, y);
      if (rc == GSL_EBADFUNC || (rc != GSL_SUCCESS && ctx.nonfinite_rhs > nonfinite_before)) {
        fail(IntegrationStatus::non_finite_state,
             "the right-hand side became non-finite at t = " + format_value(ctx.nonfinite_t) +
                 " and stayed so as the trial step shrank (h = " + format_value(h) + ")");
        break;
      }
      if (rc != GSL_SUCCESS) {
        const bool tiny = std::abs(h) < options.h_min;
        fail(tiny ? IntegrationStatus::step_size_underflow : IntegrationStatus::solver_error,
             to_string(options.stepper) + " failed at t = " + format_value(t) + " (h = " + format_value(h) +
                 "): " + gsl_strerror(rc));
        break;
      }
      ++result.counters.steps;
      if (!std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); })) {
        fail(IntegrationStatus::non_finite_state, "the state became non-finite at t = " + format_value(t));
        break;
      }
      if (on_step) on_step(t, y);
      if (stop && stop(t, y)) {
        result.stopped = true;
        break;
      }
      if (t < target && std::abs(h) < options.h_min && ctx.nonfinite_rhs > nonfinite_before) {
        fail(IntegrationStatus::non_finite_state,
             "the right-hand side is non-finite just beyond t = " + format_value(t) + " (the step size fell to " +
                 format_value(h) + ")");
        break;
      }
      if (t < target && std::abs(h) < options.h_min) {
        fail(IntegrationStatus::step_size_underflow, "the step size fell to " + format_value(h) + " < h_min = " +
                                                         format_value(options.h_min) + " at t = " + format_value(t));
        break;
      }
      if (result.counters.steps >= options.max_steps && t < target) {
        fail(IntegrationStatus::step_limit,
             "reached max_steps = " + std::to_string(options.max_steps) + " at t = " + format_value(t));
        break;
      }
      if (options.poll && (result.counters.steps & 7) == 0) options.poll();
      if (options.max_seconds > 0 && (result.counters.steps & 63) == 0 &&
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > options.max_seconds) {
        fail(IntegrationStatus::time_limit,
             "exceeded max_seconds = " + format_value(options.max_seconds) + " at t = " + format_value(t));
        break;
      }
    }
    if (result.status != IntegrationStatus::success) break;
    // A stop on a grid time still delivers that sample.
    if (on_sample && (!result.stopped || t >= target)) on_sample(t, y);
    if (result.stopped) break;
  }
  result.counters.failed_steps = evolver->failed_steps();
  result.t_reached = t;
  result.y = std::move(y);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace rbcstab
