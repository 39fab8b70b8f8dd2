// The enum name tables: the generic facility on a local enum, then every table of the library
// round-trips and keeps its exact names (outputs, JSON and tests read them).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rbcstab/analysis/predictors.hpp"
#include "rbcstab/analysis/quantity.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/eigen_arpack.hpp"
#include "rbcstab/continuation/monodromy.hpp"
#include "rbcstab/continuation/orbit.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/system.hpp"
#include "rbcstab/report/panels.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/trace.hpp"
#include "rbcstab/verdict/asymptotic.hpp"

namespace rbcstab {

enum class Colour { red, dark_green, blue };
template <>
struct EnumTable<Colour> {
  static constexpr EnumName<Colour> entries[] = {
      {Colour::red, "red"}, {Colour::dark_green, "dark-green"}, {Colour::blue, "blue"}, {Colour::dark_green, "green"}};
};

// Compile-time checks of the table rules (a duplicate name, or a value left out, is refused).
enum class Two { a, b };
template <>
struct EnumTable<Two> {
  static constexpr EnumName<Two> entries[] = {{Two::a, "a"}, {Two::b, "a"}};
};
static_assert(!enum_table_is_valid<Two>(), "duplicate name");
enum class Gap { a, b, c };
template <>
struct EnumTable<Gap> {
  static constexpr EnumName<Gap> entries[] = {{Gap::a, "a"}, {Gap::c, "c"}};
};
static_assert(!enum_table_is_valid<Gap>(), "Gap::b has no name");
static_assert(enum_table_is_valid<Colour>());

namespace {

TEST(EnumTable, NamesValuesAndAliases) {
  EXPECT_EQ(to_string(Colour::dark_green), "dark-green");  // the first name is canonical
  EXPECT_EQ(from_string<Colour>("dark-green", "colour"), Colour::dark_green);
  EXPECT_EQ(from_string<Colour>("green", "colour"), Colour::dark_green);  // alias accepted on input
  EXPECT_EQ(enum_names<Colour>(), (std::vector<std::string>{"red", "dark-green", "blue"}));
  EXPECT_FALSE(try_from_string<Colour>("Red").has_value());  // names are case-sensitive
  EXPECT_EQ(to_string(static_cast<Colour>(7)), "?");
}

TEST(EnumTable, UnknownNameNamesKeyValueAndAllowedNames) {
  try {
    from_string<Colour>("purple", "paint.colour");
    FAIL() << "purple was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "paint.colour");
    EXPECT_STREQ(e.what(), "paint.colour = 'purple' is not one of: red, dark-green, blue");
  }
}

template <class E>
void expect_table(const std::vector<std::string>& names) {
  EXPECT_EQ(enum_names<E>(), names);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const E e = static_cast<E>(k);  // every enum here is contiguous from 0, in declaration order
    EXPECT_EQ(to_string(e), names[k]);
    EXPECT_EQ(from_string<E>(names[k], "key"), e);
  }
  EXPECT_THROW(from_string<E>("no such name", "key"), InvalidArgument);
}

TEST(EnumTable, EveryLibraryTableKeepsItsNames) {
  expect_table<ModelLevel>({"auto", "full", "modal", "reduced"});
  expect_table<Stepper>({"rk8pd", "rkck", "rkf45", "msadams", "rosenbrock", "msbdf", "bsimp", "rk4imp"});
  expect_table<IntegrationStatus>(
      {"success", "step_size_underflow", "non_finite_state", "step_limit", "time_limit", "solver_error"});
  expect_table<SpecialPointType>({"LP", "BP", "HB", "LPC", "PD", "NS", "UZ", "EP"});
  expect_table<LocationStatus>({"located", "guess"});
  expect_table<ContinuationStatus>({"completed", "step_too_small", "outside_domain", "start_failed", "branch_lost"});
  expect_table<Direction>({"forward", "backward", "both"});
  expect_table<ArpackWhich>({"largest_real", "largest_magnitude", "nearest_shift"});
  expect_table<ArpackStatus>({"converged", "max_iterations", "solve_failed", "failed"});
  expect_table<OrbitKind>({"swinging", "tumbling"});
  expect_table<SceneFloquetStatus>({"converged", "relaxation_failed", "not_periodic", "arpack_failed"});
  expect_table<PanelKind>({"none", "diagram", "fig6e", "continuation", "physical_map"});
  expect_table<TraceCriterion>({"asymptotic", "finite-horizon"});
  expect_table<SigmaSource>({"equilibrium", "periodic_orbit", "time_average"});
  expect_table<Classifier>({"auto", "final", "tail"});
  expect_table<Verdict>({"stable", "unstable", "failed"});
  expect_table<Regime>(
      {"rolling", "tank-treading", "swinging", "oscillating-out-of-plane", "tumbling", "undetermined"});
  expect_table<DomainStatus>({"ok", "limit", "outside_domain"});
}

TEST(EnumTable, NamedWrappersKeepTheirKeys) {
  auto key_of = [](auto f) {
    try {
      f();
    } catch (const InvalidArgument& e) {
      return e.parameter();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(key_of([] { model_level_from_string("foo"); }), "model");
  EXPECT_EQ(key_of([] { stepper_from_string("euler"); }), "stepper");
  EXPECT_EQ(key_of([] { classifier_from_string("median"); }), "classifier");
  EXPECT_EQ(key_of([] { trace_criterion_from_string("linear"); }), "criterion");
  EXPECT_EQ(trace_criterion_from_string("finite_horizon"), TraceCriterion::finite_horizon);  // alias
  EXPECT_EQ(stepper_names(), enum_names<Stepper>());
}

}  // namespace
}  // namespace rbcstab
