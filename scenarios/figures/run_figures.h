#pragma once
// `tactip plot FILE.h5 --run K --out DIR`: one run of a dataset read, its figure tables
// written as CSVs into DIR and drawn as PNGs by scripts/plots/tactip_plot.py.

#include <functional>
#include <string>
#include <vector>

#include "scenarios/figures/run_tables.h"
#include "sensors/dataset.h"

namespace tactip {

/// One run of a dataset, checked and read for its figures.
struct RunForFigures {
  RunRecord run;         ///< the whole run
  std::string sensor;    ///< the sensor drawn (its name in the run)
  ImageCentre centre;    ///< the internal camera's principal point (px)
  std::string caption;   ///< "rail.h5 run 3, sensor tactip: smooth skin, flat, 0.1 mm/s"
};

/// Reads run `index` of dataset `path` and picks sensor `sensor` ("" = the first). Throws
/// InputError in one line for a missing or unreadable file, "--run K: PATH has no run K (it
/// has runs 0-3)" and ChooseSensor's message for an unknown sensor; the run is read in full
/// only after both checks. The principal point is the stored config's sensor.cx_px /
/// sensor.cy_px, else pin 0's first image position.
RunForFigures ReadRunForFigures(const std::string& path, int index, const std::string& sensor);

/// Names of every file WriteRunFigures may write into its folder.
std::vector<std::string> RunFigureFiles();

/// Writes the run's figure tables into the existing folder `dir` — events.csv, motion.csv,
/// quiver.csv, markers.csv (only with external markers), indentation.csv — and, when
/// `draw`, each table's PNG (motion.png, quiver.png, markers.png, indentation.png), every
/// file atomically. Calls `say` with "wrote PATH" after each file and a note when the
/// markers figure is skipped. Throws InputError if a file cannot be written, and as
/// PlotRunFigure when a figure fails (files already written stay, complete).
void WriteRunFigures(const RunForFigures& r, const std::string& dir, bool draw,
                     const std::function<void(const std::string&)>& say);

}  // namespace tactip
