#include "commands.hpp"

#include <algorithm>

#include "checks.hpp"

namespace rbcstab::cli {

std::vector<Command>& command_registry() {
  static std::vector<Command> registry;
  return registry;
}

std::map<CLI::App*, Runner> add_commands(CLI::App& app) {
  std::map<CLI::App*, Runner> runners;
  auto commands = command_registry();
  std::sort(commands.begin(), commands.end(), [](const Command& a, const Command& b) { return a.order < b.order; });
  for (const Command& c : commands) {
    CLI::App* sub = app.add_subcommand(c.name, c.help);
    runners[sub] = c.make(*sub);
    read_numbers_whole(*sub);
  }
  return runners;
}

}  // namespace rbcstab::cli
