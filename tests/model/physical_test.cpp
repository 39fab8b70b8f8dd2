// Physical units: unit suffixes, the paper's dimensionless numbers from a physical cell (Sec. II, Eq. dimless_nums)
// against hand-computed values, and the conversions both ways (rbcstab units).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/physical.hpp"

namespace rbcstab {
namespace {

std::string message_of(auto&& f) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    return e.parameter() + ": " + e.what();
  }
  return "";
}

// The worked example of docs/units.md: A = 134 um^2, V = 94 um^3, V0 = 100 um^3, kappa = 50 kBT at 310 K,
// mu = 6 uN/m, eta_ex = 1.2 mPa s, eta_in = 6 mPa s, gamma = 1000/s.
PhysicalCell typical_cell() {
  PhysicalCell c;
  c.temperature = 310;
  c.shear_rate = 1000;
  c.viscosity = 1.2e-3;
  c.inner_viscosity = 6e-3;
  c.area = 134e-12;
  c.volume = 94e-18;
  c.stress_free_volume = 100e-18;
  c.bending_modulus = 50 * kBoltzmann * 310;
  c.shear_modulus = 6e-6;
  return c;
}

TEST(Physical, UnitSuffixesConvertToSI) {
  EXPECT_DOUBLE_EQ(parse_quantity("1000", PhysicalUnit::per_second, "shear_rate"), 1000);
  EXPECT_DOUBLE_EQ(parse_quantity("1e3/s", PhysicalUnit::per_second, "shear_rate"), 1000);
  EXPECT_DOUBLE_EQ(parse_quantity("2e-19J", PhysicalUnit::joule, "bending_modulus"), 2e-19);
  EXPECT_DOUBLE_EQ(parse_quantity("0.2aJ", PhysicalUnit::joule, "bending_modulus"), 0.2e-18);
  // kBT at the stated temperature: 50 x 1.380649e-23 J/K x 310 K = 2.14000595e-19 J (hand-computed).
  EXPECT_NEAR(parse_quantity("50kBT", PhysicalUnit::joule, "bending_modulus", 310), 2.14000595e-19,
              1e-15 * 2.14000595e-19);
  EXPECT_NEAR(parse_quantity("6uN/m", PhysicalUnit::newton_per_metre, "shear_modulus"), 6e-6, 1e-15 * 6e-6);
  EXPECT_NEAR(parse_quantity("2.5 uPa m", PhysicalUnit::newton_per_metre, "shear_modulus"), 2.5e-6, 1e-15 * 2.5e-6);
  EXPECT_NEAR(parse_quantity("3.9um", PhysicalUnit::metre, "radius"), 3.9e-6, 1e-15 * 3.9e-6);
  EXPECT_NEAR(parse_quantity("3.9\xC2\xB5m", PhysicalUnit::metre, "radius"), 3.9e-6, 1e-15 * 3.9e-6);
  EXPECT_NEAR(parse_quantity("134um^2", PhysicalUnit::square_metre, "area"), 134e-12, 1e-15 * 134e-12);
  EXPECT_NEAR(parse_quantity("94 um3", PhysicalUnit::cubic_metre, "volume"), 94e-18, 1e-15 * 94e-18);
  EXPECT_NEAR(parse_quantity("94fL", PhysicalUnit::cubic_metre, "volume"), 94e-18, 1e-15 * 94e-18);
  EXPECT_NEAR(parse_quantity("1.2 mPa s", PhysicalUnit::pascal_second, "viscosity"), 1.2e-3, 1e-15 * 1.2e-3);
  EXPECT_NEAR(parse_quantity("1.2mPa.s", PhysicalUnit::pascal_second, "viscosity"), 1.2e-3, 1e-15 * 1.2e-3);
  EXPECT_NEAR(parse_quantity("1.2cP", PhysicalUnit::pascal_second, "viscosity"), 1.2e-3, 1e-15 * 1.2e-3);
}

