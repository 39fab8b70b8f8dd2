// Periodic orbits of the modal model under the in-plane forcing (modal_orbit.hpp): the forced system
// against ModalModel::rhs, its Jacobian and df/dp against differences, the ellipsoidal orbit against
// the reduced in-plane orbit with the decoupled multipliers exp(int Upsilon_l) in closed form, and the
// post-instability in-plane orbit against a long modal simulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <random>
#include <vector>

#include "continuation/periodic_quadrature.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {
namespace {

// The paper's in-plane scenes (Fig. 2 / Fig. 6 parameters) at a tilt beta.
Scene in_plane(double lambda, double beta, double delta, int L) {
  Scene s;
  s.name = "modal_orbit";
  s.parameters.lambda = lambda;
  s.parameters.Delta = 1;
  s.parameters.Delta0 = 0.01;
  s.parameters.B = 2;
  s.parameters.C = 0.04;
  s.beta = beta;
  s.delta = delta;
  s.L = L;
  s.model = ModelLevel::modal;
  return s;
}

// The forced system's x' mapped to the ModalModel's y' (lab-frame v = v~ e^{it/2}) against
// ModalModel::rhs at random states (off the sphere too) and times, for beta with and without m = 1
// content. 1e-12 relative: both evaluate the same rational expressions in a different order.
TEST(ModalOrbit, RhsMatchesModalModel) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (double beta : {M_PI / 2, 0.7, 0.0}) {
    const Scene scene = in_plane(2.0, beta, 1e-3, 6);
    const ModalModel m(scene.parameters, initial_state(scene));
    ASSERT_EQ(m.active_modes().size(), 4u);
    const ModalForcedSystem sys(scene, ContinuationParameter::lambda);
    const double p = sys.start_parameter(), Delta = scene.parameters.Delta;
    const double fz = std::sqrt(Delta / (2 * a_l(2))), fw = -std::sqrt(Delta / a_l(2));
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd x(sys.dimension());
      for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = u(gen);
      const double t = 10 * u(gen);
      Eigen::VectorXd f(x.size());
      sys.rhs(t, std::span<const double>(x.data(), static_cast<std::size_t>(x.size())), p,
              std::span<double>(f.data(), static_cast<std::size_t>(f.size())));
      const std::vector<double> y = sys.to_modal_model_state(t, x, p);
      std::vector<double> dy(y.size());
      m.rhs(t, y, dy);
      EXPECT_NEAR(sys.observe(t, x, p).sigma, m.sigma(t, y), 1e-12 * std::abs(m.sigma(t, y)));
      const std::complex<double> vdot =
          (std::complex<double>(f[3], f[4]) + std::complex<double>(0, 0.5) * std::complex<double>(x[3], x[4])) *
          std::polar(1.0, 0.5 * t);
      const double expect[5] = {fw * f[2], fz * vdot.real(), fz * vdot.imag(), fz * f[0], fz * f[1]};
      const double scale = std::max(1.0, std::abs(m.sigma(t, y)));
      for (int i = 0; i < 5; ++i) EXPECT_NEAR(dy[static_cast<std::size_t>(i)], expect[i], 1e-12 * scale) << i;
      for (int l = 3; l <= 6; ++l) {
        const Eigen::Index i = ModalEquilibriumProblem::index_of_mode(l);
        const double Dl = Delta * x[i] * x[i];
        // dDelta_l/dt = Delta_l u_l' (modal model) = 2 Delta a_l a_l' (forced system)
        EXPECT_NEAR(Dl * dy[static_cast<std::size_t>(l + 2)], 2 * Delta * x[i] * f[i], 1e-12 * scale * Dl) << l;
      }
    }
  }
}

