#pragma once
// The stability subcommand of `tactip`: the suite of stiff and extreme rail cases.

#include <CLI/CLI.hpp>

#include <atomic>
#include <functional>

namespace tactip::cli {

/// Registers `tactip stability` on `app`. The returned function runs it when it was selected
/// (returns its exit code: 0 every case healthy or refused clearly, 1 a case failed), or
/// returns -1 if it was not.
std::function<int()> AddStabilityCommands(CLI::App& app, const std::atomic<bool>* stop);

}  // namespace tactip::cli
