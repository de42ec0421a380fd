#pragma once
// The `tactip plot` subcommand: figures of one run of a dataset.

#include <CLI/CLI.hpp>

#include <functional>

namespace tactip::cli {

/// Registers `plot` on `app`. The returned function runs it when it was selected (returns
/// its exit code), or returns -1.
std::function<int()> AddPlotCommand(CLI::App& app);

}  // namespace tactip::cli