// df/dx against central differences of rhs, and the analytic df/dp against ForcedSystem's default
// central differences, for every continuation parameter. 1e-7 relative: truncation ~h^2 with
// h ~ 6e-6 and rounding ~eps/h ~ 4e-11.
TEST(ModalOrbit, JacobianAndParameterDerivativeMatchDifferences) {
  Scene scene = in_plane(2.0, 0.7, 1e-3, 5);
  scene.physical = unit_cell(scene.parameters);  // shear_rate, a table row, needs a cell
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const std::string& name : continuation_parameter_names()) {
    const ModalForcedSystem sys(scene, continuation_parameter_from_string(name));
    const double p = sys.start_parameter();
    const Eigen::Index n = sys.dimension();
    for (double t : {0.0, 1.3, 4.0}) {
      Eigen::VectorXd x(n);
      for (Eigen::Index i = 0; i < n; ++i) x[i] = u(gen);
      auto F = [&](const Eigen::VectorXd& xx) {
        Eigen::VectorXd f(n);
        sys.rhs(t, std::span<const double>(xx.data(), static_cast<std::size_t>(n)), p,
                std::span<double>(f.data(), static_cast<std::size_t>(n)));
        return f;
      };
      const double scale = std::max(1.0, F(x).cwiseAbs().maxCoeff());
      Eigen::MatrixXd J;
      sys.jacobian(t, std::span<const double>(x.data(), static_cast<std::size_t>(n)), p, J);
      for (Eigen::Index j = 0; j < n; ++j) {
        const double h = 1e-5;
        Eigen::VectorXd xp = x, xm = x;
        xp[j] += h;
        xm[j] -= h;
        const Eigen::VectorXd col = (F(xp) - F(xm)) / (2 * h);
        for (Eigen::Index i = 0; i < n; ++i) EXPECT_NEAR(J(i, j), col[i], 1e-7 * scale) << name << " " << i << "," << j;
      }
      Eigen::VectorXd a(n), d(n);
      const std::span<const double> xs(x.data(), static_cast<std::size_t>(n));
      sys.parameter_derivative(t, xs, p, std::span<double>(a.data(), static_cast<std::size_t>(n)));
      sys.ForcedSystem::parameter_derivative(t, xs, p, std::span<double>(d.data(), static_cast<std::size_t>(n)));
      const double ds = std::max(1e-3, d.cwiseAbs().maxCoeff());
      for (Eigen::Index i = 0; i < n; ++i) EXPECT_NEAR(a[i], d[i], 1e-7 * ds) << name << " t = " << t << " i = " << i;
    }
  }
}

// sigma(t) over one period of the reduced orbit through y0 (independent of the modal code: the
// ReducedModel's multiplier mu and sigma_from_mu), by the periodic trapezoid rule (periodic_quadrature.hpp).
double reduced_sigma_integral(const ReducedModel& m, const Eigen::Vector3d& y0) {
  return test::period_integral(m, std::span<const double>(y0.data(), 3),
                               [&](double t, std::span<const double> y) { return m.sigma_from_mu(m.mu(t, y)); });
}

