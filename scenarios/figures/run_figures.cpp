#include "scenarios/figures/run_figures.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "scenarios/figures/plot.h"
#include "sensors/slip_data.h"
#include "sim/base/files.h"
#include "sim/base/number_text.h"
#include "sim/config.h"

namespace tactip {

namespace {

/// The stored config's principal point, else pin 0's first image position (it lies on the
/// camera axis).
ImageCentre PrincipalPoint(const DatasetHeader& header, const SensorRecord& s) {
  const FlatConfig flat = FlattenYaml(header.config_yaml, "the dataset's config_yaml");
  const auto cx = flat.find("sensor.cx_px"), cy = flat.find("sensor.cy_px");
  ImageCentre c;
  if (cx != flat.end() && cy != flat.end() && ParseWhole(cx->second, c.u_px) && ParseWhole(cy->second, c.v_px)) {
    return c;
  }
  return {s.pos_px.at(0), s.pos_px.at(1)};
}

/// "smooth skin, flat, 0.1 mm/s": what the run was, from its attributes.
std::string RunDescription(const RunRecord& run, const SensorRecord& s) {
  std::string out;
  if (const auto it = s.text_attrs.find("skin_pattern"); it != s.text_attrs.end()) out += it->second + " skin";
  if (const auto it = run.text_attrs.find("stimulus"); it != run.text_attrs.end()) {
    out += (out.empty() ? "" : ", ") + it->second;
  }
  if (const auto it = run.attrs.find("retract_speed_mm_s"); it != run.attrs.end() && std::isfinite(it->second)) {
    out += fmt::format("{}{:g} mm/s", out.empty() ? "" : ", ", it->second);
  }
  return out;
}

/// "gross-slip onset 4.086 s, no incipient onset, object fall 4.110 s".
std::string EventsText(const RunEvents& e) {
  auto one = [](const char* name, double t) {
    return std::isnan(t) ? fmt::format("no {}", name) : fmt::format("{} {:.3f} s", name, t);
  };
  return one("gross-slip onset", e.gross_slip_onset_s) + ", " + one("incipient onset", e.incipient_onset_s) + ", " +
         one("object fall", e.object_fall_s);
}

/// "pin 0 centre, pin 25 mid radius, ...": the pins shown on their own.
std::string PinRoles(const std::vector<ShownPin>& pins) {
  std::string out;
  for (const ShownPin& p : pins) out += fmt::format("{}pin {} {}", out.empty() ? "" : ", ", p.pin, p.role);
  return out;
}

/// The quiver figure's title: the frames shown and why.
std::string QuiverTitle(const QuiverFrames& q) {
  return fmt::format("pin velocity (px/frame) {} frames before, at and after the {} at {:.3f} s",
                     kQuiverOffsetFrames, q.onset_name, q.onset_s);
}

}  // namespace

RunForFigures ReadRunForFigures(const std::string& path, int index, const std::string& sensor) {
  const DatasetReader reader(path);
  const std::vector<int>& runs = reader.run_indices();
  if (!std::binary_search(runs.begin(), runs.end(), index)) {
    throw InputError(fmt::format("--run {}: {} has no run {} (it has {})", index, path, index, RunsText(runs)));
  }
  // The sensor is checked on the run's summary before the run is read in full.
  ChooseSensor(reader.ReadRunSummary(index), sensor, path);
  RunForFigures r;
  r.run = reader.ReadRun(index);
  const SensorRecord& s = ChooseSensor(r.run, sensor, path);
  r.sensor = s.name;
  r.centre = PrincipalPoint(reader.header(), s);
  const std::string what = RunDescription(r.run, s);
  r.caption = fmt::format("{} run {}, sensor {}{}{}", std::filesystem::path(path).filename().string(), index,
                          s.name, what.empty() ? "" : ": ", what);
  return r;
}

std::vector<std::string> RunFigureFiles() {
  std::vector<std::string> names = {"events.csv"};
  for (const char* figure : {"motion", "quiver", "markers", "indentation"}) {
    names.insert(names.end(), {std::string(figure) + ".csv", std::string(figure) + ".png"});
  }
  return names;
}

void WriteRunFigures(const RunForFigures& r, const std::string& dir, bool draw,
                     const std::function<void(const std::string&)>& say) {
  const SensorRecord& s = *r.run.FindSensor(r.sensor);
  const std::filesystem::path folder(dir);
  const std::string events = (folder / "events.csv").string();
  // One table and, when drawing, its figure.
  auto write = [&](const std::string& kind, const std::string& name, const std::string& csv_text,
                   const std::string& title) {
    const std::string csv = (folder / (name + ".csv")).string();
    WriteFileAtomic(csv, csv_text);
    say("wrote " + csv);
    if (!draw) return;
    const RunFigurePlot p{kind, csv, events, r.caption + "\n" + title, (folder / (name + ".png")).string()};
    PlotRunFigure(p);
    say("wrote " + p.out_png);
  };
  WriteFileAtomic(events, EventsCsv(r.run));
  say("wrote " + events);

  // 1. Pin motion over time, events marked.
  const std::vector<ShownPin> pins = RepresentativePins(s, r.centre);
  write("run-motion", "motion", MotionCsv(r.run, s, pins),
        "pin displacement and speed (" + PinRoles(pins) + "); " + EventsText(EventsOf(r.run)));
  // 2. Pin velocities around the onset.
  const QuiverFrames q = ChooseQuiverFrames(r.run, s);
  write("run-quiver", "quiver", QuiverCsv(r.run, s, q), QuiverTitle(q));
  // 3. Internal against external markers, when the run has both.
  if (s.external_px.empty()) {
    say("note: run " + std::to_string(r.run.index) + " has no external markers: no markers.csv or markers.png");
  } else {
    write("run-markers", "markers", MarkersCsv(r.run, s), "internal pins against external markers");
  }
  // 4. The indentation field at the deepest press.
  const ChosenFrame deepest = DeepestPressFrame(r.run, s);
  const int rest = RestFrame(s);
  write("run-indentation", "indentation", IndentationCsv(s, rest, deepest.frame, r.centre),
        fmt::format("indentation field at t = {:.3f} s (frame {}, {}) against frame {} (before the first "
                    "contact)",
                    deepest.time_s, deepest.frame, deepest.reason, rest));
}

}  // namespace tactip
