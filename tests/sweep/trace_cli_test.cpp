// `rbcstab trace` end to end: criterion flag, outputs, and bad input (exit 2 naming the parameter).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;

int run(const std::string& args, const std::string& err) {
  const int s = std::system((std::string(RBCSTAB_CLI) + " trace " + args + " 2> " + err).c_str());
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}
using rbcstab::test::slurp;

// Fig. 4(a) plane (lambda = 1): one chain of pieces l = 3, 4, ... with a corner between consecutive ones,
// every point's residual mu below 1e-10 (the library tests check the criterion independently).
TEST(TraceCli, WritesCurvesAndCornersAndRejectsBadCriterion) {
  const fs::path dir = fs::temp_directory_path() / ("rbcstab_trace_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string out = (dir / "t").string(), err = (dir / "err").string();
  ASSERT_EQ(run("--lambda 1 --Delta 1 --L 10 --criterion asymptotic --out " + out, err), 0) << slurp(err);
  const nlohmann::json doc = nlohmann::json::parse(slurp(out + ".json"));
  EXPECT_EQ(doc.at("criterion"), "asymptotic");
  const auto& curves = doc.at("curves");
  ASSERT_GE(curves.size(), 4u);
  EXPECT_EQ(doc.at("corners").size(), curves.size() - 1);
  for (std::size_t c = 0; c < curves.size(); ++c) {
    EXPECT_EQ(curves[c].at("chain"), 0);
    if (c > 0) {
      EXPECT_EQ(curves[c].at("l").get<int>(), curves[c - 1].at("l").get<int>() + 1);
    }
    for (const auto& mu : curves[c].at("mu")) EXPECT_LE(std::abs(mu.get<double>()), 1e-10);
  }
  EXPECT_NE(slurp(out + ".csv").find("curve,l,lnB,lnC,sigma_R,sigma_c,mu"), std::string::npos);

  EXPECT_EQ(run("--criterion sometimes --out " + out, err), 2);
  EXPECT_NE(slurp(err).find("criterion"), std::string::npos);
  EXPECT_EQ(run("--max-step 0 --out " + out, err), 2);
  EXPECT_NE(slurp(err).find("max_step"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