TEST(Physical, MalformedOrOutOfRangeQuantitiesAreRefusedNamingTheKey) {
  EXPECT_EQ(message_of([] { parse_quantity("50kBT", PhysicalUnit::joule, "bending_modulus"); }),
            "bending_modulus: bending_modulus = '50kBT' is in kBT: state the temperature [K] too");
  const std::string m = message_of([] { parse_quantity("3.9 furlongs", PhysicalUnit::metre, "radius"); });
  EXPECT_EQ(m.rfind("radius: radius = '3.9 furlongs' must be a number in m, optionally followed by a unit (", 0), 0u)
      << m;
  EXPECT_NE(message_of([] { parse_quantity("", PhysicalUnit::metre, "radius"); }), "");
  EXPECT_NE(message_of([] { parse_quantity("um", PhysicalUnit::metre, "radius"); }), "");
  EXPECT_NE(message_of([] { parse_quantity("2e-19N/m", PhysicalUnit::joule, "bending_modulus"); }), "");
  EXPECT_NE(message_of([] { parse_quantity("6uJ", PhysicalUnit::newton_per_metre, "shear_modulus"); }), "");
  EXPECT_EQ(message_of([] { parse_quantity("-3um", PhysicalUnit::metre, "radius"); }),
            "radius: radius = '-3um' is out of range: must be finite and > 0 (m)");
  EXPECT_NE(message_of([] { parse_quantity("inf", PhysicalUnit::metre, "radius"); }), "");
  EXPECT_NE(message_of([] { parse_quantity("nan", PhysicalUnit::metre, "radius"); }), "");
}

// A bare number is read in SI, so it is accepted only within its key's plausible range: "--radius 2.8" (2.8 m) is
// refused naming the key, the value, the range and the unit that was likely meant; a number with a unit is not
// checked.
TEST(Physical, ImplausibleBareNumbersAreRefusedWithTheRangeAndASuggestion) {
  const std::string m = message_of([] { require_plausible_bare("radius", 2.8); });
  EXPECT_EQ(m.rfind("radius: radius = 2.8 (a bare number, read as 2.8 m) is not a plausible radius: a bare number "
                    "must be in [",
                    0),
            0u)
      << m;
  EXPECT_NE(m.find("] m; did you mean 2.8 um?"), std::string::npos) << m;
  EXPECT_NE(m.find("(m, cm, mm, um, nm)"), std::string::npos) << m;
  // The suggestion is the unit that lands nearest the red cell's typical value.
  EXPECT_NE(message_of([] { require_plausible_bare("shear_modulus", 6); }).find("did you mean 6 uN/m?"),
            std::string::npos);
  EXPECT_NE(message_of([] { require_plausible_bare("viscosity", 1.2); }).find("did you mean 1.2 mPa s?"),
            std::string::npos);
  EXPECT_NE(message_of([] { require_plausible_bare("bending_modulus", 50); }).find("did you mean 50 kBT"),
            std::string::npos);
  EXPECT_NE(message_of([] { require_plausible_bare("volume", 94); }).find("did you mean 94 um^3?"), std::string::npos);
  // No unit of the temperature's brings 37 into range: refused without a suggestion.
  const std::string t = message_of([] { require_plausible_bare("temperature", 37); });
  EXPECT_NE(t.find("temperature = 37"), std::string::npos) << t;
  EXPECT_EQ(t.find("did you mean"), std::string::npos) << t;
  // Plausible SI values pass: the docs' typical cell, field by field.
  const PhysicalCell c = typical_cell();
  for (auto [key, v] : {std::pair{"temperature", c.temperature},
                        {"shear_rate", c.shear_rate},
                        {"viscosity", c.viscosity},
                        {"inner_viscosity", c.inner_viscosity},
                        {"area", c.area},
                        {"volume", c.volume},
                        {"stress_free_volume", c.stress_free_volume},
                        {"bending_modulus", c.bending_modulus},
                        {"shear_modulus", c.shear_modulus}}) {
    EXPECT_TRUE(plausible_bare(key, v)) << key;
    EXPECT_EQ(message_of([&] { require_plausible_bare(key, v); }), "") << key;
  }
  EXPECT_EQ(message_of([] { require_plausible_bare("radius", 2.8e-6); }), "");
  // Not > 0: left to the positivity checks, which say "finite and > 0".
  EXPECT_EQ(message_of([] { require_plausible_bare("radius", -3); }), "");
  EXPECT_THROW(plausible_range("furlongs"), InvalidArgument);
  EXPECT_TRUE(has_unit("2.8um"));
  EXPECT_TRUE(has_unit("2.8 m"));
  EXPECT_FALSE(has_unit("2.8e-6"));
  EXPECT_FALSE(has_unit(" 2.8 "));
}

