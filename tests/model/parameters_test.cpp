// Parameters: derived quantities (Eq. Lambda_S, alpha) and validation messages.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {
namespace {

TEST(Parameters, DerivedQuantitiesMatchFig2Caption) {
  // Fig. 2: C = 0.04, lambda = 5, Delta0 = 0.01: S ~ 2, Lambda ~ 0.19 (Delta = 0.01) and 1.9 (Delta = 1).
  Parameters p{5.0, 0.01, 0.01, 2.0, 0.04};
  EXPECT_NEAR(p.Lambda(), 0.19, 0.005);
  EXPECT_NEAR(p.S(), 2.0, 0.2);
  p.Delta = 1;
  EXPECT_NEAR(p.Lambda(), 1.9, 0.05);
  // Eq. Lambda_S, independently: Lambda = sqrt(Delta)(23 lambda + 32)/(8 sqrt(30 pi)), S = C sqrt(15 pi/(2 Delta0)).
  EXPECT_NEAR(p.Lambda(), std::sqrt(1.0) * (23 * 5.0 + 32) / (8 * std::sqrt(30 * kPi)), 1e-15);
  EXPECT_NEAR(p.S(), 0.04 * std::sqrt(15 * kPi / 0.02), 1e-14);
  EXPECT_NEAR(p.inv_Lambda_S(), 1 / (p.Lambda() * p.S()), 1e-14 / (p.Lambda() * p.S()));
  EXPECT_DOUBLE_EQ(p.alpha(), 50.0);
}

TEST(Parameters, VesicleLimitsAreFinite) {
  Parameters p{1.0, 0.5, 0.0, 1.0, 0.1};
  EXPECT_NO_THROW(p.validate());
  EXPECT_TRUE(std::isinf(p.S()));
  EXPECT_EQ(p.inv_Lambda_S(), 0.0);
  p.Delta0 = 0.1;
  p.C = INFINITY;
  EXPECT_NO_THROW(p.validate());
  EXPECT_EQ(p.alpha(), 0.0);
  EXPECT_EQ(p.inv_Lambda_S(), 0.0);
}

void expect_refused(Parameters p, const std::string& name, const std::string& range_fragment) {
  try {
    p.validate();
    ADD_FAILURE() << name << " accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), name);
    const std::string what = e.what();
    EXPECT_NE(what.find(name + " = "), std::string::npos) << what;
    EXPECT_NE(what.find(range_fragment), std::string::npos) << what;
  }
}

TEST(Parameters, OutOfRangeValuesNameParameterValueAndRange) {
  const Parameters ok;
  EXPECT_NO_THROW(ok.validate());
  Parameters p = ok;
  p.B = -1;
  expect_refused(p, "B", "> 0");
  p = ok;
  p.C = NAN;
  expect_refused(p, "C", "> 0");
  p = ok;
  p.C = 0;
  expect_refused(p, "C", "> 0");
  p = ok;
  p.Delta = 20;
  expect_refused(p, "Delta", "(0, 4 pi)");
  p = ok;
  p.Delta0 = 2;
  expect_refused(p, "Delta0", "[0, Delta]");
  p = ok;
  p.lambda = -0.1;
  expect_refused(p, "lambda", ">= 0");
  p = ok;
  p.lambda = INFINITY;
  expect_refused(p, "lambda", "finite");
  p = ok;
  p.Delta = 2;
  EXPECT_NO_THROW(p.validate());
  EXPECT_EQ(p.warnings().size(), 1u);
}

TEST(Scene, ValidateNamesKey) {
  Scene s;
  s.L = 1;
  try {
    s.validate();
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "L");
    EXPECT_NE(std::string(e.what()).find("[2, 100]"), std::string::npos);
  }
  s = Scene{};
  s.delta = -1;
  EXPECT_THROW(s.validate(), InvalidArgument);
  s = Scene{};
  s.dt = 2 * s.T;
  EXPECT_THROW(s.validate(), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
