// Diagram journals (sweep/diagram.hpp run_diagram with DiagramOptions::journal): the input is the journal file
// a run resumes from, for the 2 x 2 diagram of journal_scene.toml. If the first byte is odd the rest is written
// with every record's checksum recomputed (so that the values behind the checksum are fuzzed too), otherwise
// as given. A journal refused as a whole (another configuration, a lock) is a clean InvalidArgument. A resumed
// run must
//   - finish every point of the grid, each passing point_value_error;
//   - resume exactly the records parse_point_line accepts whose index appears once, and report every other
//     line (torn, corrupt, foreign, duplicated) in DiagramRun::rejected;
//   - leave a journal from which a second run resumes every point, computes none, rejects nothing and gives
//     the same points bit for bit; and leave no lock or temporary file behind.
#include <dirent.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <map>

#include "fuzz_check.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/diagram_table.hpp"
#include "rbcstab/sweep/point_record.hpp"

using namespace rbcstab;
using namespace rbcstab::fuzz;

namespace {
struct Config {
  SceneFile file;
  DiagramSpec spec;
  std::string hash, dir, journal;
};

std::string scratch_folder() {
  const char* base =
      access("/dev/shm", W_OK) == 0 ? "/dev/shm" : (std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp");
  std::string templ = std::string(base) + "/rbcstab-fuzz-journal-XXXXXX";
  if (!mkdtemp(templ.data())) fail("cannot create a scratch folder in " + std::string(base));
  return templ;
}

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> out;
  if (DIR* d = opendir(dir.c_str())) {
    while (const dirent* e = readdir(d))
      if (std::string(e->d_name) != "." && std::string(e->d_name) != "..") out.emplace_back(e->d_name);
    closedir(d);
  }
  return out;
}

// Never destroyed, so that the exit handler removing the scratch folder can still read it (it runs after the
// destructor of a static Config would).
const Config& config() {
  static const Config& c = *[] {
    Config* k = new Config;
    k->file = load_scene(RBCSTAB_FUZZ_JOURNAL_SCENE);
    k->spec = diagram_spec(k->file);
    k->hash = config_hash(k->file.scene, k->file.options, k->spec);
    k->dir = scratch_folder();
    k->journal = k->dir + "/fuzz.journal";
    std::atexit([] {
      const Config& self = config();
      for (const std::string& e : entries(self.dir)) std::remove((self.dir + "/" + e).c_str());
      rmdir(self.dir.c_str());
    });
    return k;
  }();
  return c;
}

// Every "body *checksum" line with the checksum of its body.
std::string with_checksums(const std::string& text) {
  std::string out;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t eol = text.find('\n', pos);
    std::string line = text.substr(pos, eol == std::string::npos ? std::string::npos : eol - pos);
    pos = eol == std::string::npos ? text.size() : eol + 1;
    const std::size_t mark = line.rfind(" *");
    if (mark != std::string::npos) line = line.substr(0, mark) + " *" + fnv1a_hex(line.substr(0, mark));
    out += line + (eol == std::string::npos ? "" : "\n");
  }
  return out;
}

bool same_point(const PointResult& a, const PointResult& b) {
  return a.index == b.index && a.verdict == b.verdict && a.l_Delta == b.l_Delta && same(a.growth, b.growth) &&
         a.oscillating == b.oscillating && same(a.sigma_final, b.sigma_final) && a.status == b.status &&
         a.reason == b.reason && same(a.t_reached, b.t_reached) && a.steps == b.steps &&
         a.failed_steps == b.failed_steps && a.rhs_evaluations == b.rhs_evaluations && same(a.seconds, b.seconds) &&
         same(a.x, b.x) && same(a.y, b.y);
}

DiagramRun resume(const Config& c) {
  DiagramOptions o;
  o.threads = 1;
  o.journal = c.journal;
  return run_diagram(c.file.scene, c.file.options, c.spec, o);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0 || size > 65536) return 0;
  const Config& c = config();
  const std::string content = data[0] % 2 ? with_checksums(text_of(data + 1, size - 1)) : text_of(data + 1, size - 1);
  { std::ofstream(c.journal, std::ios::binary | std::ios::trunc) << content; }

  DiagramRun first;
  const bool ok = accepted([&] { first = resume(c); });
  const std::vector<std::string> left = entries(c.dir);
  expect(left.size() == 1 && left[0] == "fuzz.journal",
         "a run leaves " + std::to_string(left.size()) + " files in its folder");
  if (!ok) return 0;

  // What the records say, by parse_point_line alone: lines after the header line (none if the header is torn).
  std::map<std::size_t, int> times;
  std::size_t lines = 0, refused = 0;
  const std::size_t header_end = content.find('\n');
  for (std::size_t pos = header_end == std::string::npos ? content.size() : header_end + 1; pos < content.size();) {
    const std::size_t eol = content.find('\n', pos);
    const std::string line = content.substr(pos, eol == std::string::npos ? std::string::npos : eol + 1 - pos);
    pos = eol == std::string::npos ? content.size() : eol + 1;
    ++lines;
    const ParsedPoint r = parse_point_line(line, c.hash, c.spec, c.file.scene.L);
    if (r.point)
      ++times[r.point->index];
    else
      ++refused;
  }
  std::size_t once = 0, repeats = 0;  // a point's first record is dropped silently, every repeat is reported
  for (const auto& [idx, n] : times) {
    if (n == 1)
      ++once;
    else
      repeats += std::size_t(n - 1);
  }

  expect(first.complete && first.points.size() == c.spec.size(), "a resumed run did not finish the grid");
  for (std::size_t k = 0; k < first.points.size(); ++k) {
    expect(first.points[k].index == k, "a resumed run's points are not the grid in index order");
    const FieldError e = point_value_error(first.points[k], c.spec, c.file.scene.L);
    expect(e.empty(), "a resumed run holds an invalid point: " + e.why);
  }
  expect(first.resumed == once, "resumed " + std::to_string(first.resumed) + " points, the journal holds " +
                                    std::to_string(once) + " valid records of distinct points");
  expect(first.resumed + first.computed == c.spec.size(), "resumed + computed is not the grid's size");
  expect(first.rejected.size() == refused + repeats, "rejected " + std::to_string(first.rejected.size()) +
                                                         " records of " + std::to_string(lines) + ", expected " +
                                                         std::to_string(refused + repeats));

  const DiagramRun second = resume(c);
  expect(second.resumed == c.spec.size() && second.computed == 0 && second.rejected.empty(),
         "the journal a run leaves is not resumed whole (" + std::to_string(second.rejected.size()) + " rejected)");
  for (std::size_t k = 0; k < second.points.size(); ++k)
    expect(same_point(first.points[k], second.points[k]), "point " + std::to_string(k) + " changes on a second resume");
  return 0;
}
