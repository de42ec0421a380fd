#include "scenarios/app/cli/plot_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "scenarios/app/cli/common.h"
#include "scenarios/app/cli/option_checks.h"
#include "scenarios/app/cli/output_checks.h"
#include "scenarios/figures/plot.h"
#include "scenarios/figures/run_figures.h"
#include "sim/base/files.h"
#include "sim/config.h"

namespace tactip::cli {

namespace {

/// Largest --run accepted by the parser (run groups are run_NNNN; the file says which exist).
constexpr int kMaxRunIndex = 999999999;

/// The options of `tactip plot`.
struct PlotArgs {
  std::string dataset;  ///< FILE.h5
  int run = 0;          ///< --run K
  std::string sensor;   ///< --sensor NAME ("" = the first)
  std::string out;      ///< --out DIR
  bool no_plots = false;
};

// Refuses an output folder that is the input or holds it under a name written there, or an
// existing file that is not a folder.
void CheckOutputFolder(const PlotArgs& a) {
  if (SameFile(a.out, a.dataset)) {
    throw InputError(fmt::format("--out '{}' is the input dataset FILE: give a folder for the figures", a.out));
  }
  CheckOutputsAreNotInputs(FilesInFolder("--out", a.out, RunFigureFiles()), {{"FILE", a.dataset}});
  std::error_code ec;
  const auto status = std::filesystem::status(a.out, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_directory(status)) {
    throw InputError(fmt::format("--out '{}' is an existing file, not a folder: give a folder for the figures",
                                 a.out));
  }
}

int RunPlotCommand(const PlotArgs& a) {
  // Everything that can be wrong is found before the folder is made: the output, the file,
  // the run, the sensor and the plotting tool.
  CheckOutputFolder(a);
  const RunForFigures run = ReadRunForFigures(a.dataset, a.run, a.sensor);
  NoteFlaggedRuns(a.dataset, {a.run});
  if (!a.no_plots) CheckPlotting();
  NewFolderGuard folder(a.out);
  CreateOutputFolder(a.out);
  CheckWritableLocation((std::filesystem::path(a.out) / "events.csv").string());
  WriteRunFigures(run, a.out, !a.no_plots, [](const std::string& line) { std::printf("%s\n", line.c_str()); });
  folder.Keep();
  return 0;
}

}  // namespace

std::function<int()> AddPlotCommand(CLI::App& app) {
  auto a = std::make_shared<PlotArgs>();
  auto* c = app.add_subcommand("plot",
                               "Figures of one run of a dataset: pin displacement and speed over time with the "
                               "onsets, pin-velocity quivers around the onset, internal vs external markers, the "
                               "indentation field against radius (CSVs and PNGs; see docs/viewer-and-plots.md "
                               "'Figures of one run').");
  c->add_option("FILE", a->dataset, "Dataset (HDF5) written by 'tactip generate'.")
      ->required()
      ->check(NonEmpty("a dataset file"));
  c->add_option("--run", a->run, "Run index (see 'tactip info').")->required()->check(CLI::Range(0, kMaxRunIndex));
  c->add_option("--out", a->out, "Folder for the CSVs and PNGs (created if missing; files in it are replaced).")
      ->required()
      ->check(NonEmpty("a folder"));
  AddSensorOption(c, a->sensor);
  c->add_flag("--no-plots", a->no_plots, "Write the CSVs only.");
  return [a, c]() -> int { return *c ? RunPlotCommand(*a) : -1; };
}

}  // namespace tactip::cli
