// Scene files: a full scene parses, round-trips through to_toml, and bad keys/types/values are
// refused with InvalidArgument naming the key (as table.key) and, for values, the allowed range.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {
namespace {

const char* kFullScene = R"(
name = "fig3_ip_test"

[parameters]
lambda = 1.0
Delta = 0.5
Delta0 = 0.02
B = 3        # an integer is accepted for a number
C = 0.1

[initial]
beta = 1.5707963267948966
delta = 1e-10
delta_l = { 3 = 2e-3, 7 = 1e-12 }
rest_delta_l = { 4 = 1e-4 }

[run]
L = 12
T = 250.5
dt = 0.25
model = "full"
tail_window = 5

[integrator]
stepper = "rosenbrock"
rtol = 1e-9
atol = 1e-13
h_init = 1e-4
h_min = 1e-14
max_steps = 123456
max_seconds = 30
)";

TEST(SceneFile, ParsesEveryKey) {
  const SceneFile f = parse_scene(kFullScene, "full.toml");
  const Scene& s = f.scene;
  EXPECT_EQ(s.name, "fig3_ip_test");
  EXPECT_EQ(s.parameters.lambda, 1.0);
  EXPECT_EQ(s.parameters.Delta, 0.5);
  EXPECT_EQ(s.parameters.Delta0, 0.02);
  EXPECT_EQ(s.parameters.B, 3.0);
  EXPECT_EQ(s.parameters.C, 0.1);
  EXPECT_EQ(s.beta, 1.5707963267948966);
  EXPECT_EQ(s.delta, 1e-10);
  EXPECT_EQ(s.delta_l, (std::map<int, double>{{3, 2e-3}, {7, 1e-12}}));
  EXPECT_EQ(s.rest_delta_l, (std::map<int, double>{{4, 1e-4}}));
  EXPECT_EQ(s.perturbation(3), 2e-3);
  EXPECT_EQ(s.perturbation(5), 1e-10);
  EXPECT_EQ(s.L, 12);
  EXPECT_EQ(s.T, 250.5);
  EXPECT_EQ(s.dt, 0.25);
  EXPECT_EQ(s.model, ModelLevel::full);
  EXPECT_EQ(f.options.tail_window, 5.0);
  const IntegratorOptions& o = f.options.integrator;
  EXPECT_EQ(o.stepper, Stepper::rosenbrock);
  EXPECT_EQ(o.rtol, 1e-9);
  EXPECT_EQ(o.atol, 1e-13);
  EXPECT_EQ(o.h_init, 1e-4);
  EXPECT_EQ(o.h_min, 1e-14);
  EXPECT_EQ(o.max_steps, 123456u);
  EXPECT_EQ(o.max_seconds, 30.0);
}

TEST(SceneFile, EmptyFileIsTheDefaultScene) {
  const SceneFile f = parse_scene("");
  const Scene d;
  EXPECT_EQ(f.scene.name, d.name);
  EXPECT_EQ(f.scene.parameters.B, d.parameters.B);
  EXPECT_EQ(f.scene.L, d.L);
  EXPECT_EQ(f.options.integrator.rtol, IntegratorOptions{}.rtol);
}

void expect_same(const SceneFile& a, const SceneFile& b) {
  EXPECT_EQ(a.scene.name, b.scene.name);
  EXPECT_EQ(a.scene.parameters.lambda, b.scene.parameters.lambda);
  EXPECT_EQ(a.scene.parameters.Delta, b.scene.parameters.Delta);
  EXPECT_EQ(a.scene.parameters.Delta0, b.scene.parameters.Delta0);
  EXPECT_EQ(a.scene.parameters.B, b.scene.parameters.B);
  EXPECT_EQ(a.scene.parameters.C, b.scene.parameters.C);
  EXPECT_EQ(a.scene.beta, b.scene.beta);
  EXPECT_EQ(a.scene.delta, b.scene.delta);
  EXPECT_EQ(a.scene.delta_l, b.scene.delta_l);
  EXPECT_EQ(a.scene.rest_delta_l, b.scene.rest_delta_l);
  EXPECT_EQ(a.scene.L, b.scene.L);
  EXPECT_EQ(a.scene.T, b.scene.T);
  EXPECT_EQ(a.scene.dt, b.scene.dt);
  EXPECT_EQ(a.scene.model, b.scene.model);
  EXPECT_EQ(a.options.tail_window, b.options.tail_window);
  EXPECT_EQ(a.options.integrator.stepper, b.options.integrator.stepper);
  EXPECT_EQ(a.options.integrator.rtol, b.options.integrator.rtol);
  EXPECT_EQ(a.options.integrator.atol, b.options.integrator.atol);
  EXPECT_EQ(a.options.integrator.h_init, b.options.integrator.h_init);
  EXPECT_EQ(a.options.integrator.h_min, b.options.integrator.h_min);
  EXPECT_EQ(a.options.integrator.max_steps, b.options.integrator.max_steps);
  EXPECT_EQ(a.options.integrator.max_seconds, b.options.integrator.max_seconds);
}

