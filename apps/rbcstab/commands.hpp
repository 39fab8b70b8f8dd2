#pragma once
// Each subcommand lives in its own cmd_*.cpp and registers itself at start-up: it adds its options
// to a CLI11 subcommand and returns the function that runs it.
#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace rbcstab::cli {

// What a runner returns: the exit codes of the rbcstab tool (docs/cli.md).
constexpr int kOk = 0;             // done, every run succeeded
constexpr int kRunFailed = 1;      // input valid, but a computation ended with a failure status
constexpr int kInvalidInput = 2;   // bad flag, scene key or value: nothing was computed or written
constexpr int kOutputError = 3;    // an output file could not be written
constexpr int kInternalError = 4;  // a bug: please report

using Runner = std::function<int()>;
using CommandFactory = Runner (*)(CLI::App&);

struct Command {
  std::string name, help;
  CommandFactory make = nullptr;
  int order = 0;  // position in --help
  // The flag setting a library parameter whose name differs ("initial_step" -> "--step"), for messages.
  std::map<std::string, std::string> flag_of;
};

std::vector<Command>& command_registry();
// Adds every registered subcommand to app, in --help order; the runner of each (the program and the
// argument fuzzer build the same command line).
std::map<CLI::App*, Runner> add_commands(CLI::App& app);

struct RegisterCommand {
  RegisterCommand(const char* name, const char* help, CommandFactory make, int order,
                  std::map<std::string, std::string> flag_of = {}) {
    command_registry().push_back({name, help, make, order, std::move(flag_of)});
  }
};

}  // namespace rbcstab::cli
