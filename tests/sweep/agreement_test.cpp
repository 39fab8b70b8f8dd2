// The diagram agreement's asymptotic predictor in plane: one periodic orbit per flow mapped across B
// (verdict/asymptotic.hpp orbit_sigma_average_at_B) gives every point the verdict and mode of a direct
// evaluation there, for any thread count and any subset (shard) of the points.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "rbcstab/core/error.hpp"
#include "rbcstab/sweep/agreement.hpp"
#include "rbcstab/verdict/asymptotic.hpp"
#include "test_files.hpp"

namespace rbcstab {
namespace {

// App. E(a): in plane, lambda = 1, Delta = 1 (Delta0 = 0.01, L = 10) on ln B in [-1, 6], ln C in [-5.5, 2].
Scene appE_a() {
  Scene s;
  s.parameters.lambda = 1;
  s.parameters.Delta = 1;
  s.beta = 1.5707963267948966;
  return s;
}
DiagramSpec grid16() {
  DiagramSpec d;
  d.classifier = Classifier::tail_mean;
  d.x.count = d.y.count = 16;
  return d;
}
// Every point simulated stable: the asymptotic disagreements are then exactly the points predicted unstable.
std::vector<PointResult> stable_points(const DiagramSpec& spec) {
  std::vector<PointResult> points(spec.size());
  for (std::size_t i = 0; i < points.size(); ++i) points[i].index = i;
  return points;
}
// Predicted mode per point (2: stable, -1: not classified) from an agreement over `points`.
std::vector<int> predicted(const Agreement& a, const DiagramSpec& spec) {
  std::vector<int> out(spec.size(), 2);
  for (const Disagreement& d : a.verdict_disagreements) out[d.index] = d.l_predicted;
  return out;
}
AgreementOptions untraced(int threads) {
  AgreementOptions ao;
  ao.threads = threads;
  ao.trace = false;
  return ao;
}

// Oracle: asymptotic_verdict at each point's own scene (its own orbit solve, no cache). 256 points, 16 flows.
TEST(AgreementInPlane, CachedOrbitsGiveTheDirectVerdicts) {
  const Scene base = appE_a();
  const DiagramSpec spec = grid16();
  const std::vector<PointResult> points = stable_points(spec);
  const std::vector<Agreement> all = predictor_agreements(base, spec, points, untraced(2));
  ASSERT_EQ(all[0].predictor, "asymptotic");
  std::vector<int> direct(spec.size(), 2);
  std::size_t unstable = 0, not_classified = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    try {
      const AsymptoticVerdict v = asymptotic_verdict(point_scene(base, spec, i));
      if (v.unstable) direct[i] = v.l, ++unstable;
    } catch (const InvalidArgument&) {
      ++not_classified;
    }
  }
  EXPECT_EQ(predicted(all[0], spec), direct);
  EXPECT_EQ(all[0].not_classified, not_classified);
  EXPECT_EQ(all[0].points + all[0].not_classified, points.size());
  EXPECT_GT(unstable, 0u);
  EXPECT_LT(unstable, points.size());
  // The single-predictor entry point uses the same cache.
  const Agreement one = asymptotic_agreement(base, spec, points, TraceResult{});
  EXPECT_EQ(predicted(one, spec), direct);
}

// 1 and 2 threads give the same agreement; a shard (every other point) gives each of its points the full
// grid's verdict (the flows' orbits are solved at the base scene's B, whichever points hold them).
TEST(AgreementInPlane, IndependentOfThreadsAndShards) {
  const Scene base = appE_a();
  const DiagramSpec spec = grid16();
  const std::vector<PointResult> points = stable_points(spec);
  const std::vector<Agreement> one = predictor_agreements(base, spec, points, untraced(1)),
                               two = predictor_agreements(base, spec, points, untraced(2));
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    EXPECT_EQ(one[k].predictor, two[k].predictor);
    EXPECT_EQ(one[k].points, two[k].points);
    EXPECT_EQ(one[k].not_classified, two[k].not_classified);
    EXPECT_EQ(one[k].verdict_matches, two[k].verdict_matches);
    EXPECT_EQ(one[k].mode_matches, two[k].mode_matches);
    EXPECT_EQ(predicted(one[k], spec), predicted(two[k], spec)) << one[k].predictor;
  }
  std::vector<PointResult> shard;
  for (std::size_t i = 1; i < points.size(); i += 2) shard.push_back(points[i]);
  const std::vector<Agreement> part = predictor_agreements(base, spec, shard, untraced(2));
  for (std::size_t k = 0; k < 2; ++k) {  // asymptotic, finite_horizon: the flow-cached predictors
    const std::vector<int> full = predicted(one[k], spec), half = predicted(part[k], spec);
    for (std::size_t i = 1; i < points.size(); i += 2) EXPECT_EQ(half[i], full[i]) << part[k].predictor << " " << i;
  }
}

