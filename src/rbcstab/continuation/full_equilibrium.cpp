#include "rbcstab/continuation/full_equilibrium.hpp"

#include <cmath>
#include <complex>
#include <string>

#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/continuation/detail/sphere_constraint.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

namespace {

std::size_t at(Eigen::Index i) { return static_cast<std::size_t>(i); }

// The stress-free shape at parameters q: only g enters the equilibrium problem, so the current
// shape's perturbations are dropped (they would be validated against a moving Delta).
InitialState rest_shape(const Scene& scene, const Parameters& q) {
  Scene s = scene;
  s.parameters = q;
  s.delta = 0;
  s.delta_l.clear();
  return initial_state(s);
}

// The drive rotates (g_{l,m}(t) = g_{l,m}(0) e^{i m t/2}) when C is finite and g has m != 0 content.
// Content below 1e-28 of the total is rounding of beta (as scene.cpp's m = 1 test).
void require_steady_drive(const Scene& scene, const Parameters& q, const ModeAmplitudes& g) {
  if (q.inv_C() == 0) return;
  double total = 0, rotating = 0;
  for (int l = 2; l <= g.L; ++l)
    for (int m = -l; m <= l; ++m) {
      total += a_l(l) * std::norm(g.at(l, m));
      if (m != 0) rotating += a_l(l) * std::norm(g.at(l, m));
    }
  if (rotating > 1e-28 * total)
    throw InvalidArgument("beta", "beta = " + format_value(scene.beta) +
                                      " gives the stress-free shape m != 0 content, which rotates with the flow "
                                      "(g_{l,m}(t) = g_{l,m}(0) e^{i m t/2}): the full model is forced and has no "
                                      "equilibria; use beta = 0, Delta0 = 0 without rest_delta_l, or C = inf");
}

}  // namespace

FullEquilibriumProblem::FullEquilibriumProblem(const Scene& scene, ContinuationParameter free)
    : scene_(scene), free_(free), L_(scene.L), n_((scene.L + 1) * (scene.L + 1) - 4) {
  scene_.validate();
  require_L(L_, kMinL, max_L,
            "the full equilibrium problem is dense, n = (L+1)^2 - 4 unknowns and O(n^3) work per point "
            "(factorisations and the spectrum)");
  model(start_parameter());  // validates the drive at the start
}

const FullModel& FullEquilibriumProblem::model(double p) const {
  if (!cache_ || cache_p_ != p) {
    const Scene sp = with_parameter(scene_, free_, p);  // beta free: the rest shape turns with p
    const Parameters& q = sp.parameters;
    const InitialState init = rest_shape(sp, q);
    require_steady_drive(sp, q, init.g);
    cache_.reset();
    cache_.emplace(q, init);
    cache_q_ = q;
    cache_p_ = p;
  }
  return *cache_;
}

std::vector<double> FullEquilibriumProblem::to_full_state(const Eigen::VectorXd& x, double p) const {
  const double Delta = parameters(p).Delta;
  std::vector<double> y(2 * ModeAmplitudes::count(L_), 0.0);
  for (int l = 2; l <= L_; ++l) {
    const std::size_t k0 = ModeAmplitudes::index(l, 0);
    y[2 * k0] = std::sqrt(Delta / a_l(l)) * x[index(l, 0)];
    const double c = std::sqrt(Delta / (2 * a_l(l)));
    for (int m = 1; m <= l; ++m) {
      const std::size_t kp = ModeAmplitudes::index(l, m), km = ModeAmplitudes::index(l, -m);
      const double sign = m % 2 == 0 ? 1.0 : -1.0;  // f_{l,-m} = (-1)^m conj f_{l,m}
      const double re = c * x[index(l, m)], im = c * x[index(l, m) + 1];
      y[2 * kp] = re;
      y[2 * kp + 1] = im;
      y[2 * km] = sign * re;
      y[2 * km + 1] = -sign * im;
    }
  }
  return y;
}

Eigen::VectorXd FullEquilibriumProblem::from_full_state(std::span<const double> y, double p) const {
  const double Delta = parameters(p).Delta;
  // Built as a std::vector first (GCC 12 flags element writes into a fresh dynamic Eigen vector).
  std::vector<double> x(at(n_), 0.0);
  for (int l = 2; l <= L_; ++l) {
    x[at(index(l, 0))] = std::sqrt(a_l(l) / Delta) * y[2 * ModeAmplitudes::index(l, 0)];
    const double c = std::sqrt(2 * a_l(l) / Delta);
    for (int m = 1; m <= l; ++m) {
      const std::size_t kp = ModeAmplitudes::index(l, m), km = ModeAmplitudes::index(l, -m);
      const double sign = m % 2 == 0 ? 1.0 : -1.0;
      // The real-shape part of (f_{l,m}, f_{l,-m}): the mean of f_{l,m} and (-1)^m conj f_{l,-m}.
      x[at(index(l, m))] = 0.5 * c * (y[2 * kp] + sign * y[2 * km]);
      x[at(index(l, m) + 1)] = 0.5 * c * (y[2 * kp + 1] - sign * y[2 * km + 1]);
    }
  }
  return Eigen::Map<const Eigen::VectorXd>(x.data(), n_);
}