// The ellipsoidal orbit (a_l = 0, v~ = 0) of the in-plane modal problem is the reduced in-plane orbit
// (same equations on that invariant subspace): 1e-10 (both Newton solves converge to 1e-12 at
// integration tolerance 1e-12). Its multipliers are the reduced ones plus, in closed form,
// exp(int Upsilon_l(sigma) dt) for each l >= 3 and exp(int Upsilon_2 dt) twice (the v~ plane),
// with sigma(t) of the reduced orbit: 1e-7 relative (shooting at rtol 1e-12 over 8 segments).
TEST(ModalOrbit, EllipsoidalOrbitIsTheReducedOrbitWithClosedFormMultipliers) {
  for (double lambda : {1.0, 5.0}) {
    Scene rs = in_plane(lambda, M_PI / 2, 0, 2);
    rs.model = ModelLevel::reduced;
    const ReducedForcedSystem red(rs, ContinuationParameter::lambda);
    const PeriodicOrbitProblem rp(red);
    const double p = red.start_parameter();
    const NewtonResult rn = solve_fixed_parameter(rp, rp.shooting_guess(red.relaxed_state(300), p), p);
    ASSERT_TRUE(rn.converged);
    const Eigen::Vector3d y0 = rp.state_at_zero(rn.x);

    const int L = 6;
    const ModalForcedSystem sys(in_plane(lambda, M_PI / 2, 0, L), ContinuationParameter::lambda);
    const PeriodicOrbitProblem mp(sys);
    Eigen::VectorXd x0 = Eigen::VectorXd::Zero(sys.dimension());
    x0.head(3) = y0 + Eigen::Vector3d(0.01, -0.02, 0.01);  // perturbed: Newton must do the work
    const NewtonResult mn = solve_fixed_parameter(mp, mp.shooting_guess(x0, p), p);
    ASSERT_TRUE(mn.converged);
    const Eigen::VectorXd x = mp.state_at_zero(mn.x);
    EXPECT_LT((x.head(3) - y0).norm(), 1e-10) << "lambda = " << lambda;
    EXPECT_LT(x.tail(x.size() - 3).norm(), 1e-12);

    const Floquet fm = mp.floquet(mn.x, p), fr = rp.floquet(rn.x, p);
    ASSERT_TRUE(fm.trivial.has_value());
    EXPECT_NEAR(*fm.trivial, 1.0, 1e-9);
    const ReducedModel& rm = red.model(p);
    const double I_sigma = reduced_sigma_integral(rm, y0);
    std::vector<std::complex<double>> expected(fr.multipliers.data(), fr.multipliers.data() + fr.multipliers.size());
    for (int l = 2; l <= L; ++l) {
      // int Upsilon_l(sigma(t)) dt = 2 pi Upsilon_l(0) + (dUpsilon_l/dsigma) int sigma dt (Upsilon is affine)
      const Parameters& q = rs.parameters;
      const double slope = Upsilon_l(q, l, 1.0) - Upsilon_l(q, l, 0.0);
      const double rho = std::exp(kTwoPi * Upsilon_l(q, l, 0.0) + slope * I_sigma);
      expected.push_back(rho);
      if (l == 2) expected.push_back(rho);  // the v~ plane (m = 1 of l = 2) twice
      std::printf("lambda %g l %d closed-form multiplier %.12e\n", lambda, l, rho);
    }
    ASSERT_EQ(fm.multipliers.size(), static_cast<Eigen::Index>(expected.size()));
    // Match each expected multiplier to a distinct computed one.
    std::vector<bool> used(expected.size(), false);
    for (const std::complex<double>& e : expected) {
      double best = 1e300;
      std::size_t bi = 0;
      for (std::size_t k = 0; k < expected.size(); ++k) {
        const double dk = std::abs(fm.multipliers[static_cast<Eigen::Index>(k)] - e);
        if (!used[k] && dk < best) {
          best = dk;
          bi = k;
        }
      }
      used[bi] = true;
      EXPECT_LT(best, 1e-7 * std::max(1e-3, std::abs(e))) << "lambda = " << lambda << " expected " << e;
    }
  }
}

