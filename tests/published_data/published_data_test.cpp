// The published observation files (data/observations/, docs/inverse_data.md) as a user's fit reads them: every file
// parses with the library reader, and the derived donor means are the original's averages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "rbcstab/inverse/observations.hpp"

namespace rbcstab {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> observation_files() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(RBCSTAB_OBSERVATIONS_DIR))
    if (e.path().extension() == ".csv") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(PublishedData, EveryFileParses) {
  const std::vector<fs::path> files = observation_files();
  // The four files of docs/inverse_data.md and the derived donor means: a file lost or renamed shows here.
  ASSERT_GE(files.size(), 4u);
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    ObservationData d;
    ASSERT_NO_THROW(d = read_observation_data(f.string()));
    EXPECT_FALSE(d.rows.empty());
    EXPECT_FALSE(d.comments.empty()) << "no provenance comment";
    for (const ObservedRow& r : d.rows) {
      EXPECT_TRUE(std::isfinite(r.viscosity) && r.viscosity > 0) << "line " << r.line;
      if (r.observable != Observable::regime) {
        EXPECT_GT(r.uncertainty, 0) << "line " << r.line;
      }
    }
  }
}

TEST(PublishedData, DonorMeansAreTheOriginalsAverages) {
  const ObservationData raw = read_observation_data(std::string(RBCSTAB_OBSERVATIONS_DIR) + "/fischer2015.csv");
  const ObservationData means = read_observation_data(std::string(RBCSTAB_OBSERVATIONS_DIR) + "/fischer2015_means.csv");
  ASSERT_FALSE(means.rows.empty());
  for (const ObservedRow& m : means.rows) {
    double sum = 0;
    int n = 0;
    for (const ObservedRow& r : raw.rows)
      if (r.observable == Observable::inclination_angle && r.shear_rate == m.shear_rate && r.viscosity == m.viscosity)
        sum += r.value, ++n;
    ASSERT_GE(n, 3) << "line " << m.line;
    // The derived file prints 4 decimals of degrees.
    EXPECT_NEAR(m.value, sum / n, 1e-4 * M_PI / 180) << "line " << m.line;
  }
}

}  // namespace
}  // namespace rbcstab
