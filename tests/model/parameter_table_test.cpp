// The parameter table (model/parameter_table.hpp): rows in enum order, domains and their messages, get/set
// on a scene (composites move one input, log rows are ln of their base), the names per use, independence,
// and the one truncation rule require_L.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/physical.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {
namespace {

using P = SceneParameter;

TEST(ParameterTable, RowsFollowTheEnumAndNamesAreUnique) {
  std::set<std::string> names;
  std::size_t k = 0;
  for (const ParameterRow& r : parameter_table()) {
    EXPECT_EQ(static_cast<std::size_t>(r.id), k++) << r.name;
    EXPECT_TRUE(names.insert(r.name).second) << r.name;
    EXPECT_EQ(&parameter_row(r.id), &r);
    EXPECT_EQ(to_string(r.id), r.name);
    for (ParameterUse use : {ParameterUse::scene_key, ParameterUse::continuation, ParameterUse::axis}) {
      if (usable_as(r.id, use)) {
        EXPECT_EQ(parameter_from_string(r.name, use), r.id) << r.name;
      }
    }
    // A stored row moves itself; a derived one has no table.
    if (r.table) {
      EXPECT_EQ(r.moves, r.id) << r.name;
    }
    EXPECT_TRUE(r.scale == AxisScale::log ? r.get == nullptr && r.of != r.id : r.get != nullptr) << r.name;
  }
}

// The messages every flag, key and continuation shows: "<name> = <value> is out of range: must be <text>".
TEST(ParameterTable, DomainsReadLikeTheirMessages) {
  const Parameters p;
  EXPECT_EQ(parameter_domain(P::lambda, p).text(), "finite and >= 0");
  EXPECT_EQ(parameter_domain(P::Delta, p).text(), "in (0, 4 pi)");
  EXPECT_EQ(parameter_domain(P::Delta0, p).text(), "in [0, Delta] with Delta = 1");
  EXPECT_EQ(parameter_domain(P::Delta0, p).text(false), "in [0, Delta]");
  EXPECT_EQ(parameter_domain(P::B, p).text(), "finite and > 0");
  EXPECT_EQ(parameter_domain(P::C, p).text(), "> 0 (inf allowed: the vesicle limit)");
  EXPECT_EQ(parameter_domain(P::beta, p).text(), "in [0, pi] (0: rest shape out of plane, pi/2: in plane)");
  EXPECT_EQ(continuation_domain(P::beta, p).text(), "in [0, pi] (0: rest shape out of plane, pi/2: in plane)");
  EXPECT_EQ(continuation_domain(P::lambda, p).text(), parameter_domain(P::lambda, p).text());
  // ln of (0, inf) is every finite number; ln of (0, inf] adds +inf (C = inf).
  EXPECT_EQ(parameter_domain(P::lnB, p).text(), "finite");
  EXPECT_TRUE(parameter_domain(P::lnC, p).contains(INFINITY));
  EXPECT_FALSE(parameter_domain(P::lnB, p).contains(INFINITY));
  EXPECT_TRUE(parameter_domain(P::C, p).contains(INFINITY));
  EXPECT_FALSE(parameter_domain(P::C, p).contains(0));
  EXPECT_FALSE(parameter_domain(P::Delta, p).contains(4 * std::numbers::pi));
  EXPECT_TRUE(parameter_domain(P::Delta0, p).contains(1.0));
  for (const ParameterRow& r : parameter_table()) {
    EXPECT_FALSE(parameter_domain(r.id, p).contains(NAN)) << r.name;
  }
  try {
    require_in(P::B, parameter_domain(P::B, p), -1);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "B");
    EXPECT_STREQ(e.what(), "B = -1 is out of range: must be finite and > 0");
  }
}

// set then get returns the value, and only the stored parameter the row moves changes (composites move one
// input, so each moves alone).
TEST(ParameterTable, SetThenGetMovesOnlyTheRowsInput) {
  for (const ParameterRow& r : parameter_table()) {
    if (r.id == P::shear_rate) continue;  // valid only on a physical scene: ShearRateMovesBAndCOnAPhysicalScene
    Scene s;
    s.parameters.Delta0 = 0.02;
    const Domain d = continuation_domain(r.id, s.parameters);
    const double v = std::isfinite(d.hi) ? d.lo + 0.37 * (d.hi - d.lo) : std::max(d.lo, 0.0) + 1.7;
    ASSERT_TRUE(d.contains(v)) << r.name << " " << v;
    Scene t = s;
    set_parameter(t, r.id, v);
    EXPECT_NEAR(get_parameter(t, r.id), v, 1e-14 * std::abs(v)) << r.name;
    const SceneParameter moved = parameter_row(r.id).moves;
    for (const ParameterRow& stored : parameter_table()) {
      if (!stored.table || stored.id == moved) continue;
      EXPECT_EQ(get_parameter(t, stored.id), get_parameter(s, stored.id)) << r.name << " moved " << stored.name;
    }
  }
}

