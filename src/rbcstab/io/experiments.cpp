#include "rbcstab/io/experiments.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"

namespace rbcstab {

namespace {
namespace fs = std::filesystem;
constexpr const char* kFile = "experiments.csv";
const std::vector<std::string> kColumns = {
    "source",    "reference", "observation", "kind", "viscosity_Pa_s", "shear_rate_lo_per_s", "shear_rate_hi_per_s",
    "stress_Pa", "precision", "basis"};

}  // namespace

// One CSV record: fields split at commas outside double quotes; "" inside quotes is a quote.
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      out.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

std::vector<PublishedObservation> parse_observations(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  std::string line;
  int number = 0;
  std::map<std::string, std::size_t> column;
  std::vector<PublishedObservation> rows;
  auto fail = [&](const std::string& what) {
    throw InvalidArgument("experiments", path + ":" + std::to_string(number) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> f = csv_fields(line);
    if (column.empty()) {
      for (std::size_t k = 0; k < f.size(); ++k) column[f[k]] = k;
      for (const std::string& c : kColumns)
        if (!column.count(c)) fail("the header has no column '" + c + "'");
      continue;
    }
    if (f.size() != column.size())
      fail(std::to_string(f.size()) + " fields, the header has " + std::to_string(column.size()));
    auto text_of = [&](const std::string& c) { return f[column.at(c)]; };
    auto number_of = [&](const std::string& c) {
      const std::string v = text_of(c);
      if (v.empty()) return PublishedObservation::none;
      char* end = nullptr;
      const double x = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0' || !std::isfinite(x) || x <= 0)
        fail("column " + c + " = '" + v + "': must be a finite number > 0 in SI units (or empty)");
      return x;
    };
    PublishedObservation o;
    o.source = text_of("source");
    o.reference = text_of("reference");
    o.observation = text_of("observation");
    o.kind = text_of("kind");
    o.viscosity = number_of("viscosity_Pa_s");
    o.shear_rate_lo = number_of("shear_rate_lo_per_s");
    o.shear_rate_hi = number_of("shear_rate_hi_per_s");
    o.stress = number_of("stress_Pa");
    o.precision = text_of("precision");
    o.basis = text_of("basis");
    if (o.source.empty() || o.reference.empty()) fail("source and reference must be given");
    if (o.precision != "order" && o.precision != "range")
      fail("column precision = '" + o.precision + "': must be order or range");
    if (o.kind == "stress") {
      if (std::isnan(o.stress)) fail("kind stress needs stress_Pa");
    } else if (o.kind == "point" || o.kind == "rate_range") {
      if (std::isnan(o.viscosity) || std::isnan(o.shear_rate_lo) || std::isnan(o.shear_rate_hi))
        fail("kind " + o.kind + " needs viscosity_Pa_s, shear_rate_lo_per_s and shear_rate_hi_per_s");
      if (o.shear_rate_lo > o.shear_rate_hi) fail("shear_rate_lo_per_s > shear_rate_hi_per_s");
    } else {
      fail("column kind = '" + o.kind + "': must be stress, point or rate_range");
    }
    rows.push_back(o);
  }
  if (column.empty()) fail("no header line");
  return rows;
}

std::vector<PublishedObservation> read_observations(const std::string& path) {
  return parse_observations(read_file(path, "experiments", kMaxSceneBytes), path);
}

std::string shipped_observations(const std::string& executable_path) {
  std::error_code ec;
  if (const char* env = std::getenv("RBCSTAB_DATA_DIR"); env && *env)
    if (fs::is_regular_file(fs::path(env) / "data" / kFile, ec)) return (fs::path(env) / "data" / kFile).string();
  if (!executable_path.empty()) {
    const fs::path p = fs::path(executable_path).parent_path() / ".." / "share" / "rbcstab" / "data" / kFile;
    if (fs::is_regular_file(p, ec)) return fs::weakly_canonical(p, ec).string();
  }
  const fs::path source = fs::path(RBCSTAB_DATA_SOURCE_DIR) / kFile;
  return fs::is_regular_file(source, ec) ? source.string() : "";
}

nlohmann::json to_json(const std::vector<PublishedObservation>& observations) {
  nlohmann::json a = nlohmann::json::array();
  auto num = [](double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); };
  for (const PublishedObservation& o : observations)
    a.push_back({{"source", o.source},
                 {"reference", o.reference},
                 {"observation", o.observation},
                 {"kind", o.kind},
                 {"viscosity", num(o.viscosity)},
                 {"shear_rate_lo", num(o.shear_rate_lo)},
                 {"shear_rate_hi", num(o.shear_rate_hi)},
                 {"stress", num(o.stress)},
                 {"precision", o.precision},
                 {"basis", o.basis}});
  return a;
}

}  // namespace rbcstab
