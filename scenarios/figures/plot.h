#pragma once
// Figures drawn by a real plotting tool: scripts/plots/tactip_plot.py (matplotlib) run by a
// Python interpreter, reading the CSVs tactip writes and writing PNGs.

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tactip {

/// A figure could not be drawn although the plotting tool started (the script failed);
/// the message is one line naming the figure and the script's reason.
class PlotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The Python interpreter that draws: $TACTIP_PYTHON when set and not empty, else
/// /usr/bin/python3 when it exists (Debian's, where python3-matplotlib installs), else
/// "python3" looked up on PATH.
std::string PlotPython();

/// The plotting script: $TACTIP_SCRIPTS_DIR/plots/tactip_plot.py when that variable is set
/// and not empty, else the source tree's scripts/plots/tactip_plot.py (path compiled in).
std::string PlotScript();

/// Checks once, before a long job, that the script exists and that PlotPython() runs and
/// imports matplotlib. Throws InputError, one line naming the missing piece and the fix
/// (install python3-matplotlib or set TACTIP_PYTHON, set TACTIP_SCRIPTS_DIR, or pass
/// --no-plots).
void CheckPlotting();

/// Runs the script with `args` (a subcommand and its options) and returns its standard
/// output. Throws InputError as CheckPlotting when the interpreter cannot be started, and
/// PlotError "<what>: <the script's last stderr line>" when the script fails.
std::string RunPlotScript(const std::vector<std::string>& args, const std::string& what);

/// One heatmap: a CSV column coloured and written per cell over one or two key columns
/// (rows = y, first seen on top; columns = x, in order of first appearance).
struct HeatmapPlot {
  std::string csv;      ///< CSV with one row per cell (e.g. a sweep's designs.csv)
  std::string x_key;    ///< column of the x axis
  std::string y_key;    ///< column of the y axis ("" for a one-row strip)
  std::string value;    ///< column coloured and printed in the cells (NaN: grey, "n/a")
  std::string title;    ///< figure title
  std::string unit;     ///< the value's unit, on the colour bar ("" if none)
  std::string out_png;  ///< PNG written atomically (nothing on failure)
};

/// Draws `p`; throws as RunPlotScript, or PlotError if no PNG appeared.
void PlotHeatmap(const HeatmapPlot& p);

/// Error against run time: one panel per error column, every setting a labelled point, the
/// Pareto front of the healthy settings as a step line, default and reference marked (see
/// docs/viewer-and-plots.md "Error against run time (pareto)"). The CSV's other columns: is_default,
/// is_reference, healthy (0/1).
struct ParetoPlot {
  std::string csv;                            ///< one row per numerical setting
  std::string x_column = "wall_s_per_sim_s";  ///< run time (wall s per simulated s), log axis
  std::vector<std::string> y_columns;         ///< error columns (smaller is better), one panel each
  std::string label_column = "setting";       ///< text naming each setting
  std::string title;                          ///< figure title ("" for the script's default)
  std::string out_png;                        ///< PNG written atomically (nothing on failure)
};

/// Draws `p` to p.out_png; throws as RunPlotScript, or PlotError if no PNG appeared.
void PlotPareto(const ParetoPlot& p);

/// One figure of a single run (`tactip plot`), drawn by the script's subcommand `kind`
/// from `csv` and the run's events (see docs/viewer-and-plots.md "Figures of one run").
struct RunFigurePlot {
  std::string kind;        ///< run-motion, run-quiver, run-markers or run-indentation
  std::string csv;         ///< the figure's table (see run_figures/run_tables.h)
  std::string events_csv;  ///< events.csv: onsets and fall drawn as vertical lines ("" for none)
  std::string title;       ///< figure title
  std::string out_png;     ///< PNG written atomically (nothing on failure)
};

/// Draws `p`; throws as RunPlotScript, or PlotError if no PNG appeared.
void PlotRunFigure(const RunFigurePlot& p);

/// Each panel's Pareto front, as the plot draws it: (error column, settings fastest
/// first). Needs no PNG (p.out_png is ignored) and no matplotlib; throws as RunPlotScript.
std::vector<std::pair<std::string, std::vector<std::string>>> ParetoFronts(const ParetoPlot& p);

}  // namespace tactip