// The uses select the rows marked for them; the historical lists are the oracle.
TEST(ParameterTable, NamesPerUseAreTheMarkedRows) {
  EXPECT_EQ(parameter_names(ParameterUse::continuation),
            (std::vector<std::string>{"lambda", "Delta", "Delta0", "B", "C", "Lambda", "S", "beta", "shear_rate"}));
  const std::vector<std::string> axes = parameter_names(ParameterUse::axis);
  EXPECT_EQ(std::set<std::string>(axes.begin(), axes.end()),
            (std::set<std::string>{"lnB", "lnC", "lambda", "Delta", "Delta0", "alpha", "beta", "shear_rate"}));
  EXPECT_EQ(parameter_names(ParameterUse::scene_key),
            (std::vector<std::string>{"lambda", "Delta", "Delta0", "B", "C", "beta", "delta"}));
  try {
    (void)parameter_from_string("kappa", ParameterUse::continuation);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "parameter");
    EXPECT_NE(std::string(e.what()).find("lambda, Delta, Delta0, B, C, Lambda, S, beta"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW((void)parameter_from_string("lnB", ParameterUse::continuation), InvalidArgument);
  EXPECT_THROW((void)parameter_from_string("C", ParameterUse::axis), InvalidArgument);
  EXPECT_EQ(parameter_label(P::lnC), "ln C");
  EXPECT_EQ(parameter_label(P::Delta0), "Delta0");
}

TEST(ParameterTable, IndependenceIsSharingNoInput) {
  EXPECT_TRUE(independent(P::Lambda, P::S));
  EXPECT_TRUE(independent(P::B, P::C));
  EXPECT_TRUE(independent(P::beta, P::Lambda));
  EXPECT_FALSE(independent(P::Lambda, P::Delta));
  EXPECT_FALSE(independent(P::lambda, P::Lambda));
  EXPECT_FALSE(independent(P::S, P::Delta0));
  EXPECT_FALSE(independent(P::C, P::S));
  EXPECT_FALSE(independent(P::alpha, P::B));
  EXPECT_FALSE(independent(P::lnB, P::B));
  EXPECT_FALSE(independent(P::beta, P::beta));
  EXPECT_TRUE(is_material(P::S));
  EXPECT_FALSE(is_material(P::beta));
  EXPECT_FALSE(is_material(P::delta));
}

// shear_rate (gamma) lives in the physical cell: set moves B and C by gamma'/gamma (alpha kept), and the result
// equals the cell converted afresh at gamma'. Oracle: physical_parameters (B = eta gamma R^3/kappa, C = eta gamma
// R/mu); 1e-14: one multiplication and one division apart.
TEST(ParameterTable, ShearRateMovesBAndCOnAPhysicalScene) {
  PhysicalCell c{
      .shear_rate = 1000, .viscosity = 1.2e-3, .radius = 3.9e-6, .bending_modulus = 2.1e-19, .shear_modulus = 6e-6};
  Scene s;
  s.physical = c;
  s.parameters = physical_parameters(c, s.parameters);
  EXPECT_EQ(get_parameter(s, P::shear_rate), 1000);
  Scene t = s;
  set_parameter(t, P::shear_rate, 250);
  EXPECT_EQ(get_parameter(t, P::shear_rate), 250);
  c.shear_rate = 250;
  const Parameters fresh = physical_parameters(c, s.parameters);
  EXPECT_NEAR(t.parameters.B, fresh.B, 1e-14 * fresh.B);
  EXPECT_NEAR(t.parameters.C, fresh.C, 1e-14 * fresh.C);
  EXPECT_NEAR(t.parameters.alpha(), s.parameters.alpha(), 1e-14 * s.parameters.alpha());
  for (P q : {P::lambda, P::Delta, P::Delta0, P::beta, P::delta}) {
    EXPECT_EQ(get_parameter(t, q), get_parameter(s, q)) << to_string(q);
  }
  EXPECT_EQ(parameter_domain(P::shear_rate, s.parameters).text(), "finite and > 0 (1/s)");
  EXPECT_EQ(parameter_row(P::shear_rate).scale, AxisScale::geometric);
  EXPECT_FALSE(is_material(P::shear_rate));  // not a function of Parameters: the material overloads refuse it
  // Moves B and C, keeps alpha: dependent on B, C, their logs and S (~ C); independent of alpha and the rest.
  for (P q : {P::B, P::C, P::lnB, P::lnC, P::S, P::shear_rate})
    EXPECT_FALSE(independent(P::shear_rate, q)) << to_string(q);
  for (P q : {P::alpha, P::lambda, P::Delta, P::Delta0, P::Lambda, P::beta}) {
    EXPECT_TRUE(independent(P::shear_rate, q)) << to_string(q);
    EXPECT_TRUE(independent(q, P::shear_rate)) << to_string(q);
  }
  // Without a complete physical cell: InvalidArgument naming shear_rate and what makes a physical scene.
  for (bool partial : {false, true}) {
    Scene plain;
    if (partial) plain.physical = PhysicalCell{};
    for (auto use : {0, 1, 2}) {
      try {
        if (use == 0) (void)get_parameter(plain, P::shear_rate);
        if (use == 1) set_parameter(plain, P::shear_rate, 10);
        if (use == 2) require_usable(P::shear_rate, plain);
        ADD_FAILURE() << "no throw, use " << use;
      } catch (const InvalidArgument& e) {
        EXPECT_EQ(e.parameter(), "shear_rate");
        EXPECT_NE(std::string(e.what()).find("needs a physical scene"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--shear-rate"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("[physical]"), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_NO_THROW(require_usable(P::lnB, Scene{}));
}

// Each row's `levels` bit against the systems themselves: a level moves when the right-hand side at a fixed
// state or the initial state changes with the value. Oracle: make_system at two values; exact comparison, since
// a level that does not read the parameter computes the same floating-point numbers.
TEST(ParameterTable, LevelsAreThoseWhoseSystemsMove) {
  Scene base;
  base.parameters = Parameters{.lambda = 2, .Delta = 1, .Delta0 = 0.5, .B = 3, .C = 0.5};
  base.beta = 0.4;
  base.delta = 1e-3;
  base.L = 4;
  base.physical = unit_cell(base.parameters);
  auto fingerprint = [](const Scene& s, ModelLevel level) {
    const std::unique_ptr<System> sys = make_system(s.parameters, initial_state(s), level);
    std::vector<double> y = sys->initial_state(), out = y;
    std::vector<double> at(y.size());
    for (std::size_t k = 0; k < y.size(); ++k) at[k] = y[k] + 1e-3 * double(k % 5 + 1);
    std::vector<double> dy(y.size());
    sys->rhs(0.37, at, dy);
    out.insert(out.end(), dy.begin(), dy.end());
    return out;
  };
  for (const ParameterRow& r : parameter_table()) {
    const double v = get_parameter(base, r.id);
    const double moved = r.scale == AxisScale::log ? v + 0.1 : v == 0 ? 0.1 : 1.1 * v;
    Scene t = base;
    set_parameter(t, r.id, moved);
    for (ModelLevel level : {ModelLevel::reduced, ModelLevel::modal, ModelLevel::full}) {
      const bool moves = fingerprint(base, level) != fingerprint(t, level);
      EXPECT_EQ(moves, (r.levels & level_bit(level)) != 0) << r.name << " at the " << to_string(level) << " level";
    }
  }
}

// What a branch in some parameters leaves fixed: every stored parameter but the ones they are set through.
TEST(ParameterTable, MovedStoredParametersFollowTheRows) {
  const P lambda_[] = {P::Lambda}, S_[] = {P::S}, gamma_[] = {P::shear_rate}, lnB_[] = {P::lnB};
  EXPECT_TRUE(moves_stored(lambda_, P::Delta));
  EXPECT_FALSE(moves_stored(lambda_, P::lambda));
  EXPECT_TRUE(moves_stored(S_, P::C));
  EXPECT_FALSE(moves_stored(S_, P::Delta0));
  EXPECT_TRUE(moves_stored(gamma_, P::B));
  EXPECT_TRUE(moves_stored(gamma_, P::C));
  EXPECT_FALSE(moves_stored(gamma_, P::lambda));
  EXPECT_TRUE(moves_stored(lnB_, P::B));
  EXPECT_EQ(moved_parameter(P::lnC), P::C);
  EXPECT_EQ(moved_parameter(P::alpha), P::B);
  // Every stored row is moved by itself and by nothing that does not list it as an input.
  for (const ParameterRow& r : parameter_table()) {
    if (!r.table) continue;
    for (const ParameterRow& q : parameter_table()) {
      const P free[] = {q.id};
      const bool listed = (parameter_row(q.scale == AxisScale::log ? q.of : q.id).inputs >> unsigned(r.id)) & 1u;
      if (!listed) {
        EXPECT_FALSE(moves_stored(free, r.id)) << q.name << " " << r.name;
      }
    }
    const P self[] = {r.id};
    EXPECT_TRUE(moves_stored(self, r.id)) << r.name;
  }
}

TEST(ParameterTable, OneTruncationRuleWithTheCallersReason) {
  EXPECT_NO_THROW(require_L(kMinL));
  EXPECT_NO_THROW(require_L(kMaxL));
  try {
    require_L(17, kMinL, 16, "dense");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "L");
    EXPECT_STREQ(e.what(), "L = 17 is out of range: must be an integer in [2, 16] (dense)");
  }
  try {
    require_L(1LL << 40);  // a TOML integer beyond int: refused before narrowing
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("[2, 100]"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rbcstab
