#pragma once
// `tactip track`: the hardware pin pipeline on a folder of real camera frames, written as
// the documented pin CSV that `tactip detect` reads.

#include <CLI/CLI.hpp>

#include <functional>

namespace tactip::cli {

/// Registers `track`; the returned function runs it (-1 when not selected).
std::function<int()> AddTrackCommand(CLI::App& app);

}  // namespace tactip::cli
