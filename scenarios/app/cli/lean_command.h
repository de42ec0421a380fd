#pragma once
// `tactip bench --lean`: the lean-scene study (see scenarios/studies/lean/lean.h).

#include <string>
#include <vector>

#include "scenarios/studies/lean/lean.h"

namespace tactip::cli {

/// Measures the scenes named (empty: the study's defaults): the table on standard output,
/// one progress line per run on standard error, and DIR/lean.csv when `out_dir` is given.
/// An unknown scene or an unwritable folder is refused before anything runs (InputError).
int RunLeanStudy(const std::vector<std::string>& scenes, const LeanOptions& options, const std::string& out_dir);

}  // namespace tactip::cli
