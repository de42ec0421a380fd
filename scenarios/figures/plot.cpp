#include "scenarios/figures/plot.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "scenarios/figures/child_process.h"
#include "sim/config.h"

#ifndef TACTIP_SCRIPTS_DIR
#error "TACTIP_SCRIPTS_DIR (the source tree's scripts/ folder) must be defined by the build"
#endif

namespace tactip {
namespace {

constexpr const char* kDebianPython = "/usr/bin/python3";
constexpr const char* kFix = "apt-get install python3-matplotlib (or set TACTIP_PYTHON), or pass --no-plots";

/// An environment variable's value, "" when unset.
std::string Env(const char* name) {
  const char* v = std::getenv(name);
  return v == nullptr ? "" : v;
}

/// Where PlotPython() came from, for messages.
std::string PythonOrigin() {
  if (!Env("TACTIP_PYTHON").empty()) return "TACTIP_PYTHON=" + Env("TACTIP_PYTHON");
  if (std::filesystem::exists(kDebianPython)) return kDebianPython;
  return "python3 on PATH";
}

/// Runs the script through the interpreter; InputError when the interpreter cannot start.
ChildResult RunScript(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {PlotPython(), PlotScript()};
  argv.insert(argv.end(), args.begin(), args.end());
  try {
    return RunChild(argv);
  } catch (const std::system_error& e) {
    throw InputError("plots need python3 with matplotlib: cannot run " + PythonOrigin() + " (" +
                     std::strerror(e.code().value()) + "); " + kFix);
  }
}

/// The reason a failed run gives: its last stderr line, or its exit status.
std::string FailureReason(const ChildResult& r) {
  const std::string line = LastLine(r.err);
  if (!line.empty()) return line;
  if (r.signal != 0) return "killed by signal " + std::to_string(r.signal);
  return "exit code " + std::to_string(r.exit_code);
}

/// Runs a drawing subcommand and checks that its PNG appeared.
void Draw(const std::vector<std::string>& args, const std::string& out_png) {
  RunPlotScript(args, "plot '" + out_png + "'");
  if (!std::filesystem::is_regular_file(out_png)) {
    throw PlotError("plot '" + out_png + "': the plotting script wrote no file");
  }
}

/// Joins `items` with commas.
std::string Join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ",") + s;
  return out;
}

/// The pareto subcommand's arguments for `p` (without --out / --print-front).
std::vector<std::string> ParetoArgs(const ParetoPlot& p) {
  std::vector<std::string> args = {"pareto", p.csv, "--x", p.x_column, "--y", Join(p.y_columns), "--label",
                                   p.label_column};
  if (!p.title.empty()) args.insert(args.end(), {"--title", p.title});
  return args;
}

}  // namespace

std::string PlotPython() {
  if (std::string v = Env("TACTIP_PYTHON"); !v.empty()) return v;
  if (std::filesystem::exists(kDebianPython)) return kDebianPython;
  return "python3";
}

std::string PlotScript() {
  const std::string dir = Env("TACTIP_SCRIPTS_DIR").empty() ? TACTIP_SCRIPTS_DIR : Env("TACTIP_SCRIPTS_DIR");
  return (std::filesystem::path(dir) / "plots" / "tactip_plot.py").string();
}

void CheckPlotting() {
  // The script first: without it no interpreter helps.
  const std::string script = PlotScript();
  if (!std::filesystem::is_regular_file(script)) {
    const std::string from = Env("TACTIP_SCRIPTS_DIR").empty() ? "the source tree this program was built from"
                                                               : "TACTIP_SCRIPTS_DIR";
    throw InputError("plots need the script '" + script + "' (from " + from +
                     "), which is missing: set TACTIP_SCRIPTS_DIR to tactip-sim's scripts/ folder, or pass "
                     "--no-plots");
  }
  // Then the interpreter and matplotlib: `check` imports it.
  const ChildResult r = RunScript({"check"});
  if (r.exit_code != 0) {
    throw InputError("plots need python3 with matplotlib: " + PythonOrigin() + " cannot draw (" + FailureReason(r) +
                     "); " + kFix);
  }
}

std::string RunPlotScript(const std::vector<std::string>& args, const std::string& what) {
  const ChildResult r = RunScript(args);
  if (r.exit_code != 0) throw PlotError(what + ": " + FailureReason(r));
  return r.out;
}

void PlotHeatmap(const HeatmapPlot& p) {
  std::vector<std::string> args = {"heatmap", p.csv, "--x", p.x_key, "--value", p.value, "--out", p.out_png};
  if (!p.y_key.empty()) args.insert(args.end(), {"--y", p.y_key});
  if (!p.title.empty()) args.insert(args.end(), {"--title", p.title});
  if (!p.unit.empty()) args.insert(args.end(), {"--unit", p.unit});
  Draw(args, p.out_png);
}

void PlotPareto(const ParetoPlot& p) {
  std::vector<std::string> args = ParetoArgs(p);
  args.insert(args.end(), {"--out", p.out_png});
  Draw(args, p.out_png);
}

void PlotRunFigure(const RunFigurePlot& p) {
  std::vector<std::string> args = {p.kind, p.csv, "--title", p.title, "--out", p.out_png};
  if (!p.events_csv.empty()) args.insert(args.end(), {"--events", p.events_csv});
  Draw(args, p.out_png);
}

std::vector<std::pair<std::string, std::vector<std::string>>> ParetoFronts(const ParetoPlot& p) {
  std::vector<std::string> args = ParetoArgs(p);
  args.push_back("--print-front");
  std::istringstream lines(RunPlotScript(args, "Pareto front of '" + p.csv + "'"));
  // One line per panel: COLUMN<TAB>SETTING<TAB>...
  std::vector<std::pair<std::string, std::vector<std::string>>> fronts;
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> fields;
    std::istringstream parts(line);
    for (std::string f; std::getline(parts, f, '\t');) fields.push_back(f);
    if (fields.empty()) continue;
    fronts.emplace_back(fields[0], std::vector<std::string>(fields.begin() + 1, fields.end()));
  }
  return fronts;
}

}  // namespace tactip