void FullEquilibriumProblem::dynamics(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const {
  const std::vector<double> y = to_full_state(x, p);
  std::vector<double> dydt(y.size());
  model(p).rhs(0, y, dydt);
  F = from_full_state(dydt, p);
}

void FullEquilibriumProblem::dynamics_jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& DF) const {
  const std::vector<double> y = to_full_state(x, p);
  StructuredJacobian J;
  std::vector<double> dfdt(y.size());
  model(p).jacobian(0, y, J, dfdt);
  // DF = R J E = R M E + (R v)(E^T w)^T. M maps real shapes to real shapes block by block, so R M E
  // is M's own (l, m >= 0) block: Upsilon_l for m = 0 (the Im f_{l,0} half is dropped), the 2x2
  // rotation [[Y, -m/2], [m/2, Y]] for m > 0. E^T w collects w over both halves of each (l, +-m).
  const double Delta = parameters(p).Delta;
  const Eigen::VectorXd Rv = from_full_state(J.v, p);
  std::vector<double> Etw(at(n_));
  DF.setZero(n_, n_);
  for (int l = 2; l <= L_; ++l) {
    const std::size_t k0 = ModeAmplitudes::index(l, 0);
    const Eigen::Index i0 = index(l, 0);
    DF(i0, i0) = J.diag[2 * k0];
    Etw[at(i0)] = std::sqrt(Delta / a_l(l)) * J.w[2 * k0];
    const double c = std::sqrt(Delta / (2 * a_l(l)));
    for (int m = 1; m <= l; ++m) {
      const std::size_t kp = ModeAmplitudes::index(l, m), km = ModeAmplitudes::index(l, -m);
      const double sign = m % 2 == 0 ? 1.0 : -1.0;
      const Eigen::Index i = index(l, m);
      DF(i, i) = J.diag[2 * kp];
      DF(i, i + 1) = J.upper[2 * kp];
      DF(i + 1, i) = J.lower[2 * kp];
      DF(i + 1, i + 1) = J.diag[2 * kp + 1];
      Etw[at(i)] = c * (J.w[2 * kp] + sign * J.w[2 * km]);
      Etw[at(i + 1)] = c * (J.w[2 * kp + 1] - sign * J.w[2 * km + 1]);
    }
  }
  DF.noalias() += Rv * Eigen::Map<const Eigen::VectorXd>(Etw.data(), n_).transpose();
}

void FullEquilibriumProblem::residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& G) const {
  dynamics(x, p, G);
  detail::add_sphere_constraint(x, G);
}

void FullEquilibriumProblem::jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const {
  dynamics_jacobian(x, p, J);
  detail::add_sphere_constraint_jacobian(x, J);
}

Eigen::VectorXcd FullEquilibriumProblem::spectrum(const Eigen::VectorXd& x, double p) const {
  return certified_spectrum(x, p, false).values;
}

