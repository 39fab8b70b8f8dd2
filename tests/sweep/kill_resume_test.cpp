// Integration test: `rbcstab diagram` killed with SIGKILL mid-run and rerun with the same command
// loses no finished point and recomputes none; SIGINT stops it cleanly with the same guarantee.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;

struct JournalView {
  std::size_t points = 0;
  std::set<std::string> indices;
};

JournalView read_journal(const std::string& path) {
  JournalView v;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::istringstream ss(line);
    std::string tag, hash, index;
    ss >> tag >> hash >> index;
    if (tag != "P") continue;
    ++v.points;
    v.indices.insert(index);
  }
  return v;
}

pid_t spawn(const std::vector<std::string>& args, const std::string& stderr_path) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    if (!freopen(stderr_path.c_str(), "w", stderr)) _exit(126);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

int wait_exit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

using rbcstab::test::slurp;

// 10 x 8 points of the Fig. 4(b) panel region integrated to T = 3000 (--full-horizon: early termination would
// finish the grid before the kill): about 12 ms a point, 1 s on one thread, so that polling the journal every
// 2 ms catches the run midway.
std::vector<std::string> command(const std::string& out) {
  return {RBCSTAB_CLI,
          "diagram",
          "--L",
          "6",
          "--T",
          "3000",
          "--dt",
          "3000",
          "--full-horizon",
          "--axes",
          "lnB,lnC",
          "--x-range=-1,6",
          "--y-range=-5.5,2",
          "--counts",
          "10,8",
          "--classifier",
          "final",
          "--threads",
          "1",
          "--no-seconds",
          "--out",
          out};
}

void kill_and_resume(int signal_number) {
  const fs::path dir = fs::temp_directory_path() /
                       ("rbcstab_kill_test_" + std::to_string(getpid()) + "_" + std::to_string(signal_number));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = (dir / "panel").string(), journal = out + ".journal", err = (dir / "err.txt").string();

  const pid_t pid = spawn(command(out), err);
  // Wait until a few points are journaled (but not all), then kill.
  const auto t0 = std::chrono::steady_clock::now();
  while (read_journal(journal).points < 5 && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  kill(pid, signal_number);
  const int rc = wait_exit(pid);
  EXPECT_NE(rc, 0) << "the sweep finished before it could be interrupted";
  const JournalView before = read_journal(journal);
  ASSERT_GE(before.points, 5u);
  ASSERT_LT(before.points, 80u) << "the sweep finished before it could be interrupted";
  EXPECT_EQ(before.indices.size(), before.points);
  EXPECT_FALSE(fs::exists(out + ".csv")) << "outputs must only appear for a finished sweep";

  // Rerun the same command: it resumes exactly the journaled points and computes the rest.
  ASSERT_EQ(wait_exit(spawn(command(out), err)), 0) << slurp(err);
  const std::string log = slurp(err);
  EXPECT_NE(log.find("80 points (" + std::to_string(80 - before.points) + " computed, " +
                     std::to_string(before.points) + " resumed)"),
            std::string::npos)
      << log;
  const JournalView after = read_journal(journal);
  EXPECT_EQ(after.points, 80u);  // one line per point: nothing recomputed
  EXPECT_EQ(after.indices.size(), 80u);

  // The result equals an uninterrupted run byte for byte.
  const std::string clean = (dir / "clean").string();
  ASSERT_EQ(wait_exit(spawn(command(clean), err)), 0) << slurp(err);
  EXPECT_EQ(slurp(out + ".csv"), slurp(clean + ".csv"));
  EXPECT_EQ(slurp(out + ".json"), slurp(clean + ".json"));
  fs::remove_all(dir);
}

TEST(DiagramCli, SigkillMidRunLosesNothingAndRecomputesNothing) { kill_and_resume(SIGKILL); }
TEST(DiagramCli, SigintMidRunLosesNothingAndRecomputesNothing) { kill_and_resume(SIGINT); }

}  // namespace

namespace {
// Job arrays: `--shard k/3` runs then `rbcstab merge` give the serial CSV and JSON byte for byte.
TEST(DiagramCli, ShardsMergeToTheSerialOutput) {
  const fs::path dir = fs::temp_directory_path() / ("rbcstab_merge_test_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string err = (dir / "err.txt").string();
  auto args = [&](const std::string& out) {
    return std::vector<std::string>{
        RBCSTAB_CLI, "diagram", "--L",       "5", "--T",          "60",      "--dt",  "60",
        "--counts",  "5,4",     "--threads", "2", "--no-seconds", "--quiet", "--out", (dir / out).string()};
  };
  ASSERT_EQ(wait_exit(spawn(args("serial"), err)), 0) << slurp(err);
  std::vector<std::string> merge{RBCSTAB_CLI, "merge", "--out", (dir / "merged").string()};
  for (int k = 0; k < 3; ++k) {
    auto a = args("part");
    a.push_back("--shard");
    a.push_back(std::to_string(k) + "/3");
    ASSERT_EQ(wait_exit(spawn(a, err)), 0) << slurp(err);
    merge.push_back((dir / ("part.shard" + std::to_string(k) + "of3.json")).string());
  }
  std::vector<std::string> partial(merge.begin(), merge.end() - 1);
  EXPECT_EQ(wait_exit(spawn(partial, err)), 1) << "a merge with a missing shard must fail";
  ASSERT_EQ(wait_exit(spawn(merge, err)), 0) << slurp(err);
  EXPECT_EQ(slurp((dir / "merged.csv").string()), slurp((dir / "serial.csv").string()));
  EXPECT_EQ(slurp((dir / "merged.json").string()), slurp((dir / "serial.json").string()));
  fs::remove_all(dir);
}
}  // namespace
