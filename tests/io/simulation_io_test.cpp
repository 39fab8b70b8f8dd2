// The simulation views read back against the run.
#include <gtest/gtest.h>

#include <sstream>

#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/io/simulation_io.hpp"

namespace rbcstab {
namespace {

TEST(SimulationIo, JsonTextAndCsvReadBackTheRun) {
  SceneFile sf = parse_scene("");
  sf.scene.L = 4;
  sf.scene.T = 10;
  sf.L_reason = "set by the test";
  const SimulationResult r = simulate(sf.scene, sf.options);
  const nlohmann::json j = simulation_json(sf, r);
  EXPECT_EQ(j["L"], 4);
  EXPECT_EQ(j["L_reason"], "set by the test");
  EXPECT_EQ(j["steps"], r.counters.steps);
  EXPECT_EQ(j["l_Delta"], r.l_Delta);
  EXPECT_EQ(j["rtol"].get<double>(), sf.options.integrator.rtol);
  EXPECT_EQ(j["stepper"], to_string(sf.options.integrator.stepper));
  EXPECT_EQ(j["parameters"]["lambda"].get<double>(), sf.scene.parameters.lambda);
  EXPECT_EQ(simulation_text(sf, r).substr(0, 6), "model ");
  const std::string csv = trajectory_csv(r);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "t,Delta_2,Delta_3,Delta_4,sigma,r,Psi,integrated");
  std::istringstream in(csv);
  std::string line;
  std::size_t rows = 0;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, r.trajectory.rows() + 1);
}

}  // namespace
}  // namespace rbcstab