TEST(SceneFile, RoundTripsThroughToToml) {
  const SceneFile f = parse_scene(kFullScene);
  expect_same(parse_scene(to_toml(f)), f);
  // Values that need all 17 digits, and the vesicle limit C = inf.
  SceneFile g;
  g.scene.parameters.C = INFINITY;
  g.scene.parameters.lambda = 1.0 / 3;
  g.scene.beta = 0.1 + 0.2;
  g.scene.T = 123.456789012345678;
  g.options.integrator.rtol = 3.3e-11;
  const std::string text = to_toml(g);
  const SceneFile back = parse_scene(text);
  expect_same(back, g);
  EXPECT_TRUE(std::isinf(back.scene.parameters.C)) << text;
}

TEST(SceneFile, LoadsFromDiskAndNamesMissingFile) {
  const std::string path = (std::filesystem::temp_directory_path() / "rbcstab_scene_file_test.toml").string();
  write_file_atomic(path, kFullScene);
  EXPECT_EQ(load_scene(path).scene.name, "fig3_ip_test");
  std::remove(path.c_str());
  try {
    load_scene(path);
    FAIL() << "missing file accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

// Expects InvalidArgument whose parameter() is key and whose message contains key and each fragment.
void expect_refused(const std::string& toml, const std::string& key, std::initializer_list<std::string> fragments) {
  try {
    parse_scene(toml, "bad.toml");
    ADD_FAILURE() << "accepted: " << toml;
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.parameter(), key) << what;
    EXPECT_NE(what.find(key), std::string::npos) << "message does not name " << key << ": " << what;
    for (const auto& f : fragments) EXPECT_NE(what.find(f), std::string::npos) << "missing '" << f << "' in: " << what;
  }
}

TEST(SceneFile, UnknownKeysAreRefusedByName) {
  expect_refused("colour = 3", "colour", {"unknown"});
  expect_refused("[parameters]\nkappa = 3", "parameters.kappa", {"unknown", "lambda"});
  expect_refused("[run]\nLmax = 3", "run.Lmax", {"unknown"});
  expect_refused("[integrator]\nmethod = 'rk4'", "integrator.method", {"unknown", "stepper"});
  expect_refused("[flow]\nrate = 1", "flow", {"unknown"});
}

TEST(SceneFile, WrongTypesAreRefusedByName) {
  expect_refused("[parameters]\nB = 'two'", "parameters.B", {"number"});
  expect_refused("[run]\nL = 10.5", "run.L", {"integer"});
  expect_refused("[run]\nmodel = 3", "run.model", {"string"});
  expect_refused("parameters = 3", "parameters", {"table"});
  expect_refused("[initial]\ndelta_l = 3", "initial.delta_l", {"table"});
  expect_refused("[initial]\ndelta_l = { x = 1e-3 }", "initial.delta_l", {"integer"});
  expect_refused("[initial]\ndelta_l = { 3 = 'a' }", "initial.delta_l.3", {"number"});
}

// A name is one line of printable text, and any such name reads back (found by fuzzing: a name starting with a
// newline lost it through to_toml).
TEST(SceneFile, NamesArePrintableAndRoundTripThroughToToml) {
  for (const std::string name : {"it's \\ '''", "a \" b", "\u00e9 \u03bb", "", "''"}) {
    SceneFile f;
    f.scene.name = name;
    const std::string text = to_toml(f);
    EXPECT_EQ(parse_scene(text).scene.name, name) << text;
  }
  expect_refused("name = \"\\name\"", "name", {"U+000A at position 0", "one line of printable text"});
  expect_refused("name = \"a\\tb\"", "name", {"U+0009 at position 1"});
  expect_refused("name = \"a\\u007f\"", "name", {"U+007F"});
}

// Keys that name one mode ("3", "03", " 3", "+3") were merged, the last silently winning (found by fuzzing).
TEST(SceneFile, ModeGivenTwiceIsRefused) {
  expect_refused("[initial]\ndelta_l = { 3 = 1e-3, \"03\" = 2e-3 }", "initial.delta_l", {"'03' and '3'", "mode l = 3"});
  expect_refused("[initial]\nrest_delta_l = { \"+4\" = 1e-4, 4 = 2e-4 }", "initial.rest_delta_l",
                 {"give each mode once"});
  EXPECT_EQ(parse_scene("[initial]\ndelta_l = { 3 = 1e-3, 4 = 2e-3 }").scene.delta_l.size(), 2u);
}

TEST(SceneFile, OutOfRangeValuesNameKeyValueAndRange) {
  expect_refused("[parameters]\nB = -1", "parameters.B", {"-1", "> 0"});
  expect_refused("[parameters]\nC = nan", "parameters.C", {"nan", "> 0"});
  expect_refused("[parameters]\nDelta = 20", "parameters.Delta", {"20", "(0, 4 pi)"});
  expect_refused("[parameters]\nDelta0 = 2", "parameters.Delta0", {"2", "[0, Delta]"});
  expect_refused("[parameters]\nlambda = -1", "parameters.lambda", {"-1", ">= 0"});
  expect_refused("[run]\nL = 1", "run.L", {"1", "[2, 100]"});
  expect_refused("[run]\nL = 101", "run.L", {"101", "[2, 100]"});
  expect_refused("[run]\nT = -5", "run.T", {"-5", "(0, 1e7]"});
  expect_refused("[run]\ndt = 0", "run.dt", {"0", "(0, T]"});
  expect_refused("[run]\nmodel = 'foo'", "run.model", {"foo", "auto, full, modal, reduced"});
  expect_refused("[run]\ntail_window = -1", "run.tail_window", {"-1", "> 0"});
  expect_refused("[initial]\nbeta = inf", "initial.beta", {"inf", "finite"});
  expect_refused("[initial]\ndelta = -1e-3", "initial.delta", {"-0.001", "[0, Delta]"});
  expect_refused("[initial]\ndelta_l = { 2 = 1e-3 }", "initial.delta_l", {"[3, L]"});
  expect_refused("[initial]\ndelta_l = { 3 = -1 }", "initial.delta_l.3", {"-1", "[0, Delta]"});
  expect_refused("[integrator]\nrtol = 0", "integrator.rtol", {"0", "[1e-15, 0.1]"});
  expect_refused("[integrator]\natol = -1", "integrator.atol", {"-1", "[0, 1]"});
  expect_refused("[integrator]\nmax_steps = 0", "integrator.max_steps", {"0", "> 0"});
  expect_refused("[integrator]\nmax_seconds = -2", "integrator.max_seconds", {"-2", ">= 0"});
  expect_refused("[integrator]\nstepper = 'euler'", "integrator.stepper", {"euler", "rk8pd"});
}

// The [physical] table (the path the CLI flags and Python keywords share): a bare number, TOML number or text
// without a unit, only within the key's plausible SI range; with a unit as given, and written back with it.
TEST(SceneFile, ImplausibleBarePhysicalNumbersAreRefused) {
  const std::string cell = "shear_rate = 1000\nviscosity = 1e-3\nbending_modulus = 2e-19\nshear_modulus = 6e-6\n";
  for (const std::string radius : {"2.8", "'2.8'"}) {
    try {
      (void)parse_scene("[physical]\n" + cell + "radius = " + radius + "\n");
      ADD_FAILURE() << radius << " accepted as 2.8 m";
    } catch (const InvalidArgument& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("radius = 2.8 (a bare number, read as 2.8 m)"), std::string::npos) << m;
      EXPECT_NE(m.find("did you mean 2.8 um?"), std::string::npos) << m;
    }
  }
  EXPECT_EQ(parse_scene("[physical]\n" + cell + "radius = 2.8e-6\n").scene.physical->radius, 2.8e-6);
  EXPECT_EQ(parse_scene("[physical]\n" + cell + "radius = '2.8um'\n").scene.physical->radius, 2.8e-6);
  // Stated in metres it is taken as given, and to_toml writes it with its unit so it reads back.
  const SceneFile big = parse_scene("[physical]\n" + cell + "radius = '2.8 m'\n");
  EXPECT_EQ(big.scene.physical->radius, 2.8);
  const std::string text = to_toml(big);
  EXPECT_NE(text.find("2.8 m"), std::string::npos) << text;
  EXPECT_EQ(parse_scene(text).scene.physical->radius, 2.8);
}

TEST(SceneFile, SyntaxErrorNamesSourceAndLine) {
  try {
    parse_scene("[parameters]\nB = = 2\n", "broken.toml");
    FAIL();
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("broken.toml:2"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace rbcstab
