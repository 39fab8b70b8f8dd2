// Non-finite values are never hidden, for every subcommand: each --json output and each JSON file written,
// over scenes at the extremes the documented ranges allow (lambda = 1e308, C = inf, B and C tiny), is strict
// JSON (no NaN or Infinity tokens), and every null -- or array holding one -- has its "<key>_reason"
// (unexplained_nulls, the library's own walker); every CSV written holds no nan or inf field. The inputs are
// valid, so the exit code is 0 or 1 (a run that stopped), never 2.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "rbcstab/io/json.hpp"

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The extremes: an input that overflows, the vesicle limit, and inputs whose inverse overflows.
const std::vector<std::pair<std::string, std::string>> kExtremes = {
    {"lambda = 1e308", "--lambda 1e308"}, {"C = inf", "--C inf"}, {"B tiny", "--B 1e-300"}, {"C tiny", "--C 1e-300"}};

class JsonWalk : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rbcstab_json_walk_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // Runs `rbcstab args` in a fresh folder, then checks stdout (when `json_out`) and every file written.
  void walk(const std::string& what, const std::string& args, bool json_out = true) {
    SCOPED_TRACE(what + ": rbcstab " + args);
    const fs::path work = dir_ / std::to_string(runs_++);
    fs::create_directories(work);
    const std::string out = (work / "stdout").string(), err = (work / "stderr").string();
    const std::string cmd =
        "cd '" + work.string() + "' && " + std::string(RBCSTAB_CLI) + " " + args + " > " + out + " 2> " + err;
    const int s = std::system(cmd.c_str());
    const int rc = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
    EXPECT_TRUE(rc == 0 || rc == 1) << "exit " << rc << "\n" << slurp(err);
    // A run that failed before it had anything to show (an orbit not found) prints nothing on stdout.
    if (json_out && !(rc == 1 && slurp(out).empty())) check_json("stdout", slurp(out));
    for (const auto& e : fs::recursive_directory_iterator(work)) {
      if (!e.is_regular_file()) continue;
      const std::string ext = e.path().extension().string();
      if (ext == ".json") check_json(e.path().string(), slurp(e.path()));
      if (ext == ".csv") check_csv(e.path().string(), slurp(e.path()));
    }
  }

  static void check_json(const std::string& where, const std::string& text) {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(text);  // strict: NaN and Infinity are not JSON
    } catch (const nlohmann::json::exception& e) {
      ADD_FAILURE() << where << " is not strict JSON (" << e.what() << "):\n" << text.substr(0, 400);
      return;
    }
    for (const std::string& path : rbcstab::unexplained_nulls(j))
      ADD_FAILURE() << where << ": null at " << path << " has no reason";
  }

  // Every field (split at newlines and commas), trimmed, without a sign, case-folded: never nan, inf or infinity.
  static void check_csv(const std::string& where, const std::string& text) {
    std::string field;
    auto check = [&] {
      std::string f;
      for (char c : field)
        if (!std::isspace(static_cast<unsigned char>(c))) f += char(std::tolower(static_cast<unsigned char>(c)));
      if (!f.empty() && (f[0] == '-' || f[0] == '+')) f.erase(0, 1);
      if (f == "nan" || f == "inf" || f == "infinity")
        ADD_FAILURE() << where << " holds a non-finite field: '" << field << "'";
      field.clear();
    };
    for (char c : text) {
      if (c == ',' || c == '\n')
        check();
      else
        field += c;
    }
    check();
  }

  // Each command line (without the scene flags) for every extreme scene.
  void walk_extremes(std::initializer_list<std::string> commands) {
    for (const auto& [name, scene] : kExtremes)
      for (const std::string& c : commands) walk(name, c + " " + scene);
  }
  // A file the last walk wrote.
  fs::path written(const std::string& name) const { return dir_ / std::to_string(runs_ - 1) / name; }

  fs::path dir_;
  int runs_ = 0;
};

TEST_F(JsonWalk, SceneCommands) {
  walk_extremes({"summary --T 5 --json", "simulate --T 5 --json --trajectory t.csv", "thresholds --json",
                 "post --T 5 --json", "shape --T 5 --resolution 8 --format csv --output s --json",
                 "floquet --T 5 --L 4 --relax-periods 1 --k 4 --json"});
}

TEST_F(JsonWalk, ContinuationAndPlot) {
  walk_extremes(
      {"continue --max-points 12 --save b.json --csv b.csv --json", "continue --kind orbit --max-points 6 --json"});
  // A branch of the vesicle limit drawn by plot: the figure's JSON beside the PNG.
  walk("plot", "continue --max-points 12 --save b.json --C inf --json");
  walk("plot", "plot " + written("b.json").string() + " --output p.png --json");
}

TEST_F(JsonWalk, PlaneCommands) {
  walk_extremes(
      {"diagram --counts 3,3 --T 5 --no-journal --quiet --out d --json", "trace --lines 2 --samples 8 --out t --json"});
  // Two shards of a failing grid, merged.
  std::string shards;
  for (const std::string k : {"0", "1"}) {
    walk("merge", "diagram --counts 2,2 --T 5 --lambda 1e308 --no-journal --quiet --out m --json --shard " + k + "/2");
    shards += ' ';
    shards += written("m.shard" + k + "of2.json").string();
  }
  walk("merge", "merge" + shards + " --out merged --json");
}

TEST_F(JsonWalk, ReportAndBench) {
  walk_extremes(
      {"report --T 5 --frames 2 --shape-resolution 8 --output r --json",
       "bench truncation --T 5 --Ls 3,4 --no-plot --output b --json",
       "bench work-precision --T 5 --levels modal --steppers rk8pd --rtols 1e-4 --no-plot --output b --json"});
  walk("lambda = 1e308", "bench threshold --lambda 1e308 --no-plot --output b --json");
}

}  // namespace