CertifiedSpectrum FullEquilibriumProblem::certified_spectrum(const Eigen::VectorXd& x, double p, bool) const {
  Eigen::MatrixXd DF;
  dynamics_jacobian(x, p, DF);
  // Block structure: DF = D + u grad(sigma)^T with D block diagonal (1x1 for m = 0, the 2x2 rotation
  // for m > 0) and u proportional to x (FullModel::jacobian). A block (l, m) with x = 0 there has u = 0
  // there, so its rows hold only its D block: DF is block triangular and that block's eigenvalues
  // (Upsilon_l +- i m/2) are exact without the dense solve. The rest (the "active" blocks, which
  // contain x, so x^perp splits the same way) goes through the dense tangent-plane spectrum.
  // On the symmetric branches almost every l >= 3 block is inactive: the dense part is ~6 x 6.
  std::vector<Eigen::Index> active;
  std::vector<std::complex<double>> values;
  std::vector<double> errors;
  const double eta = assembly_accuracy(DF.rows());
  auto append = [&](const CertifiedSpectrum& c) {
    values.insert(values.end(), c.values.data(), c.values.data() + c.values.size());
    errors.insert(errors.end(), c.errors.data(), c.errors.data() + c.errors.size());
  };
  for (int l = 2; l <= L_; ++l)
    for (int m = 0; m <= l; ++m) {
      const Eigen::Index i = index(l, m), k = m == 0 ? 1 : 2;
      if (x.segment(i, k).cwiseAbs().maxCoeff() > 0) {
        for (Eigen::Index j = 0; j < k; ++j) active.push_back(i + j);
        continue;
      }
      append(certified_eigenvalues(DF.block(i, i, k, k), eta));
    }
  const Eigen::Index na = static_cast<Eigen::Index>(active.size());
  Eigen::MatrixXd DFa(na, na);
  Eigen::VectorXd xa(na);
  for (Eigen::Index a = 0; a < na; ++a) {
    xa[a] = x[active[at(a)]];
    for (Eigen::Index b = 0; b < na; ++b) DFa(a, b) = DF(active[at(a)], active[at(b)]);
  }
  append(detail::certified_tangent_spectrum(DFa, xa, eta));
  const auto size = static_cast<Eigen::Index>(values.size());
  return {Eigen::Map<const Eigen::VectorXcd>(values.data(), size),
          Eigen::Map<const Eigen::VectorXd>(errors.data(), size)};
}

void FullEquilibriumProblem::parameter_derivative(const Eigen::VectorXd& x, double p, Eigen::VectorXd& Fp) const {
  if (free_ != ContinuationParameter::beta) {
    ContinuationProblem::parameter_derivative(x, p, Fp);
    return;
  }
  // Where the problem is defined, F does not move with beta: C = inf (no rest-shape term), no rest
  // shape, or the one-point domain beta = 0 of a pulling one (as ModalEquilibriumProblem).
  model(p);  // the domain check
  Fp = Eigen::VectorXd::Zero(n_);
}

Eigen::VectorXd FullEquilibriumProblem::ellipsoidal_state(double p) const {
  const Scene sp = with_parameter(scene_, free_, p);
  const Parameters& q = sp.parameters;
  const OutOfPlaneEquilibrium e = out_of_plane_equilibrium(q);
  // The closed form is written for the rest shape's w0 = +1 (g20 <= 0, e.g. beta = 0); the system is
  // odd in (w, w0). Orientation from Delta0 = Delta > 0 so that it is defined at Delta0 = 0 too.
  Parameters oriented = q;
  oriented.Delta0 = oriented.Delta;
  const double g20 = rest_shape(sp, oriented).g.at(2, 0).real();
  const double w0 = g20 <= 0 ? 1.0 : -1.0;
  // Layout x_{2,0}, x_{2,1} (2), x_{2,2} (2); x_{2,0} = sqrt(a2/Delta) f20 = -w, x_{2,2} = z. (Values
  // first, then resized: GCC 12 flags element writes into a fresh vector as null dereferences.)
  static_assert(index(2, 0) == 0 && index(2, 2) == 3);
  std::vector<double> x = {-w0 * e.w, 0.0, 0.0, e.r * std::cos(e.Psi), -e.r * std::sin(e.Psi)};
  x.resize(at(n_), 0.0);
  return Eigen::Map<const Eigen::VectorXd>(x.data(), n_);
}

Eigen::VectorXd FullEquilibriumProblem::relaxed_state(double T) const {
  require(std::isfinite(T) && T > 0, "T", T, "a finite number > 0");
  const double p = start_parameter();
  const FullModel start(parameters(p), initial_state(scene_));  // parameters(p) checks the drive
  const std::vector<double> y0 = start.initial_state();
  const double grid[1] = {T};
  IntegratorOptions o;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  const IntegrationResult r = integrate(start, y0, 0.0, grid, o, {});
  const Eigen::VectorXd x = from_full_state(r.y, p);
  return x / x.norm();  // the run's area is Delta plus the perturbations
}

FullEquilibriumState FullEquilibriumProblem::observe(const Eigen::VectorXd& x, double p) const {
  const std::vector<double> y = to_full_state(x, p);
  const Observation o = model(p).observe(0, y);
  FullEquilibriumState s;
  s.sigma = o.sigma;
  s.Delta_l = o.Delta_l;
  s.r = o.Delta2 > 0 ? std::min(1.0, std::abs(o.f22) * std::sqrt(2 * a_l(2) / o.Delta2)) : 0.0;
  s.Psi = -std::arg(o.f22);
  if (s.Psi <= -kPi) s.Psi += 2 * kPi;
  return s;
}

}  // namespace rbcstab
