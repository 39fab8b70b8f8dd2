// The command line as the program parses it: every subcommand and flag (apps/rbcstab/commands.hpp
// add_commands), with CLI11's splitting of comma lists (--x-range, --counts, --axes) and rbcstab's validators
// (apps/rbcstab/checks.hpp). The input's lines are the arguments after "rbcstab"; nothing is run. A parse
// error (CLI::ParseError) is a clean refusal. After an accepted parse
//   - every value of a numeric option (CLI11 type FLOAT, INT, UINT) is a number given in full (read_number,
//     read_integer: no empty text, no trailing text) and CLI11 stores the value that text means;
//   - no comma-list value had an empty item ("1,,2", "1,2,"): CLI11 drops those, which would accept a list
//     with a missing number as another list.
#include <CLI/CLI.hpp>

#include "checks.hpp"
#include "commands.hpp"
#include "fuzz_check.hpp"

using namespace rbcstab;
using namespace rbcstab::fuzz;

namespace {
std::string type_of(const CLI::Option& o) {
  const std::string t = o.get_type_name();
  return t.substr(0, t.find(':'));
}

void check_numbers(const CLI::Option& o) {
  const std::string type = type_of(o);
  for (const std::string& r : o.results()) {
    if (type == "FLOAT") {
      const std::optional<double> ours = read_number(r);
      double theirs = 0;
      expect(ours.has_value(), o.get_name() + " accepted '" + r + "', which is not a number in full");
      expect(CLI::detail::lexical_cast(r, theirs) && same(ours.value_or(0), theirs),
             o.get_name() + " stores another value than '" + r + "' means");
    } else if (type == "INT" || type == "UINT") {
      const std::optional<long long> ours = read_integer(r);
      long long theirs = 0;
      expect(ours.has_value(), o.get_name() + " accepted '" + r + "', which is not an integer in full");
      expect(CLI::detail::lexical_cast(r, theirs) && ours == theirs,
             o.get_name() + " stores another value than '" + r + "' means");
      expect(type == "INT" || ours.value_or(0) >= 0,
             o.get_name() + " accepted the negative '" + r + "' for an unsigned value");
    }
  }
}

bool has_empty_item(const std::string& value, char delimiter) {
  if (value.find(delimiter) == std::string::npos) return false;
  for (const std::string& item : split(value, delimiter))
    if (item.empty()) return true;
  return false;
}

// The values the arguments give to option o ("--name=v", or "--name" then "v").
std::vector<std::string> values_of(const CLI::Option& o, const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (const std::string& name : o.get_lnames()) {
    const std::string flag = "--" + name;
    for (std::size_t a = 0; a < args.size(); ++a) {
      if (args[a].rfind(flag + "=", 0) == 0) out.push_back(args[a].substr(flag.size() + 1));
      if (args[a] == flag && a + 1 < args.size() && args[a + 1].rfind("--", 0) != 0) out.push_back(args[a + 1]);
    }
  }
  return out;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 4096) return 0;
  std::vector<std::string> args = split(text_of(data, size), '\n');
  for (const std::string& a : args)
    if (a.find('\0') != std::string::npos) return 0;  // a command line cannot hold a NUL byte
  std::vector<char*> argv;
  std::string program = "rbcstab";
  argv.push_back(program.data());
  for (std::string& a : args) argv.push_back(a.data());

  CLI::App app{"rbcstab"};
  app.require_subcommand(0, 1);
  const auto runners = cli::add_commands(app);
  try {
    app.parse(int(argv.size()), argv.data());
  } catch (const CLI::ParseError&) {
    return 0;
  } catch (const std::exception& e) {
    fail(std::string("the parse threw something other than CLI::ParseError: ") + e.what());
  }
  for (const auto& [sub, run] : runners) {
    if (!sub->parsed()) continue;
    for (const CLI::Option* o : sub->get_options()) {
      if (o->count() == 0) continue;
      check_numbers(*o);
      if (o->get_delimiter() == '\0') continue;
      for (const std::string& v : values_of(*o, args))
        expect(!has_empty_item(v, o->get_delimiter()), o->get_name() + " accepted '" + v + "' with an empty item");
    }
  }
  return 0;
}