// Writers put an implausible value with its SI unit, so it reads back as itself and is not refused as bare.
TEST(Physical, ImplausibleValuesAreWrittenWithTheirUnit) {
  EXPECT_FALSE(needs_unit_text("radius", 2.8e-6));
  EXPECT_FALSE(needs_unit_text("radius", kNotGiven));
  EXPECT_TRUE(needs_unit_text("radius", 2.8));
  EXPECT_EQ(with_si_unit("radius", 2.8), "2.8 m");
  const double x = 0.1 + 0.2;  // needs 17 digits
  EXPECT_EQ(parse_quantity(with_si_unit("viscosity", x), PhysicalUnit::pascal_second, "viscosity"), x);
}

TEST(Physical, TypicalCellGivesTheHandComputedNumbers) {
  // Hand-computed (Sec. II): R = (3 x 94e-18/(4 pi))^(1/3) = 2.8206319097606938e-6 m; Delta = A/R^2 - 4 pi;
  // Delta0 likewise with V0 = 100 um^3; B = eta gamma R^3/kappa; C = eta gamma R/mu; alpha = mu R^2/kappa.
  const CellNumbers n = cell_numbers(typical_cell());
  EXPECT_NEAR(n.R, 2.8206319097606938e-06, 1e-20);
  EXPECT_NEAR(n.Delta, 4.27633930264518, 1e-13);
  EXPECT_NEAR(n.Delta0, 3.595707615540686, 1e-13);
  EXPECT_NEAR(n.B, 125.83617522721724, 1e-12);
  EXPECT_NEAR(n.C, 0.5641263819521387, 1e-15);
  EXPECT_NEAR(n.alpha, 223.06380139812953, 1e-12);
  EXPECT_NEAR(n.alpha, n.B / n.C, 1e-12);
  EXPECT_DOUBLE_EQ(n.lambda, 5);
  EXPECT_DOUBLE_EQ(n.time_unit, 1e-3);
  // The paper's own estimate (Sec. VI): R = 3 um, mu = 2.5 uN/m, kappa = 2e-19 J, eta = 1 cP, gamma = 1000/s:
  // B = 1e-3 x 1e3 x 27e-18/2e-19 = 135 (~1e2), C = 1e-3 x 1e3 x 3e-6/2.5e-6 = 1.2 (~1).
  EXPECT_NEAR(bending_number(1e-3, 1000, 3e-6, 2e-19), 135, 1e-12);
  EXPECT_NEAR(capillary_number(1e-3, 1000, 3e-6, 2.5e-6), 1.2, 1e-15);
  EXPECT_NEAR(excess_area(4 * kPi, 4 * kPi / 3), 0, 1e-14);  // a unit sphere has no excess area
}

TEST(Physical, ParametersFollowTheCellAndNameWhatTheyAreMadeOf) {
  const Parameters p = physical_parameters(typical_cell(), Parameters{});
  EXPECT_NEAR(p.B, 125.83617522721724, 1e-12);
  EXPECT_DOUBLE_EQ(p.lambda, 5);
  const auto d = derived_parameters(typical_cell());
  ASSERT_EQ(d.size(), 5u);
  EXPECT_EQ(d[0].parameter, "B");
  EXPECT_EQ(d[4].parameter, "Delta0");
  PhysicalCell r = typical_cell();
  r.area = r.volume = r.stress_free_volume = r.inner_viscosity = kNotGiven;
  r.radius = 3e-6;
  EXPECT_EQ(derived_parameters(r).size(), 2u);  // only B and C: lambda, Delta, Delta0 stay dimensionless
  const Parameters q = physical_parameters(r, Parameters{});
  EXPECT_DOUBLE_EQ(q.lambda, Parameters{}.lambda);
  EXPECT_DOUBLE_EQ(q.Delta, Parameters{}.Delta);
}

