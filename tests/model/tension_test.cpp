// The single tension (model/tension.hpp) and growth rate (GrowthRate) behind every level:
//  - each level's rhs keeps the total excess area constant, checked by central differences of Delta along
//    the flow, Delta computed from the state alone (observe().Delta_l) with no reference to sigma;
//  - AreaBalance::sigma is the zero of N + sigma D and sigma_change its derivative;
//  - Upsilon_l vanishes at sigma_l^c and sigma_at inverts it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <string>

#include "model/test_scenes.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/tension.hpp"

namespace rbcstab {
namespace {

using testing::fig2_scene;
using testing::generic_scene;
using testing::perturbed;

double total_area(const System& sys, double t, const std::vector<double>& y) {
  const std::vector<double> D = sys.observe(t, y).Delta_l;
  return std::accumulate(D.begin(), D.end(), 0.0);
}

// d/dt Delta(y(t)) along y' = F(t, y) by central differences over (t -+ h, y -+ h F), Richardson-extrapolated
// (Delta is quadratic in the full and reduced states, smooth in the modal u_l whose rates reach |F| ~ 1e2).
// The scale is sum_i |dDelta/dy_i F_i|, from the same differences one component at a time: the balance
// cancels terms of that size.
void expect_area_constant(const System& sys, double t, const std::vector<double>& y, const std::string& what) {
  const std::size_t n = sys.dimension();
  std::vector<double> F(n), yp(y), ym(y);
  sys.rhs(t, y, F);
  double Fmax = 1;
  for (double f : F) Fmax = std::max(Fmax, std::abs(f));
  const double h = 1e-3 / Fmax;  // h |F| <= 1e-3
  double scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    yp = y;
    ym = y;
    yp[i] += h * F[i];
    ym[i] -= h * F[i];
    scale += std::abs(total_area(sys, t, yp) - total_area(sys, t, ym)) / (2 * h);
  }
  const auto rate = [&](double k) {
    for (std::size_t i = 0; i < n; ++i) {
      yp[i] = y[i] + k * F[i];
      ym[i] = y[i] - k * F[i];
    }
    return (total_area(sys, t + k, yp) - total_area(sys, t - k, ym)) / (2 * k);
  };
  const double dDelta = (4 * rate(h / 2) - rate(h)) / 3;
  ASSERT_GT(scale, 1e-3) << what << ": the state moves area between components (the check is not vacuous)";
  // Truncation (h |F|)^4 / 120 ~ 1e-14 of the scale; rounding eps |Delta| / h ~ 1e-11 |F|. Bound 1e-8.
  EXPECT_NEAR(dDelta, 0.0, 1e-8 * scale) << what;
}

TEST(AreaConstraintTension, KeepsTheExcessAreaConstantAtEveryLevel) {
  // Full: no symmetry, all m, stress-free l >= 3 content (explicit time dependence of every S_{l,m}).
  {
    const Scene s = generic_scene(6, true);
    const auto full = make_system(s.parameters, initial_state(s), ModelLevel::full);
    for (unsigned seed : {1u, 2u, 3u})
      expect_area_constant(*full, 0.7 * seed, perturbed(full->initial_state(), 0.4, seed), "full");
  }
  // Modal: the l = 2 block and ln Delta_l of several perturbed modes.
  {
    const Scene s = generic_scene(8, false);
    const auto modal = make_system(s.parameters, initial_state(s), ModelLevel::modal);
    for (unsigned seed : {1u, 2u, 3u})
      expect_area_constant(*modal, 1.1 * seed, perturbed(modal->initial_state(), 0.3, seed), "modal");
  }
  // Reduced: in and off the unit sphere (Q = |z|^2 + w^2 is conserved wherever the state is).
  for (const Scene& s : {fig2_scene(1.0, std::numbers::pi / 2), fig2_scene(0.01, 1.1)}) {
    const auto reduced = make_system(s.parameters, initial_state(s), ModelLevel::reduced);
    for (unsigned seed : {1u, 2u, 3u})
      expect_area_constant(*reduced, 0.9 * seed, perturbed(reduced->initial_state(), 0.3, seed), "reduced");
  }
}

TEST(AreaConstraintTension, IsTheZeroOfTheBalanceAndDifferentiatesIt) {
  const Parameters p{2.5, 0.8, 0.05, 1.7, 0.3};
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  AreaBalance b;
  std::vector<double> Delta;
  for (int l = 2; l <= 7; ++l) {
    Delta.push_back(U(gen));
    b.add_mode(Upsilon_l(p, l), Delta.back());
  }
  const double W = 0.37;
  b.add_work(W);
  const double sigma = b.sigma();
  // The balance sum_l Upsilon_l(sigma) Delta_l + W written from the rates themselves.
  double balance = W, size = std::abs(W);
  for (int l = 2; l <= 7; ++l) {
    balance += Upsilon_l(p, l, sigma) * Delta[std::size_t(l - 2)];
    size += std::abs(Upsilon_l(p, l, sigma) * Delta[std::size_t(l - 2)]);
  }
  EXPECT_NEAR(balance, 0.0, 1e-14 * size);
  // sigma_change against a central difference of -N/D in each sum.
  const double hN = 1e-6 * std::abs(b.N), hD = 1e-6 * std::abs(b.D);
  const auto sigma_of = [](double N, double D) { return AreaBalance{N, D}.sigma(); };
  EXPECT_NEAR(b.sigma_change(1.0, 0.0), (sigma_of(b.N + hN, b.D) - sigma_of(b.N - hN, b.D)) / (2 * hN),
              1e-8 * std::abs(b.sigma_change(1.0, 0.0)));
  EXPECT_NEAR(b.sigma_change(0.0, 1.0), (sigma_of(b.N, b.D + hD) - sigma_of(b.N, b.D - hD)) / (2 * hD),
              1e-8 * std::abs(b.sigma_change(0.0, 1.0)));
}

TEST(GrowthRate, VanishesAtSigmaCriticalAndInverts) {
  for (const Parameters& p : {Parameters{5.0, 1.0, 0.01, 2.0, 0.04}, Parameters{0.0, 0.3, 0.0, 0.7, INFINITY},
                              Parameters{20.0, 2.0, 1.0, 40.0, 1e-3}}) {
    for (int l = 2; l <= 30; ++l) {
      const GrowthRate Y = Upsilon_l(p, l);
      EXPECT_EQ(Y.sigma_c, sigma_c(l, p.alpha())) << "l = " << l;
      EXPECT_EQ(Y(sigma_c(l, p.alpha())), 0.0) << "l = " << l;  // the affine form is exact at its zero
      EXPECT_DOUBLE_EQ(Y.slope, Gamma2(p.lambda, l) / p.B) << "l = " << l;
      for (double sigma : {-80.0, -12.5, 0.0, 3.0}) {
        // Eq. eom_sup_ups as printed, to rounding of its O(|Gamma| |sigma| / B) terms.
        const double printed = (Gamma1(p.lambda, l) + sigma * Gamma2(p.lambda, l)) / p.B + Gamma3(p.lambda, l) / p.C;
        const double size = (std::abs(Gamma1(p.lambda, l)) + std::abs(sigma * Gamma2(p.lambda, l))) / p.B +
                            std::abs(Gamma3(p.lambda, l) / p.C);
        EXPECT_NEAR(Y(sigma), printed, 1e-14 * size) << "l = " << l << ", sigma = " << sigma;
        EXPECT_NEAR(Y.sigma_at(Y(sigma)), sigma, 1e-13 * (std::abs(sigma) + std::abs(Y.sigma_c)))
            << "l = " << l << ", sigma = " << sigma;
      }
    }
  }
}

}  // namespace
}  // namespace rbcstab
