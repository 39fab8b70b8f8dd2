// The physical phase diagram (verdict/physical_map.hpp) against identities of the model's scaling: the reduced
// flow depends on lambda, Delta, Delta0, C and beta only, so at fixed lambda the tumbling -> swinging boundary sits
// at one C = eta_ex gamma R / mu: its rate scales as mu/(eta_ex R) exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/verdict/physical_map.hpp"
#include "verdict/physical_map_cell.hpp"

namespace rbcstab {
namespace {

Scene cell(double eta_in = 6e-3) { return test::map_cell(eta_in); }
PhysicalMapOptions fast(double eta_lo, double eta_hi, int n) { return test::fast_map(eta_lo, eta_hi, n); }

// Doubling eta_in and eta_ex together keeps lambda, so the boundary keeps its C: the rate halves.
TEST(PhysicalMap, TumblingBoundaryKeepsItsStressAtFixedLambda) {
  const PhysicalMap a = physical_map(cell(6e-3), fast(25e-3, 25e-3, 1));
  const PhysicalMap b = physical_map(cell(12e-3), fast(50e-3, 50e-3, 1));
  const RateCrossing& x = a.columns[0].tumbling_to_swinging;
  const RateCrossing& y = b.columns[0].tumbling_to_swinging;
  ASSERT_TRUE(x.found) << x.reason;
  ASSERT_TRUE(y.found) << y.reason;
  EXPECT_DOUBLE_EQ(a.columns[0].lambda, b.columns[0].lambda);
  // Each rate is the upper end of a bracket hi/lo - 1 <= rtol = 1e-4: the ratio is 0.5 to about 2e-4.
  EXPECT_NEAR(y.rate / x.rate, 0.5, 1e-4);
  // And the bracket is a true bracket: tumbling at lo, not at hi (the crossing is where the regime changes).
  EXPECT_LT(x.lo, x.rate);
  EXPECT_LE(x.rate / x.lo - 1, 1e-4);
}

// A spread in mu moves only C's scale: the band's ends are the nominal rate times mu_end/mu (to the bisection).
TEST(PhysicalMap, ShearModulusBandScalesTheBoundary) {
  PhysicalMapOptions o = fast(25e-3, 25e-3, 1);
  o.spreads = {{"shear_modulus", 3e-6, 12e-6, "test"}};
  const PhysicalMap m = physical_map(cell(), o);
  const PhysicalMapColumn& c = m.columns[0];
  ASSERT_TRUE(c.tumbling_to_swinging.found);
  EXPECT_EQ(c.tumbling_band.cells, 3);
  EXPECT_EQ(c.tumbling_band.found, 3);
  EXPECT_NEAR(c.tumbling_band.lo / c.tumbling_to_swinging.rate, 0.5, 1e-4);
  EXPECT_NEAR(c.tumbling_band.hi / c.tumbling_to_swinging.rate, 2.0, 4e-4);
  EXPECT_EQ(c.tumbling_band.lo_key, "shear_modulus = 3e-06");
  EXPECT_EQ(c.tumbling_band.hi_key, "shear_modulus = 1.2e-05");
}

// The onset equals the summary's search at the column's viscosity (one search, two callers), and the threads do
// not change the map.
TEST(PhysicalMap, OnsetIsTheSummarysSearchAndThreadsDoNotMatter) {
  PhysicalMapOptions o = fast(1e-3, 2e-3, 2);
  o.onset = true;
  o.min_rate = 10;
  o.max_rate = 1e5;
  o.rtol = 1e-3;
  const PhysicalMap m = physical_map(cell(), o);
  o.threads = 1;
  const PhysicalMap one = physical_map(cell(), o);
  ASSERT_EQ(m.columns.size(), 2u);
  for (std::size_t v = 0; v < 2; ++v) {
    const PhysicalMapColumn& c = m.columns[v];
    Scene s = with_physical_value(cell(), "viscosity", c.viscosity);
    ShearRateSearchOptions search;
    search.min_rate = 10;
    search.max_rate = 1e5;
    search.samples = 13;
    search.rtol = 1e-3;
    search.predictor = o.predictor;
    const auto t = shear_rate_thresholds(s, search);
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(c.onset[k].found, t[std::size_t(k)].found) << v << " " << k;
      EXPECT_EQ(c.onset[k].rate, t[std::size_t(k)].shear_rate);
      EXPECT_EQ(c.onset[k].l, t[std::size_t(k)].l);
      EXPECT_EQ(one.columns[v].onset[k].rate, c.onset[k].rate);
    }
    EXPECT_EQ(one.columns[v].tumbling_to_swinging.rate, c.tumbling_to_swinging.rate);
  }
}

TEST(PhysicalMap, AssumptionsSayHowFarOff) {
  PhysicalMapOptions o = fast(25e-3, 25e-3, 1);
  const PhysicalMap m = physical_map(cell(), o);
  ASSERT_EQ(m.assumptions.size(), 3u);
  EXPECT_EQ(m.assumptions[0].value, 1.0);  // Delta
  EXPECT_TRUE(m.assumptions[0].holds);
  const double rate = m.columns[0].tumbling_to_swinging.rate, R = 2.8e-6;
  EXPECT_NEAR(m.assumptions[1].value, 1000 * rate * R * R / 25e-3, 1e-12 * m.assumptions[1].value);
  EXPECT_NEAR(m.assumptions[2].value, 25e-3 * rate * R / 6e-6, 1e-12 * m.assumptions[2].value);
  // A real cell's excess area fails the first check, saying by how much.
  Scene real = cell();
  real.parameters.Delta = 4.3;
  o.onset = true;
  const PhysicalMap r = physical_map(real, o);
  EXPECT_FALSE(r.assumptions[0].holds);
  EXPECT_NE(r.assumptions[0].meaning.find("4.3"), std::string::npos);
  // There the l >= 3 modes grow at every rate searched: no crossing, the side says where the boundary lies, and
  // the summary's search agrees (its reason).
  for (const RateCrossing& c : r.columns[0].onset) {
    EXPECT_FALSE(c.found);
    EXPECT_EQ(c.side, "below") << c.reason;
    EXPECT_EQ(c.reason.rfind("unstable already at min_rate", 0), 0u) << c.reason;
  }
  EXPECT_EQ(r.min_rate, 0.1);
}

TEST(PhysicalMap, BadInputNamesTheParameter) {
  auto thrown_key = [](auto&& f) {
    try {
      f();
    } catch (const InvalidArgument& e) {
      return e.parameter();
    }
    return std::string("nothing thrown");
  };
  Scene plain = cell();
  plain.physical.reset();
  EXPECT_EQ(thrown_key([&] { physical_map(plain); }), "viscosity");
  Scene no_inner = cell();
  no_inner.physical->inner_viscosity = kNotGiven;
  EXPECT_EQ(thrown_key([&] { physical_map(no_inner); }), "viscosity");
  PhysicalMapOptions o = fast(25e-3, 25e-3, 1);
  o.spreads = {{"stiffness", 1, 2, ""}};
  EXPECT_EQ(thrown_key([&] { physical_map(cell(), o); }), "stiffness");
  o.spreads = {{"shear_modulus", 2e-6, 1e-6, ""}};
  EXPECT_EQ(thrown_key([&] { physical_map(cell(), o); }), "shear_modulus");
  o.spreads = {{"area", 1e-10, 2e-10, ""}};  // this cell has a radius, not an area
  EXPECT_EQ(thrown_key([&] { physical_map(cell(), o); }), "area");
  o = fast(25e-3, 1e-3, 2);
  EXPECT_EQ(thrown_key([&] { physical_map(cell(), o); }), "max_viscosity");
}

}  // namespace
}  // namespace rbcstab
