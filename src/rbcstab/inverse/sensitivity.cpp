#include "rbcstab/inverse/sensitivity.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/inverse/fit.hpp"
#include "rbcstab/model/reduced_model.hpp"

namespace rbcstab {

namespace {

// The reduced orbit with its variational equations and the Psi quadratures, for rk8pd (explicit: the augmented
// system's Jacobian is never asked for). State: y (3); Phi (3 x 3, column-major) with Phi' = J Phi; eta_a, eta_k
// with eta' = J eta + df/da (df/dkappa); and with g = grad Psi = (y1, -y0, 0)/(y0^2 + y1^2) the integrals of
// g^T Phi (3), g . eta_a and g . eta_k: the period averages of dPsi need no samples.
class OrbitVariations final : public System {
 public:
  static constexpr std::size_t kDim = 23;
  explicit OrbitVariations(const ReducedModel& model) : model_(model) {}
  ModelLevel level() const override { return ModelLevel::reduced; }
  std::size_t dimension() const override { return kDim; }
  int L() const override { return 2; }
  void rhs(double t, std::span<const double> y, std::span<double> dydt) const override {
    const ReducedModel::DenseTerms d = model_.dense_terms(t, y.first(3));
    double fa[3], fk[3];
    ReducedModel::coefficient_derivatives(y.first(3), d.direction, fa, fk);
    const double r2 = y[0] * y[0] + y[1] * y[1];
    const double g[3] = {y[1] / r2, -y[0] / r2, 0.0};
    auto apply = [&](std::size_t at, std::size_t out, const double* add) {
      for (int i = 0; i < 3; ++i) {
        double s = add ? add[i] : 0.0;
        for (int j = 0; j < 3; ++j) s += d.J[3 * i + j] * y[at + j];
        dydt[out + i] = s;
      }
    };
    for (int i = 0; i < 3; ++i) dydt[i] = d.f[i];
    for (std::size_t k = 0; k < 3; ++k) apply(3 + 3 * k, 3 + 3 * k, nullptr);
    apply(12, 12, fa);
    apply(15, 15, fk);
    auto dot_g = [&](std::size_t at) { return g[0] * y[at] + g[1] * y[at + 1] + g[2] * y[at + 2]; };
    for (std::size_t k = 0; k < 3; ++k) dydt[18 + k] = dot_g(3 + 3 * k);
    dydt[21] = dot_g(12);
    dydt[22] = dot_g(15);
  }
  void jacobian(double, std::span<const double>, StructuredJacobian&, std::span<double>) const override {
    throw std::logic_error("the orbit's variational run integrates with explicit steppers only");
  }
  Observation observe(double, std::span<const double>) const override {
    throw std::logic_error("the orbit's variational run has no observation");
  }
  std::vector<double> initial_state() const override { return {}; }
  ModeAmplitudes amplitudes(double, std::span<const double>) const override {
    throw std::logic_error("the orbit's variational run has no amplitudes");
  }

 private:
  const ReducedModel& model_;
};

// The polynomial through (t_k, v_k) at s (Lagrange form; five points around an extremum).
double lagrange(std::span<const double> t, std::span<const double> v, double s) {
  double sum = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    double w = v[k];
    for (std::size_t j = 0; j < t.size(); ++j)
      if (j != k) w *= (s - t[j]) / (t[k] - t[j]);
    sum += w;
  }
  return sum;
}

// The zero of the interpolated Psi' in [t_0, t_4] by bisection; the guess when Psi' does not change sign there
// (a tank-treading cell whose Psi barely moves).
double interpolated_root(std::span<const double> t, std::span<const double> dpsi, double guess) {
  double a = t.front(), b = t.back();
  double fa = lagrange(t, dpsi, a);
  if ((fa > 0) == (lagrange(t, dpsi, b) > 0)) return guess;
  for (int it = 0; it < 100 && b - a > 1e-14 * std::max(1.0, std::abs(a)); ++it) {
    const double c = 0.5 * (a + b), fc = lagrange(t, dpsi, c);
    if ((fc > 0) == (fa > 0)) {
      a = c;
      fa = fc;
    } else {
      b = c;
    }
  }
  return 0.5 * (a + b);
}

constexpr int kWindow = 5;  // samples around each extremum

}  // namespace