// The post-instability in-plane state of the paper's Fig. 6 scenes (lambda = 5 and 1, beta = pi/2,
// delta = 1e-3, L = 10): past the threshold mode l = 3 takes area and the relaxed simulation is a
// periodic orbit with a_3 != 0 (a_l = 0 for l >= 4). Solved by shooting from the simulation at
// t ~ 600 and compared with the same simulation continued for 4 more periods.
TEST(ModalOrbit, PostInstabilityInPlaneOrbitIsTheLongTimeStateOfTheModalSimulation) {
  for (double lambda : {5.0, 1.0}) {
    const Scene sim = in_plane(lambda, M_PI / 2, 1e-3, 10);
    const ModalForcedSystem sys(total_area_scene(sim), ContinuationParameter::lambda);
    const double p = sys.start_parameter();
    const int K0 = 96;  // periods of relaxation (T ~ 603, the paper's horizon is 500)
    const PeriodicOrbitProblem pr(sys);
    const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(sys.relaxed_state(sim, kTwoPi * K0), p), p);
    ASSERT_TRUE(nr.converged) << lambda;
    const Eigen::VectorXd x0 = pr.state_at_zero(nr.x);
    const ModalState s0 = sys.observe(0, x0, p);
    EXPECT_GT(s0.Delta_l[1], 0.3) << "mode 3 carries area";
    for (int l = 4; l <= 10; ++l) EXPECT_LT(s0.Delta_l[static_cast<std::size_t>(l - 2)], 1e-100) << l;

    // Stable: every nontrivial multiplier inside the unit circle (measured max |rho| = 0.233 at
    // lambda = 5, 0.0136 at lambda = 1), and the same multipliers with 16 segments (labels do not
    // depend on the discretisation; 1e-8 relative to the largest, the shooting tolerance's reach).
    const Floquet f8 = pr.floquet(nr.x, p);
    const double rho_max = f8.multipliers.cwiseAbs().maxCoeff();
    EXPECT_LT(rho_max, 0.5);
    // Closed form: a_3 != 0 periodic needs int Upsilon_3 dt = 0, and Upsilon_l is affine in sigma, so
    // int Upsilon_l dt = 2 pi [Upsilon_l(0) - (s_l/s_3) Upsilon_3(0)] (s_l = dUpsilon_l/dsigma) whatever
    // sigma(t) is. The directions with zero amplitude decouple with that exponent: a_l for l >= 4 and
    // the v~ plane (v~ = 0 here; l = 2, twice). 1e-8 relative (1e-11 absolute for the tiny ones).
    {
      const Parameters& q = sim.parameters;
      auto slope = [&](int l) { return Upsilon_l(q, l, 1.0) - Upsilon_l(q, l, 0.0); };
      for (int l : {2, 4, 5, 6, 7, 8, 9, 10}) {
        const double rho = std::exp(kTwoPi * (Upsilon_l(q, l, 0.0) - slope(l) / slope(3) * Upsilon_l(q, 3, 0.0)));
        int found = 0;
        for (Eigen::Index i = 0; i < f8.multipliers.size(); ++i)
          if (std::abs(f8.multipliers[i] - rho) < std::max(1e-8 * rho, 1e-11)) ++found;
        EXPECT_GE(found, l == 2 ? 2 : 1) << "lambda = " << lambda << " l = " << l << ": exp(int Upsilon_l) = " << rho;
        if (l <= 4) std::printf("lambda %g: closed-form multiplier of l = %d: %.9e\n", lambda, l, rho);
      }
    }
    std::printf("lambda %g: Delta_3(0) = %.10f, max |rho| = %.6e, trivial = %.3e\n", lambda, s0.Delta_l[1], rho_max,
                *f8.trivial - 1);
    OrbitOptions o64;
    o64.segments = 64;
    const PeriodicOrbitProblem p64(sys, o64);
    const NewtonResult n64 = solve_fixed_parameter(p64, p64.shooting_guess(x0, p), p);
    ASSERT_TRUE(n64.converged);
    EXPECT_LT((p64.state_at_zero(n64.x) - x0).norm(), 1e-10);
    EXPECT_NEAR(p64.floquet(n64.x, p).multipliers.cwiseAbs().maxCoeff(), rho_max, 1e-8 * rho_max);

    // The orbit's period means of Delta_l from the 64 segment states (uniform in t: the periodic
    // trapezoid rule is spectrally accurate).
    const Eigen::Index n = sys.dimension();
    std::vector<double> orbit_mean(9, 0.0), sim_mean(9, 0.0);
    for (int j = 0; j < 64; ++j) {
      const ModalState sj = sys.observe(kTwoPi * j / 64, n64.x.segment(j * n, n), p);
      for (std::size_t k = 0; k < 9; ++k) orbit_mean[k] += sj.Delta_l[k] / 64;
    }

    // The simulation over 4 more periods, 64 samples per period: its states at t = 2 pi k are the
    // orbit's x0, and its Delta_l tail means are the orbit's means. Tolerance 1e-9: the transient
    // has decayed by rho_max^96 < 1e-60, what is left is the simulation's own error at rtol 1e-11,
    // which drifts along the neutral area direction linearly in time (measured |x|^2 - 1 ~ 3e-12
    // at T = 600 for lambda = 5, 3e-11 for lambda = 1).
    const ModalModel m(sim.parameters, initial_state(sim));
    std::vector<double> grid;
    for (int k = 0; k <= 4 * 64; ++k) grid.push_back(kTwoPi * (K0 + k / 64.0));
    IntegratorOptions io;
    io.rtol = 1e-11;
    io.atol = 1e-13;
    int sample = 0;
    double worst = 0;
    integrate(m, m.initial_state(), 0.0, grid, io, [&](double t, std::span<const double> y) {
      if (sample % 64 == 0) worst = std::max(worst, (sys.from_modal_model_state(m, t, y, p) - x0).norm());
      if (sample < 4 * 64) {  // whole periods: samples 0..255
        const Observation ob = m.observe(t, y);
        for (std::size_t k = 0; k < 9; ++k) sim_mean[k] += ob.Delta_l[k] / (4 * 64);
      }
      ++sample;
    });
    ASSERT_EQ(sample, 4 * 64 + 1);
    EXPECT_LT(worst, 1e-9) << lambda;
    for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(sim_mean[k], orbit_mean[k], 1e-9) << "l = " << k + 2;
    std::printf(
        "lambda %g: |x_sim(2 pi k) - x0| <= %.3e; <Delta_2> = %.10f, <Delta_3> = %.10f (orbit), %.10f, %.10f "
        "(simulation)\n",
        lambda, worst, orbit_mean[0], orbit_mean[1], sim_mean[0], sim_mean[1]);
  }
}

