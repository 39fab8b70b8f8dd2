// The native rk8pd stepper (integrate/detail/prince_dormand.hpp) and the compact forms it steps
// (model/system.hpp).
//
// Oracles: GSL's own rk8pd, driven by gsl_odeiv2_evolve_apply with the standard control on the same system (the
// same method and control: the steps and states must be the same bit for bit); the modal level stepped on its full
// state (the compact form is a change of unknowns: the same steps up to rounding, the same states to rounding);
// the model's own right-hand side (the compact one must rebuild it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "integrate/rk8pd_fixtures.hpp"
#include "model/test_scenes.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/modal_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {
namespace {

using testing::fig3_scene;
using testing::FullState;
using testing::gsl_rk8pd;
using testing::native_rk8pd;
using testing::Steps;

IntegratorOptions rk8pd(double rtol, double atol) {
  IntegratorOptions o;
  o.stepper = Stepper::rk8pd;
  o.rtol = rtol;
  o.atol = atol;
  return o;
}

// Every level (the modal one on its full state) at two tolerances, through an output grid whose times cut steps
// short: the same accepted and rejected steps and the same samples, bit for bit.
TEST(PrinceDormand, BitForBitWithGslsRk8pd) {
  struct Case {
    ModelLevel level;
    double beta;
    int L;
  };
  for (const Case c : {Case{ModelLevel::full, 0.001, 5}, Case{ModelLevel::modal, 0.001, 10},
                       Case{ModelLevel::modal, std::numbers::pi / 2, 10}, Case{ModelLevel::reduced, 0.0, 2}}) {
    Scene scene = fig3_scene(c.beta);
    scene.L = c.L;
    scene.model = c.level;
    if (c.level == ModelLevel::reduced) scene.delta = 0;
    const SceneSystem ss = make_scene_system(scene);
    const FullState plain(*ss.system);
    const std::vector<double> grid = {0.37, 10, 55.5, 120};
    for (double rtol : {1e-6, 1e-10}) {
      const IntegratorOptions o = rk8pd(rtol, rtol * 1e-4);
      const Steps a = native_rk8pd(plain, grid, o), b = gsl_rk8pd(plain, grid, o);
      const std::string what = to_string(c.level) + " L = " + std::to_string(c.L) + " rtol " + std::to_string(rtol);
      EXPECT_EQ(a.steps, b.steps) << what;
      EXPECT_EQ(a.failed, b.failed) << what;
      EXPECT_GT(a.failed, 0u) << what;  // the rejection path is exercised
      ASSERT_EQ(a.samples.size(), grid.size()) << what;
      ASSERT_EQ(b.samples.size(), grid.size()) << what;
      for (std::size_t k = 0; k < a.samples.size(); ++k)
        EXPECT_EQ(a.samples[k], b.samples[k]) << what << " sample " << k;
    }
  }
}

// The compact form rebuilds the modal state exactly where it starts, and its right-hand side is the model's:
// the l = 2 block's rates are the same numbers, each u_l' = scale (s' + (reference - pivot) tau') equals
// 2 Upsilon_l(sigma) to rounding of 2 Upsilon_l' sigma.
TEST(PrinceDormand, CompactFormRebuildsTheModalState) {
  Scene scene = fig3_scene(0.001);
  scene.delta_l = {{4, 0.02}, {7, 1e-9}};
  const SceneSystem ss = make_scene_system(scene);
  ASSERT_EQ(ss.system->level(), ModelLevel::modal);
  const std::vector<double> y0 = ss.system->initial_state();
  std::optional<CompactForm> form = ss.system->compact_form(y0);
  ASSERT_TRUE(form.has_value());
  EXPECT_EQ(form->x0.size(), 7u);  // the l = 2 block, s, tau
  std::vector<double> y(y0.size()), dy(y0.size()), dx(form->x0.size());
  form->expand(form->x0, y);
  EXPECT_EQ(y, y0);
  // Away from the start: s and tau nonzero, a reference set as a stepper centres it.
  std::vector<double> x = form->x0;
  x[0] *= 0.9;
  x[3] += 0.05;
  x[5] = -3.25;
  x[6] = 0.75;
  form->reference[5] = -12.5;
  const double t = 3.3;
  form->expand(x, y);
  ss.system->compact_rhs(t, x, *form, dx);
  ss.system->rhs(t, y, dy);
  EXPECT_EQ(dx[6], 1.0);
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(dx[k], dy[k]) << k;
  const double sigma = dx[5] + form->reference[5];
  for (std::size_t k = 5; k < y.size(); ++k)
    EXPECT_NEAR(form->rate(k, dx), dy[k], 4e-16 * std::abs(form->scale[k] * sigma) + 1e-300) << k;
  // rebase keeps the state and restarts the integrals.
  std::vector<double> before(y.size()), after(y.size());
  form->expand(x, before);
  form->rebase(x);
  form->expand(x, after);
  EXPECT_EQ(x[5], 0.0);
  EXPECT_EQ(x[6], 0.0);
  EXPECT_EQ(form->reference[5], 0.0);
  EXPECT_EQ(after, before);
}

// Stepping the compact form against stepping the full state (the same method and control on a change of
// unknowns): the same steps up to one and every sample to rounding. Measured over T = 500 at rtol 1e-8 and 1e-12,
// out of plane and in plane: 910/910, 2201/2201, 1365/1365 and 3997/3998 steps; Delta_l within 2.6e-14 (Delta = 1),
// sigma within 3.6e-15 relative. Bounds: 5 steps in a thousand, 100 times the rest.
TEST(PrinceDormand, CompactFormTakesTheSameStepsAsTheFullState) {
  for (double beta : {0.001, std::numbers::pi / 2}) {
    Scene scene = fig3_scene(beta);
    const SceneSystem ss = make_scene_system(scene);
    const FullState plain(*ss.system);
    std::vector<double> grid;
    for (double t = 50; t <= 500; t += 50) grid.push_back(t);
    for (double rtol : {1e-8, 1e-12}) {
      const IntegratorOptions o = rk8pd(rtol, 1e-16);
      const Steps a = native_rk8pd(*ss.system, grid, o), b = native_rk8pd(plain, grid, o);
      EXPECT_NEAR(double(a.steps), double(b.steps), 0.005 * double(b.steps)) << beta << " " << rtol;
      ASSERT_EQ(a.samples.size(), grid.size());
      ASSERT_EQ(b.samples.size(), grid.size());
      for (std::size_t k = 0; k < a.samples.size(); ++k) {
        const Observation oa = ss.system->observe(grid[k], a.samples[k]),
                          ob = ss.system->observe(grid[k], b.samples[k]);
        for (std::size_t l = 0; l < oa.Delta_l.size(); ++l)
          EXPECT_NEAR(oa.Delta_l[l], ob.Delta_l[l], 2.6e-12)
              << beta << " " << rtol << " t = " << grid[k] << " l = " << l + 2;
        EXPECT_NEAR(oa.sigma, ob.sigma, 3.6e-13 * std::abs(ob.sigma)) << beta << " " << rtol << " t = " << grid[k];
      }
    }
  }
}

}  // namespace
}  // namespace rbcstab