OrbitSensitivity orbit_sensitivity(const Parameters& p, const InPlaneMotion& m, const ForwardOptions& options) {
  OrbitSensitivity out;
  if (m.orbit_state.size() != 3 || !std::isfinite(m.t_max) || !std::isfinite(m.t_min)) {
    out.reason = "no converged orbit to differentiate";
    return out;
  }
  if (!(p.inv_Lambda_S() > 0)) {
    out.reason = "kappa = 1/(Lambda S) = 0: the model drops the rest shape's direction";
    return out;
  }
  Scene scene;
  scene.parameters = p;
  scene.beta = kPi / 2;
  const ReducedModel model(p, initial_state(validated(scene)));
  const OrbitVariations flow(model);
  const double t0 = m.orbit_time, T = t0 + kTwoPi;
  // Windows of kWindow samples at half the forward's sample spacing around each sampled extremum: its time is off
  // by O(spacing^2), and Psi' interpolated on the window puts it to ~1e-12.
  const double delta = 0.5 * kTwoPi / options.samples_per_period;
  std::vector<double> grid;
  double centre[2];
  for (int e = 0; e < 2; ++e) {
    double te = e == 0 ? m.t_max : m.t_min;
    if (te - 2 * delta <= 0) te += kTwoPi;  // after t0: dx(t) is 2 pi-periodic once dx0 is the periodic one
    centre[e] = t0 + te;
    for (int k = -2; k <= 2; ++k) grid.push_back(centre[e] + k * delta);
  }
  grid.push_back(T);
  std::vector<std::size_t> order(grid.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return grid[a] < grid[b]; });
  std::vector<double> sorted;
  for (std::size_t k : order) sorted.push_back(grid[k]);
  std::vector<std::vector<double>> states(grid.size());
  std::size_t next = 0;
  std::vector<double> z0(OrbitVariations::kDim, 0.0);
  for (int i = 0; i < 3; ++i) {
    z0[i] = m.orbit_state[i];
    z0[3 + 4 * i] = 1;  // Phi(t0) = I
  }
  IntegratorOptions io;
  io.stepper = Stepper::rk8pd;
  io.rtol = options.rtol;
  io.atol = options.rtol / 10;
  io.max_steps = 5'000'000;
  const IntegrationResult res = integrate(flow, z0, t0, sorted, io, [&](double, std::span<const double> s) {
    states[order[next++]].assign(s.begin(), s.end());
  });
  if (res.status != IntegrationStatus::success) {
    out.reason = "the variational run failed: " + to_string(res.status) + ": " + res.reason;
    return out;
  }
  const std::vector<double>& end = states.back();
  Eigen::Matrix3d M;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) M(i, k) = end[3 + 3 * k + i];
  const Eigen::Vector3d x0(m.orbit_state[0], m.orbit_state[1], m.orbit_state[2]);
  // The multipliers on the tangent plane: M's eigenvalues other than the one nearest 1 (x0^T M = x0^T).
  const Eigen::Vector3cd ev = M.eigenvalues();
  int trivial = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(ev(k) - 1.0) < std::abs(ev(trivial) - 1.0)) trivial = k;
  out.multiplier = 0;
  for (int k = 0; k < 3; ++k)
    if (k != trivial) out.multiplier = std::max(out.multiplier, std::abs(ev(k)));
  if (!(out.multiplier < 1)) {
    out.reason = "the orbit is not attracting (Floquet multiplier " + format_value(out.multiplier) + ")";
    return out;
  }
  Eigen::Matrix<double, 4, 3> A;
  A.topRows<3>() = Eigen::Matrix3d::Identity() - M;
  A.row(3) = x0.transpose();
  Eigen::Matrix<double, 4, 2> rhs = Eigen::Matrix<double, 4, 2>::Zero();
  for (int i = 0; i < 3; ++i) {
    rhs(i, 0) = end[12 + i];
    rhs(i, 1) = end[15 + i];
  }
  const Eigen::Matrix<double, 3, 2> dx0 = A.colPivHouseholderQr().solve(rhs);
  // Mean: (1/2) (1/2 pi) int dPsi = (1/2)(q_Phi . dx0 + q_eta)/(2 pi); psi = Psi/2.
  const Eigen::Vector3d qPhi(end[18], end[19], end[20]);
  out.mean_invL = 0.5 * (qPhi.dot(dx0.col(0)) + end[21]) / kTwoPi;
  out.mean_kappa = 0.5 * (qPhi.dot(dx0.col(1)) + end[22]) / kTwoPi;
  // Amplitude: (1/4)(dPsi(t_max) - dPsi(t_min)); the extrema's own shift changes Psi there only at second order.
  double shift[2][2];
  for (int e = 0; e < 2; ++e) {
    double t[kWindow], dpsi[kWindow], da[kWindow], dk[kWindow];
    for (int k = 0; k < kWindow; ++k) {
      const std::vector<double>& s = states[static_cast<std::size_t>(e * kWindow + k)];
      t[k] = grid[static_cast<std::size_t>(e * kWindow + k)];
      const double r2 = s[0] * s[0] + s[1] * s[1];
      const double g[3] = {s[1] / r2, -s[0] / r2, 0.0};
      const ReducedModel::DenseTerms d = model.dense_terms(t[k], std::span<const double>(s.data(), 3));
      dpsi[k] = g[0] * d.f[0] + g[1] * d.f[1];
      double v[2] = {0, 0};
      for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 2; ++c) {
          double dx = s[12 + 3 * c + i];
          for (int j = 0; j < 3; ++j) dx += s[3 + 3 * j + i] * dx0(j, c);
          v[c] += g[i] * dx;
        }
      da[k] = v[0];
      dk[k] = v[1];
    }
    const double te = interpolated_root(t, dpsi, centre[e]);
    shift[e][0] = lagrange(t, da, te);
    shift[e][1] = lagrange(t, dk, te);
  }
  out.amplitude_invL = 0.25 * (shift[0][0] - shift[1][0]);
  out.amplitude_kappa = 0.25 * (shift[0][1] - shift[1][1]);
  out.ok = true;
  return out;
}