#ifdef RBCSTAB_CLI
using rbcstab::test::slurp;

// `rbcstab diagram` with --threads 1 and 2 writes byte-identical outputs (--no-seconds), agreement and traced
// boundary included. A 6 x 6 App. E(a) window keeps it to ~2 s of CPU per run (mostly the trace).
TEST(AgreementInPlane, CliOutputsIdenticalForOneAndTwoThreads) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rbcstab_agreement_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  auto run = [&](int threads) {
    const std::string out = (dir / (threads == 1 ? "t1" : "t2")).string();  // ("t" + to_string: GCC 12 -Wrestrict)
    std::ostringstream c;
    c << RBCSTAB_CLI << " diagram --scene " << RBCSTAB_SCENES_DIR << "/appE_a_ip.toml --counts 6,6 --x-range 1,4 "
      << "--y-range -3,0 --no-journal --no-seconds --quiet --threads " << threads << " --out " << out;
    const std::string cmd = c.str();
    const int s = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(s) && WEXITSTATUS(s) == 0) << cmd;
    return std::pair(slurp(out + ".json"), slurp(out + ".csv"));
  };
  const auto [json1, csv1] = run(1);
  const auto [json2, csv2] = run(2);
  EXPECT_FALSE(json1.empty());
  EXPECT_NE(json1.find("\"agreement\""), std::string::npos);
  EXPECT_EQ(json1, json2);
  EXPECT_EQ(csv1, csv2);
  fs::remove_all(dir);
}
#endif

}  // namespace
}  // namespace rbcstab

namespace rbcstab {
namespace {

// A boundary the caller traced already (a report draws it) serves the agreement's distances: identical to the
// agreement tracing it itself, and really used (an empty boundary leaves every distance undefined).
TEST(Agreement, GivenAsymptoticBoundaryEqualsTracingIt) {
  Scene base;  // Fig. 3 out of plane: lambda = 5, Delta = 1 (the trace takes ~10 ms)
  DiagramSpec spec;
  spec.x.count = spec.y.count = 12;
  std::vector<PointResult> points(spec.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i].index = i;
    points[i].verdict = i % 3 ? Verdict::stable : Verdict::unstable;  // disagreements on both sides
    points[i].l_Delta = i % 3 ? 2 : 4;
  }
  AgreementOptions ao;
  ao.finite_horizon = false;
  const std::vector<Agreement> own = predictor_agreements(base, spec, points, ao);
  ao.asymptotic_boundary = std::make_shared<const TraceResult>(trace_boundary(base, spec, ao.trace_options));
  ASSERT_FALSE(ao.asymptotic_boundary->curves.empty());
  const std::vector<Agreement> given = predictor_agreements(base, spec, points, ao);
  ASSERT_EQ(own.size(), given.size());
  for (std::size_t k = 0; k < own.size(); ++k) {
    EXPECT_EQ(own[k].boundary_pieces, given[k].boundary_pieces) << own[k].predictor;
    EXPECT_EQ(own[k].beyond_one_step, given[k].beyond_one_step) << own[k].predictor;
    ASSERT_EQ(own[k].verdict_disagreements.size(), given[k].verdict_disagreements.size());
    for (std::size_t i = 0; i < own[k].verdict_disagreements.size(); ++i)
      EXPECT_EQ(own[k].verdict_disagreements[i].distance_steps, given[k].verdict_disagreements[i].distance_steps);
  }
  ao.asymptotic_boundary = std::make_shared<const TraceResult>();
  const std::vector<Agreement> empty = predictor_agreements(base, spec, points, ao);
  EXPECT_EQ(empty[0].boundary_pieces, 0u);
  ASSERT_FALSE(empty[0].verdict_disagreements.empty());
  EXPECT_FALSE(std::isfinite(empty[0].verdict_disagreements[0].distance_steps));
}

}  // namespace
}  // namespace rbcstab
