// Static checks of the three levels: initial states as in the paper (Sec. III-IV, Appendix A),
// the reduced level against the paper's Eqs. red_eqs and st_red, and the modal and reduced flows
// against the full model's right-hand side on the states they represent.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include "model/test_scenes.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/full_model.hpp"
#include "rbcstab/model/modal_model.hpp"
#include "rbcstab/model/reduced_model.hpp"

namespace rbcstab {
namespace {

using testing::fig2_scene;
using testing::fig3_scene;
using testing::generic_scene;
using testing::perturbed;

TEST(InitialState, InPlaneValuesOfSectionIII) {
  const Scene s = fig2_scene(1.0, kPi / 2);
  const InitialState init = initial_state(s);
  const double Delta = s.parameters.Delta, Delta0 = s.parameters.Delta0, a2 = 2;
  // f_{2,+-2} = -(1/2) sqrt(3 Delta/(2 a2)), f_{2,0} = (1/2) sqrt(Delta/a2), likewise g with Delta0.
  EXPECT_NEAR(std::abs(init.f.at(2, 2) - (-0.5 * std::sqrt(3 * Delta / (2 * a2)))), 0, 1e-15);
  EXPECT_NEAR(std::abs(init.f.at(2, -2) - (-0.5 * std::sqrt(3 * Delta / (2 * a2)))), 0, 1e-15);
  EXPECT_NEAR(std::abs(init.f.at(2, 0) - 0.5 * std::sqrt(Delta / a2)), 0, 1e-15);
  EXPECT_NEAR(std::abs(init.g.at(2, 2) - (-0.5 * std::sqrt(3 * Delta0 / (2 * a2)))), 0, 1e-15);
  EXPECT_NEAR(init.f.excess_area(2), Delta, 1e-15);
  EXPECT_NEAR(init.g.excess_area(2), Delta0, 1e-17);
  // r(0) = sqrt(3)/2 and Psi(0) = pi, read through the reduced level's observation.
  ReducedModel red(s.parameters, init);
  const Observation o = red.observe(0, red.initial_state());
  EXPECT_NEAR(std::abs(o.f22) * std::sqrt(4 / o.Delta2), std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(std::abs(std::remainder(-std::arg(o.f22) - kPi, 2 * kPi)), 0, 1e-15);
}

TEST(InitialState, PerturbationsCarryDeltaInEveryMode) {
  for (double beta : {0.001, kPi / 2, 0.7}) {
    const Scene s = fig3_scene(beta);
    const InitialState init = initial_state(s);
    // Rotation preserves each Delta_l: the column is a unit vector (checked to 1e-12 in wigner_test).
    EXPECT_NEAR(init.f.excess_area(2), s.parameters.Delta, 1e-12);
    for (int l = 3; l <= s.L; ++l) {
      EXPECT_NEAR(init.f.excess_area(l), s.delta, 1e-12 * s.delta) << "l = " << l;
      EXPECT_EQ(init.g.excess_area(l), 0) << "l = " << l;
    }
    // Reality f_{l,-m} = (-1)^m conj f_{l,m}.
    for (int l = 2; l <= s.L; ++l)
      for (int m = 1; m <= l; ++m) EXPECT_EQ(init.f.at(l, -m), (m % 2 ? -1.0 : 1.0) * std::conj(init.f.at(l, m)));
  }
}

// A scene checked once (validated) gives the same initial state and system as the plain scene, whose overloads
// still check: the proof cannot be had for an invalid scene.
TEST(InitialState, AValidatedSceneIsTheSameSceneCheckedOnce) {
  Scene s;
  s.L = 6;
  const ValidScene valid = validated(s);
  EXPECT_EQ(&*valid, &s);
  const InitialState a = initial_state(s), b = initial_state(valid);
  for (int l = 2; l <= s.L; ++l)
    for (int m = -l; m <= l; ++m) {
      EXPECT_EQ(a.f.at(l, m), b.f.at(l, m));
      EXPECT_EQ(a.g.at(l, m), b.g.at(l, m));
    }
  EXPECT_EQ(make_scene_system(valid).level.level, make_scene_system(s).level.level);
  s.L = 1;
  EXPECT_THROW(validated(s), InvalidArgument);
  EXPECT_THROW(initial_state(s), InvalidArgument);
  EXPECT_THROW(make_scene_system(s), InvalidArgument);
}

// A lower L of a checked scene is checked only for what L decides; the copy is what validate() accepts.
TEST(InitialState, AValidSceneAtAnotherLChecksOnlyWhatLDecides) {
  Scene s;
  s.L = 8;
  s.delta_l[5] = 1e-3;
  const ValidScene valid = validated(s);
  Scene copy;
  const ValidScene at6 = validated_at_L(valid, copy, 6);
  EXPECT_EQ(&*at6, &copy);
  EXPECT_EQ(copy.L, 6);
  EXPECT_NO_THROW(copy.validate());
  // Below a mode the scene sets, or outside L's range: refused, as validate() refuses that scene.
  for (int L : {4, 1, kMaxL + 1}) {
    Scene c;
    EXPECT_THROW(validated_at_L(valid, c, L), InvalidArgument) << "L = " << L;
    Scene direct = s;
    direct.L = L;
    EXPECT_THROW(direct.validate(), InvalidArgument) << "L = " << L;
  }
}

TEST(LevelChoice, SmallestExactLevel) {
  {
    const Scene s = fig3_scene(0.001);
    EXPECT_EQ(choose_level(s, initial_state(s)).level, ModelLevel::modal);
  }
  {
    const Scene s = fig2_scene(1.0, kPi / 2);
    EXPECT_EQ(choose_level(s, initial_state(s)).level, ModelLevel::reduced);
  }
  {
    const Scene s = fig2_scene(1.0, 0.0);
    EXPECT_EQ(choose_level(s, initial_state(s)).level, ModelLevel::reduced);
  }
  {
    Scene s = generic_scene(5, true);
    EXPECT_EQ(choose_level(s, initial_state(s)).level, ModelLevel::full);
    s.model = ModelLevel::modal;
    EXPECT_THROW(choose_level(s, initial_state(s)), InvalidArgument);
  }
  {
    // beta = 0.001 puts ~1e-6 of f_{2,+-1}: the reduced level would not be exact.
    Scene s = fig2_scene(1.0, 0.001);
    EXPECT_EQ(choose_level(s, initial_state(s)).level, ModelLevel::modal);
    s.model = ModelLevel::reduced;
    const LevelChoice c = choose_level(s, initial_state(s));
    EXPECT_EQ(c.level, ModelLevel::reduced);
    EXPECT_FALSE(c.exact);
  }
}

// A random point (Re z, Im z, w) of the unit sphere with w > 0.
std::vector<double> random_sphere_point(std::mt19937& gen) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<double> y{n(gen), n(gen), std::abs(n(gen))};
  const double q = std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
  for (double& v : y) v /= q;
  return y;
}

class ReducedAgainstPaper : public ::testing::TestWithParam<Scene> {};

TEST_P(ReducedAgainstPaper, RhsEqualsEqRedEqsByChainRule) {
  const Scene s = GetParam();
  const Parameters& p = s.parameters;
  ReducedModel red(p, initial_state(s));
  const double Lambda = p.Lambda(), S = p.S();
  // kappa = (Lambda S)^-1 computed from the paper's Lambda and S (Eq. Lambda_S) here, not reused.
  const double kappa = std::isfinite(S) ? 1 / (Lambda * S) : 0.0;
  // The paper's Eq. subs writes f_{2,0} = -sqrt(Delta (1 - r^2)/a_2), i.e. w = sqrt(1 - r^2) >= 0, and
  // likewise w0 >= 0. The in-plane start (beta = pi/2) has f_{2,0}, g_{2,0} > 0, i.e. w, w0 < 0: the
  // paper's formulas hold with the product w w0 = +sqrt((1 - r0^2)(1 - r^2)), i.e. for sign(w) = sign(w0).
  // (The regular form carries the signed product w w0, which also covers w crossing 0 at r = 1.)
  const InitialState init = initial_state(s);
  const double w0_sign = init.g.at(2, 0).real() > 0 ? -1.0 : 1.0;
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> ut(0.0, 40.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> y = random_sphere_point(gen);
    y[2] *= w0_sign;
    const double t = ut(gen);
    std::vector<double> dy(3);
    red.rhs(t, y, dy);
    const std::complex<double> z(y[0], y[1]), dz(dy[0], dy[1]);
    const double r = std::abs(z), Psi = -std::arg(z);
    // r' and Psi' by the chain rule on z = r e^{-i Psi}.
    const double r_dot = std::real(std::conj(z) * dz) / r;
    const double Psi_dot = -std::imag(std::conj(z) * dz) / (r * r);
    // The stress-free shape: z0(t) = r0 e^{-i Phi(t)}; Phi' = -1 is checked separately.
    const std::complex<double> z0 = red.z0(t);
    const double r0 = std::abs(z0), Phi = -std::arg(z0);
    const double r_paper = (1 - r * r) * std::sin(Psi) / Lambda + kappa * (r0 * (1 - r * r) * std::cos(Phi - Psi) -
                                                                           r * std::sqrt((1 - r0 * r0) * (1 - r * r)));
    const double Psi_paper = -1 + std::cos(Psi) / (Lambda * r) + kappa * r0 / r * std::sin(Phi - Psi);
    // Terms are O(1/Lambda + kappa) (and /r for Psi'); both sides are a few roundings: 1e-12.
    const double sc = 1 / Lambda + kappa + 1;
    EXPECT_NEAR(r_dot, r_paper, 1e-12 * sc) << "trial " << trial;
    EXPECT_NEAR(Psi_dot, Psi_paper, 1e-12 * sc / r) << "trial " << trial << ", r = " << r;
    // The unit sphere is invariant: d/dt (|z|^2 + w^2) = 0.
    EXPECT_NEAR(y[0] * dy[0] + y[1] * dy[1] + y[2] * dy[2], 0, 1e-13 * sc);
    // sigma_R of Eq. st_red.
    const double B = p.B, C = p.C, D = p.Delta, D0 = p.Delta0;
    const double sigma_paper =
        -6 + std::sqrt(30 * kPi) * B / (3 * std::sqrt(D)) * r * std::sin(Psi) +
        (std::isfinite(C) ? 2 * B / (3 * C) : 0.0) *
            (std::sqrt(D0 / D) * (r0 * r * std::cos(Phi - Psi) + std::sqrt((r0 * r0 - 1) * (r * r - 1))) - 1);
    const double sigma_scale = 6 + std::sqrt(30 * kPi) * B / (3 * std::sqrt(D)) + p.alpha();
    EXPECT_NEAR(red.observe(t, y).sigma, sigma_paper, 1e-13 * sigma_scale) << "trial " << trial;
  }
  // Phi' = -1: z0(t) = z0(0) e^{it}.
  const std::complex<double> z0a = red.z0(0.0), z0b = red.z0(0.25);
  if (std::abs(z0a) > 0) {
    EXPECT_NEAR(std::arg(z0b / z0a), 0.25, 1e-14);
  }
}

Scene with_params(Scene s, double Delta0, double C) {
  s.parameters.Delta0 = Delta0;
  s.parameters.C = C;
  return s;
}

INSTANTIATE_TEST_SUITE_P(Scenes, ReducedAgainstPaper,
                         ::testing::Values(fig2_scene(0.01, kPi / 2), fig2_scene(1.0, kPi / 2), fig2_scene(1.0, 1.1),
                                           with_params(fig2_scene(1.0, kPi / 2), 0.0, 0.04),
                                           with_params(fig2_scene(0.3, kPi / 2), 0.02, INFINITY)));

// The modal (or reduced) flow, mapped to amplitudes, must be the full model's flow there:
// full.rhs(t, f(t, y)) = d/dt f(t, y(t)) with y' = F_level(t, y), by central differences in t.
void expect_flow_matches_full(const System& level, const FullModel& full, const std::vector<double>& y, double t) {
  const std::size_t n = level.dimension();
  std::vector<double> F(n), yp(n), ym(n);
  level.rhs(t, y, F);
  const double h = 1e-5;
  for (std::size_t i = 0; i < n; ++i) {
    yp[i] = y[i] + h * F[i];
    ym[i] = y[i] - h * F[i];
  }
  const ModeAmplitudes fp = level.amplitudes(t + h, yp), fm = level.amplitudes(t - h, ym), f = level.amplitudes(t, y);
  std::vector<double> yf(full.dimension()), Ff(full.dimension());
  for (std::size_t k = 0; k < f.values.size(); ++k) {
    yf[2 * k] = f.values[k].real();
    yf[2 * k + 1] = f.values[k].imag();
  }
  full.rhs(t, yf, Ff);
  double scale = 0;
  for (double v : Ff) scale = std::max(scale, std::abs(v));
  // Central difference along the flow: O(h^2 |f'''|) ~ 1e-10 of the scale; 1e-7 bound.
  for (std::size_t k = 0; k < f.values.size(); ++k) {
    const std::complex<double> fd = (fp.values[k] - fm.values[k]) / (2 * h);
    ASSERT_NEAR(fd.real(), Ff[2 * k], 1e-7 * scale) << "k = " << k;
    ASSERT_NEAR(fd.imag(), Ff[2 * k + 1], 1e-7 * scale) << "k = " << k;
  }
  // The same state has the same tension at both levels (sigma is a function of the amplitudes).
  EXPECT_NEAR(level.observe(t, y).sigma, full.observe(t, yf).sigma, 1e-12 * std::abs(full.observe(t, yf).sigma));
  const Observation ol = level.observe(t, y), of = full.observe(t, yf);
  for (std::size_t j = 0; j < ol.Delta_l.size(); ++j) EXPECT_NEAR(ol.Delta_l[j], of.Delta_l[j], 1e-14);
}

TEST(LevelFlows, ModalFlowIsTheFullFlow) {
  for (const Scene& s : {generic_scene(6, false), fig3_scene(kPi / 2), fig3_scene(0.001)}) {
    const InitialState init = initial_state(s);
    ModalModel modal(s.parameters, init);
    FullModel full(s.parameters, init);
    // Generic modal states: the l = 2 block and ln Delta_l perturbed, at several times.
    for (unsigned seed : {1u, 2u, 3u}) {
      const std::vector<double> y = perturbed(modal.initial_state(), 0.3, seed);
      expect_flow_matches_full(modal, full, y, 0.9 * seed);
    }
  }
}

TEST(LevelFlows, ReducedFlowIsTheFullFlow) {
  for (const Scene& s : {fig2_scene(1.0, kPi / 2), fig2_scene(0.01, kPi / 2), fig2_scene(1.0, 0.0)}) {
    const InitialState init = initial_state(s);
    ReducedModel red(s.parameters, init);
    FullModel full(s.parameters, init);
    std::mt19937 gen(5);
    for (int trial = 0; trial < 5; ++trial) expect_flow_matches_full(red, full, random_sphere_point(gen), 1.7 * trial);
  }
}

TEST(FullTension, KeepsExcessAreaConstantAndMatchesEqStWithRealPart) {
  // At generic states of a scene without symmetry (all m, stress-free l >= 3 content):
  // (1) the tension makes dDelta/dt = sum_l a_l sum_m 2 Re(conj(f) f') vanish (its definition);
  // (2) it equals the paper's Eq. st evaluated with complex amplitudes, with the real part taken;
  // (3) the bracket of Eq. st has a non-zero imaginary part, so the printed form (without Re) is not real.
  const Scene s = generic_scene(6, true);
  const InitialState init = initial_state(s);
  FullModel full(s.parameters, init);
  const Parameters& p = s.parameters;
  double max_imag = 0;
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    const std::vector<double> y = perturbed(full.initial_state(), 0.5, seed);
    const double t = 0.77 * seed;
    std::vector<double> dy(y.size());
    full.rhs(t, y, dy);
    const ModeAmplitudes f = full.amplitudes(t, y);
    double dDelta = 0, scale = 0;
    std::complex<double> bracket = 0;
    double denom = 0;
    for (int l = 2; l <= s.L; ++l)
      for (int m = -l; m <= l; ++m) {
        const std::size_t k = ModeAmplitudes::index(l, m);
        const std::complex<double> fk(y[2 * k], y[2 * k + 1]), dfk(dy[2 * k], dy[2 * k + 1]);
        dDelta += a_l(l) * 2 * std::real(std::conj(fk) * dfk);
        scale += a_l(l) * 2 * std::abs(fk) * std::abs(dfk);
        // g_{l,m}(t) = g_{l,m}(0) e^{i m t/2} (Eq. eom_g); S = C_{l,m} - Gamma3/C g (Eq. eom_sup).
        const std::complex<double> g = init.g.at(l, m) * std::polar(1.0, 0.5 * m * t);
        const std::complex<double> S = shear_drive(p.lambda, l, m) - Gamma3(p.lambda, l) / p.C * g;
        bracket += a_l(l) * (Gamma1(p.lambda, l) / p.B * f.at(l, m) + Gamma3(p.lambda, l) / p.C * f.at(l, m) + S) *
                   std::conj(f.at(l, m));
        denom += Gamma2(p.lambda, l) * a_l(l) * std::norm(f.at(l, m));
      }
    // Cancellation of O(scale) terms: 1e-13 relative.
    EXPECT_NEAR(dDelta, 0, 1e-13 * scale) << "seed " << seed;
    const double sigma_paper = -p.B / denom * bracket.real();
    const double sigma = full.sigma(t, y);
    EXPECT_NEAR(sigma, sigma_paper, 1e-12 * std::abs(sigma)) << "seed " << seed;
    max_imag = std::max(max_imag, std::abs(p.B / denom * bracket.imag()) / std::abs(sigma));
  }
  EXPECT_GT(max_imag, 1e-3) << "Eq. st without Re would be complex at these states";
}

TEST(ModalTension, KeepsExcessAreaConstant) {
  const Scene s = generic_scene(8, false);
  ModalModel modal(s.parameters, initial_state(s));
  for (unsigned seed : {1u, 2u, 3u}) {
    const std::vector<double> y = perturbed(modal.initial_state(), 0.3, seed);
    std::vector<double> dy(y.size());
    modal.rhs(1.1 * seed, y, dy);
    // Delta_2 = a_2 (f20^2 + 2 |f21|^2 + 2 |f22|^2); Delta_l = exp(u_l).
    const double a2 = 2;
    double dDelta = 2 * a2 * (y[0] * dy[0] + 2 * (y[1] * dy[1] + y[2] * dy[2] + y[3] * dy[3] + y[4] * dy[4]));
    double scale = std::abs(dDelta);
    for (std::size_t j = 5; j < y.size(); ++j) {
      dDelta += std::exp(y[j]) * dy[j];
      scale += std::abs(std::exp(y[j]) * dy[j]);
    }
    EXPECT_NEAR(dDelta, 0, 1e-13 * scale) << "seed " << seed;
  }
}

TEST(InitialTension, OutOfPlaneStartMatchesSectionIV) {
  // Sec. IV: at r = r0 = 0 (beta = 0), sigma_R^init = -6 + (2/3) alpha (sqrt(Delta0/Delta) - 1), exact there.
  for (double Delta : {0.01, 0.3, 1.0}) {
    Scene s = fig2_scene(Delta, 0.0);
    const Parameters& p = s.parameters;
    const double expected = -6 + 2.0 / 3 * p.alpha() * (std::sqrt(p.Delta0 / p.Delta) - 1);
    for (ModelLevel level : {ModelLevel::full, ModelLevel::modal, ModelLevel::reduced}) {
      const auto sys = make_system(p, initial_state(s), level);
      // A few roundings of O(alpha) terms: 1e-13 relative.
      EXPECT_NEAR(sys->observe(0, sys->initial_state()).sigma, expected, 1e-13 * std::abs(expected))
          << to_string(level) << ", Delta = " << Delta;
    }
  }
}

}  // namespace
}  // namespace rbcstab