std::array<double, 2> coefficient_gradient(const CellModel& cell, FitParameter q, bool log_scale, double shear_rate,
                                           double viscosity) {
  const double v = get_value(cell, q), x = log_scale ? std::log(v) : v;
  const double h = 1e-6 * std::max(1.0, std::abs(x));
  auto coefficients = [&](double at) {
    CellModel c = cell;
    set_value(c, q, log_scale ? std::exp(at) : at);
    const Parameters p = condition_parameters(c, shear_rate, viscosity);
    return std::array<double, 2>{1 / p.Lambda(), p.inv_Lambda_S()};
  };
  const auto plus = coefficients(x + h), minus = coefficients(x - h);
  return {(plus[0] - minus[0]) / (2 * h), (plus[1] - minus[1]) / (2 * h)};
}

Linearisation variational_linearise(std::span<const ObservedRow> rows, std::span<const FitParameter> free,
                                    const CellModel& cell, const FitOptions& options, double step) {
  // The in-plane rows by the variational equations; the others (transition shear rates) by central differences.
  std::vector<ObservedRow> in_plane, other;
  std::vector<std::size_t> in_plane_at, other_at;
  std::size_t count = 0;
  for (const ObservedRow& o : rows) {
    if (o.observable == Observable::regime) continue;
    const bool orbit = o.observable != Observable::transition_shear_rate;
    (orbit ? in_plane : other).push_back(o);
    (orbit ? in_plane_at : other_at).push_back(count++);
  }
  Linearisation lin;
  try {
    cell.validate();
  } catch (const InvalidArgument& e) {
    lin.reason = e.what();
    return lin;
  }
  lin.r.assign(count, 0.0);
  lin.J.assign(count, std::vector<double>(free.size(), 0.0));
  if (!other.empty()) {
    FitOptions fd = options;
    fd.jacobian = JacobianMethod::finite_difference;
    const Linearisation l = linearise(other, free, cell, fd, step);
    if (!l.ok) return l;
    for (std::size_t i = 0; i < other.size(); ++i) {
      lin.r[other_at[i]] = l.r[i];
      lin.J[other_at[i]] = l.J[i];
    }
  }
  struct Condition {
    InPlaneMotion motion;
    OrbitSensitivity sensitivity;
    std::vector<std::array<double, 2>> gradient;  // per free parameter: d(1/Lambda, kappa)/dx_j
  };
  std::map<std::pair<double, double>, Condition> conditions;
  for (std::size_t i = 0; i < in_plane.size(); ++i) {
    const ObservedRow& o = in_plane[i];
    const auto key = std::make_pair(o.shear_rate, o.viscosity);
    auto it = conditions.find(key);
    if (it == conditions.end()) {
      Condition c;
      const Parameters p = condition_parameters(cell, o.shear_rate, o.viscosity);
      c.motion = in_plane_motion(p, options.forward);
      if (c.motion.regime == Regime::swinging || c.motion.regime == Regime::tank_treading) {
        c.sensitivity = orbit_sensitivity(p, c.motion, options.forward);
        for (const FitParameter q : free)
          c.gradient.push_back(
              coefficient_gradient(cell, q, fit_parameter_info(q, cell).log_scale, o.shear_rate, o.viscosity));
      }
      it = conditions.emplace(key, std::move(c)).first;
    }
    const Condition& c = it->second;
    const Prediction pr = predict_from_motion(c.motion, o);
    if (!pr.ok()) {
      lin.reason = "line " + std::to_string(o.line) + ": " + pr.reason;
      return lin;
    }
    const std::size_t row = in_plane_at[i];
    lin.r[row] = (pr.value - o.value) / o.uncertainty;
    const bool angle = o.observable == Observable::inclination_angle || o.observable == Observable::swinging_amplitude;
    if (!angle) continue;  // the frequencies are fixed by the shear rate: no parameter moves them
    if (!c.sensitivity.ok) {
      lin.reason = "line " + std::to_string(o.line) + ": no sensitivity: " + c.sensitivity.reason;
      return lin;
    }
    const bool mean = o.observable == Observable::inclination_angle;
    const double da = mean ? c.sensitivity.mean_invL : c.sensitivity.amplitude_invL;
    const double dk = mean ? c.sensitivity.mean_kappa : c.sensitivity.amplitude_kappa;
    for (std::size_t j = 0; j < free.size(); ++j)
      lin.J[row][j] = (da * c.gradient[j][0] + dk * c.gradient[j][1]) / o.uncertainty;
  }
  lin.ok = true;
  return lin;
}

}  // namespace rbcstab
