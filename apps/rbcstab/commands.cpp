#include "commands.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "checks.hpp"

namespace rbcstab::cli {

std::vector<Command>& command_registry() {
  static std::vector<Command> registry;
  return registry;
}

namespace {
// The text CLI11 converts for a numeric option, made from rbcstab's own reading of the whole text: CLI11 alone
// reads "" as 0, "010" as octal 8, "0x10" as 16, "-1" for an unsigned option as 2^64 - 1, and a decimal through
// long double (rounded twice). Integers become plain decimal, other numbers hexadecimal floats (read exactly).
CLI::Validator whole_number(const std::string& type) {
  return CLI::Validator(
      [type](std::string& text) -> std::string {
        if (type == "FLOAT") {
          double v = 0;
          if (!parse_number(text, v)) return number_error(text);
          // Rewritten only when CLI11's reading would differ, so that messages quote the value as given.
          if (static_cast<double>(std::strtold(text.c_str(), nullptr)) != v) {
            char hex[64];
            std::snprintf(hex, sizeof hex, "%a", v);
            text = hex;
          }
          return {};
        }
        long long v = 0;
        if (!parse_integer(text, v)) return "'" + text + "' is not an integer";
        if (type == "UINT" && v < 0) return text + " is out of range: must be an integer >= 0";
        text = std::to_string(v);
        return {};
      },
      "", "");
}

// Adds whole_number last to every numeric option of app (after the option's own checks, whose messages name
// its range).
void read_numbers_whole(CLI::App& app) {
  for (CLI::Option* o : app.get_options()) {
    const std::string type = o->get_type_name().substr(0, o->get_type_name().find(':'));
    if (type != "FLOAT" && type != "INT" && type != "UINT") continue;
    o->check(whole_number(type), "whole_number");
    o->get_validator("whole_number")->non_modifying(false);  // check() adds a validator that cannot rewrite the text
  }
}
}  // namespace

std::map<CLI::App*, Runner> add_commands(CLI::App& app) {
  std::map<CLI::App*, Runner> runners;
  auto commands = command_registry();
  std::sort(commands.begin(), commands.end(), [](const Command& a, const Command& b) { return a.order < b.order; });
  for (const Command& c : commands) {
    CLI::App* sub = app.add_subcommand(c.name, c.help);
    runners[sub] = c.make(*sub);
    require_whole_numbers(*sub);  // checks whose messages name the flag's range come first
    read_numbers_whole(*sub);
  }
  return runners;
}

}  // namespace rbcstab::cli