TEST(Physical, IncompleteOrContradictoryCellsAreRefused) {
  PhysicalCell c = typical_cell();
  c.radius = 3e-6;
  EXPECT_EQ(message_of([&] { c.validate(); }).rfind("radius: radius and area both given", 0), 0u);
  c = typical_cell();
  c.shear_modulus = kNotGiven;
  EXPECT_EQ(message_of([&] { c.validate_complete(); }).rfind("shear_modulus: shear_modulus is missing", 0), 0u);
  c = typical_cell();
  c.volume = kNotGiven;
  EXPECT_EQ(message_of([&] { c.validate(); }).rfind("area: area is given without volume", 0), 0u);
  c = typical_cell();
  c.stress_free_volume = 90e-18;  // V0 < V: Delta0 > Delta
  EXPECT_EQ(message_of([&] { c.validate(); }).rfind("stress_free_volume: stress_free_volume = 9e-17", 0), 0u);
}

TEST(Physical, ConvertsBothWays) {
  // Dimensionless to physical: B = 125.836... with eta, R, kappa gives back gamma = 1000/s; C with it mu.
  UnitsQuery q;
  q.cell = typical_cell();
  q.cell.shear_rate = q.cell.shear_modulus = q.cell.inner_viscosity = kNotGiven;
  q.B = 125.83617522721724;
  q.C = 0.5641263819521387;
  q.lambda = 5;
  const UnitsAnswer a = convert_units(q);
  EXPECT_NEAR(a.cell.shear_rate, 1000, 1e-10);
  EXPECT_NEAR(a.cell.shear_modulus, 6e-6, 1e-19);
  EXPECT_NEAR(a.cell.inner_viscosity, 6e-3, 1e-17);
  ASSERT_TRUE(a.parameters.has_value());
  EXPECT_NEAR(a.numbers.alpha, 223.06380139812953, 1e-10);
  // Delta to the area at fixed volume, Delta0 to the stress-free volume.
  UnitsQuery g;
  g.cell.volume = 94e-18;
  g.Delta = 4.27633930264518;
  g.Delta0 = 3.595707615540686;
  const UnitsAnswer b = convert_units(g);
  EXPECT_NEAR(b.cell.area, 134e-12, 1e-14 * 134e-12);
  EXPECT_NEAR(b.cell.stress_free_volume, 100e-18, 1e-14 * 100e-18);
  // A number and the physical value it would fix, both given: refused naming both.
  UnitsQuery both;
  both.cell = typical_cell();
  both.B = 100;
  EXPECT_EQ(message_of([&] { convert_units(both); }),
            "B: B and shear_rate both given: B fixes shear_rate here; give one");
  UnitsQuery missing;
  missing.B = 100;
  EXPECT_EQ(message_of([&] { convert_units(missing); }), "B: B = 100 needs viscosity to give shear_rate");
}

// A given number is held to its parameter-table domain, with the message a scene key gives (one range per
// parameter): Delta beyond 4 pi, Delta0 above the Delta it is given with, a negative lambda.
TEST(Physical, UnitsInputsTakeTheTablesRanges) {
  UnitsQuery big;
  big.Delta = 13;
  EXPECT_EQ(message_of([&] { convert_units(big); }), "Delta: Delta = 13 is out of range: must be in (0, 4 pi)");
  UnitsQuery above;
  above.Delta = 1;
  above.Delta0 = 2;
  EXPECT_EQ(message_of([&] { convert_units(above); }),
            "Delta0: Delta0 = 2 is out of range: must be in [0, Delta] with Delta = 1");
  UnitsQuery alone;  // no Delta known: only Delta0's lower end applies
  alone.Delta0 = 2;
  EXPECT_NO_THROW(convert_units(alone));
  alone.Delta0 = -1;
  EXPECT_EQ(message_of([&] { convert_units(alone); }), "Delta0: Delta0 = -1 is out of range: must be finite and >= 0");
  // Every row with a units input is one of number_formulas' keys.
  std::set<std::string> keys;
  for (const NumberFormula& f : number_formulas()) keys.insert(f.key);
  for (const ParameterRow& r : parameter_table()) {
    EXPECT_EQ(keys.count(r.name), r.physical.formula ? 1u : 0u) << r.name;
    if (r.physical.input) {
      EXPECT_TRUE(r.physical.formula && r.physical.completes) << r.name;
    }
  }
}

}  // namespace
}  // namespace rbcstab
