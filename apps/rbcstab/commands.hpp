#pragma once
// Each subcommand registers its options on a CLI11 subcommand and returns the function that runs it.
#include <CLI/CLI.hpp>
#include <functional>

namespace rbcstab::cli {

using Runner = std::function<int()>;

Runner add_simulate(CLI::App& app);
Runner add_summary(CLI::App& app);

}  // namespace rbcstab::cli
