// rbcstab: the command-line tool. Only this program prints and chooses exit codes (docs/cli.md).
#include <CLI/CLI.hpp>
#include <iostream>
#include <map>

#include "checks.hpp"
#include "commands.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/text.hpp"

namespace {
// "--flag: " when the library named a parameter that the user gave as a flag of the running subcommand
// (max_points -> --max-points, run.T -> --T, diagram.x_range -> --x-range, or the command's flag_of), so every
// message names the flag; "" when the message already does or the value came from a scene file or a default.
std::string flag_hint(CLI::App& app, const std::vector<rbcstab::cli::Command>& commands,
                      const rbcstab::InvalidArgument& e) {
  const std::string parameter = e.parameter();
  // The flag overrides the file's value, but the file's own value was refused: the message says it came from there.
  if (std::string(e.what()).find(parameter + " from the scene file") != std::string::npos) return "";
  for (CLI::App* sub : app.get_subcommands()) {
    std::string flag = "--" + parameter.substr(parameter.rfind('.') + 1);
    for (char& c : flag)
      if (c == '_') c = '-';
    for (const auto& c : commands)
      if (c.name == sub->get_name() && c.flag_of.count(parameter)) flag = c.flag_of.at(parameter);
    if (std::string(e.what()).find(flag) != std::string::npos) return "";
    const CLI::Option* o = sub->get_option_no_throw(flag);
    if (o && o->count() > 0) return flag + ": ";
  }
  return "";
}
}  // namespace

int main(int argc, char** argv) {
  using namespace rbcstab::cli;
  // What the commands print directly (tables, progress) follows the renderers' rule: NaN reads "n/a".
  std::cout.imbue(rbcstab::text_locale());
  std::cerr.imbue(rbcstab::text_locale());
  CLI::App app{"rbcstab " RBCSTAB_VERSION
               ": shape dynamics and shape instabilities of a quasi-spherical red blood cell in shear flow\n"
               "(the perturbative model of Moriel, Stone and Mendez). Without a subcommand: the summary of the "
               "default scene."};
  app.set_version_flag("--version", "rbcstab " RBCSTAB_VERSION);
  app.require_subcommand(0, 1);
  std::map<CLI::App*, Runner> runners = add_commands(app);
  const std::vector<Command>& commands = command_registry();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e) == 0 ? kOk : kInvalidInput;  // --help, --version
    const std::string ours = parse_error_message(app, e);
    std::cerr << "rbcstab: error: " << (ours.empty() ? e.what() : ours) << "\nRun with --help for more information.\n";
    return kInvalidInput;
  }
  try {
    for (auto& [sub, run] : runners)
      if (sub->parsed()) return run();
    CLI::App* summary = app.get_subcommand("summary");
    summary->parse(std::vector<std::string>{});
    return runners[summary]();
  } catch (const rbcstab::InvalidArgument& e) {
    std::cerr << "rbcstab: error: " << flag_hint(app, commands, e) << e.what() << "\n";
    return kInvalidInput;
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kOk : kInvalidInput;
  } catch (const std::runtime_error& e) {
    std::cerr << "rbcstab: error: " << e.what() << "\n";
    return kOutputError;
  } catch (const std::exception& e) {
    std::cerr << "rbcstab: internal error: " << e.what() << "\n";
    return kInternalError;
  }
}