// A tilted rest shape (beta = 0.7: m = 1 content, v forced with period 4 pi in the lab frame): the
// orbit in the co-rotating frame is 2 pi-periodic with v~ != 0, and a lab-frame modal simulation sits
// on it at every t = 2 pi k, odd k included (where the lab-frame v has flipped sign). 1e-9: the
// simulation's error at rtol 1e-11 after ~100 periods (as above).
TEST(ModalOrbit, TiltedRestShapeOrbitInTheCoRotatingFrameMatchesSimulation) {
  const Scene sim = in_plane(5.0, 0.7, 1e-3, 4);
  const ModalForcedSystem sys(total_area_scene(sim), ContinuationParameter::lambda);
  const double p = sys.start_parameter();
  const int K0 = 96;
  const PeriodicOrbitProblem pr(sys);
  const NewtonResult nr = solve_fixed_parameter(pr, pr.shooting_guess(sys.relaxed_state(sim, kTwoPi * K0), p), p);
  ASSERT_TRUE(nr.converged);
  const Eigen::VectorXd x0 = pr.state_at_zero(nr.x);
  EXPECT_GT(std::hypot(x0[3], x0[4]), 1e-3) << "the m = 1 forcing holds v~ away from 0";
  const ModalModel m(sim.parameters, initial_state(sim));
  std::vector<double> grid;
  for (int k = 0; k <= 3; ++k) grid.push_back(kTwoPi * (K0 + k));
  IntegratorOptions io;
  io.rtol = 1e-11;
  io.atol = 1e-13;
  double worst = 0;
  integrate(m, m.initial_state(), 0.0, grid, io, [&](double t, std::span<const double> y) {
    worst = std::max(worst, (sys.from_modal_model_state(m, t, y, p) - x0).norm());
  });
  EXPECT_LT(worst, 1e-9);
  std::printf("beta 0.7: |v~| = %.6f, max |x_sim(2 pi k) - x0| = %.3e, max |rho| = %.4f\n", std::hypot(x0[3], x0[4]),
              worst, pr.floquet(nr.x, p).multipliers.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace rbcstab
