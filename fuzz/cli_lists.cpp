// The small text parsers behind command-line values: --shard k/n (shard_from_string), --measures a,b
// (TableOptions::from_list, checked against a branch's measures) and the names of diagram axes and classifiers.
// The input's first byte picks the parser, the rest is the value. An accepted value must
//   - shard: satisfy 0 <= k < n and be exactly the "k/n" that strtol reads from it, and "k/n" must parse back;
//   - measures: one non-empty name per comma-separated piece (no piece dropped; the empty text: no names,
//     the default table), joining back to the same list, and validate only when each is a branch measure;
//   - axis, classifier: be exactly a listed name (no case folding, no prefix, no trailing text).
#include <algorithm>
#include <cerrno>
#include <cstdlib>

#include "fuzz_check.hpp"
#include "rbcstab/continuation/branch_io.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
#include "rbcstab/sweep/diagram.hpp"

using namespace rbcstab;
using namespace rbcstab::fuzz;

namespace {
void shard(const std::string& text) {
  Shard s;
  if (!accepted([&] { s = shard_from_string(text); })) return;
  expect(s.n >= 1 && s.k >= 0 && s.k < s.n, "shard '" + text + "' gives k/n outside 0 <= k < n");
  const std::size_t slash = text.find('/');
  expect(slash != std::string::npos && text.find('\0') == std::string::npos, "shard '" + text + "' has no k/n form");
  const std::string ks = text.substr(0, slash), ns = text.substr(slash + 1);
  char* end = nullptr;
  errno = 0;
  const long k = std::strtol(ks.c_str(), &end, 10);
  expect(!errno && end != ks.c_str() && !*end && k == s.k, "shard '" + text + "' is not read as its k");
  const long n = std::strtol(ns.c_str(), &end, 10);
  expect(!errno && end != ns.c_str() && !*end && n == s.n, "shard '" + text + "' is not read as its n");
  const std::string canonical = std::to_string(s.k) + "/" + std::to_string(s.n);
  Shard back;
  expect(accepted([&] { back = shard_from_string(canonical); }) && back.k == s.k && back.n == s.n,
         "shard '" + canonical + "' does not parse back");
}

void measures(const std::string& text) {
  TableOptions t;
  if (!accepted([&] { t = TableOptions::from_list(text); })) return;
  std::string joined;
  for (const std::string& m : t.measures) {
    expect(!m.empty() && m.find(',') == std::string::npos, "from_list('" + text + "') gives the name '" + m + "'");
    joined += (joined.empty() ? "" : ",") + m;
  }
  const std::size_t pieces = text.empty() ? 0 : split(text, ',').size();
  expect(t.measures.size() == pieces, "from_list('" + text + "') gives " + std::to_string(t.measures.size()) +
                                          " names for " + std::to_string(pieces) + " pieces");
  expect(TableOptions::from_list(joined).measures == t.measures, "from_list('" + joined + "') does not round-trip");
  for (ProblemKind kind : {ProblemKind::equilibrium, ProblemKind::orbit}) {
    const std::vector<std::string> available = measure_names(kind, 4);
    if (!accepted([&] { t.validate(available); })) continue;
    for (const std::string& m : t.measures)
      expect(std::find(available.begin(), available.end(), m) != available.end(), "measure '" + m + "' validates");
  }
}

template <class Parse>
void name(const std::string& text, const std::vector<std::string>& names, Parse parse, const char* what) {
  const bool listed = std::find(names.begin(), names.end(), text) != names.end();
  const bool ok = accepted([&] { (void)parse(text); });
  expect(ok == listed,
         std::string(what) + " '" + text + (ok ? "' is accepted but not listed" : "' is listed but refused"));
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0 || size > 4096) return 0;
  const std::string text = text_of(data + 1, size - 1);
  switch (data[0] % 4) {
    case 0:
      shard(text);
      break;
    case 1:
      measures(text);
      break;
    case 2:
      name(text, axis_names(), axis_from_string, "axis");
      break;
    default:
      name(text, enum_names<Classifier>(), classifier_from_string, "classifier");
      break;
  }
  return 0;
}
