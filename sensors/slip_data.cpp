#include "sensors/slip_data.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "detectors/pin_csv.h"
#include "sensors/dataset.h"
#include "sim/config.h"

namespace tactip {

std::vector<int> ParseRunList(const std::string& text) {
  std::set<int> out;
  size_t start = 0;
  auto bad = [&] { return InputError("--runs '" + text + "': expected e.g. 0-19 or 0,3,5-7"); };
  auto number = [&](const std::string& s) {
    if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 9) throw bad();
    return std::stoi(s);
  };
  if (text.empty()) throw bad();
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    const size_t dash = item.find('-');
    if (dash == std::string::npos) {
      out.insert(number(item));
    } else {
      const int a = number(item.substr(0, dash)), b = number(item.substr(dash + 1));
      if (b < a) throw bad();
      if (b - a > 1000000) throw InputError("--runs '" + text + "': range larger than a million runs");
      for (int i = a; i <= b; ++i) out.insert(i);
    }
    start = comma + 1;
  }
  return {out.begin(), out.end()};
}

std::string RunsText(const std::vector<int>& runs) {
  if (runs.size() == 1) return fmt::format("run {}", runs.front());
  if (runs.back() - runs.front() + 1 == static_cast<int>(runs.size())) {
    return fmt::format("runs {}-{}", runs.front(), runs.back());
  }
  return fmt::format("{} runs from {} to {}", runs.size(), runs.front(), runs.back());
}

const SensorRecord& ChooseSensor(const RunRecord& run, const std::string& name, const std::string& path) {
  if (name.empty() && !run.sensors.empty()) return run.sensors.front();
  if (const SensorRecord* s = run.FindSensor(name)) return *s;
  throw InputError(fmt::format("--sensor '{}': dataset '{}' has no such sensor (its sensors: {})", name, path,
                               SensorNames(run)));
}

void CheckSensorOption(const std::string& path, const std::string& name) {
  const DatasetReader reader(path);
  ChooseSensor(reader.ReadRunSummary(reader.run_indices().front()), name, path);
}

namespace {

/// The frames of sensor `s` of run `rec` (read from `path`), exactly what a camera gives:
/// pixel positions and detection flags, of the camera model or of the blob pipeline.
std::vector<PinFrame> SensorFrames(const RunRecord& rec, const SensorRecord& s, const std::string& path,
                                   PinSource pins) {
  const size_t T = rec.frames(), N = static_cast<size_t>(s.n_pins);
  if (pins == PinSource::kDetected && s.detected_px.empty()) {
    throw InputError(fmt::format("--pins detected: dataset '{}' {}/sensors/{} has no pins/detected_px (generate it "
                                 "with --images)",
                                 path, RunGroupName(rec.index), s.name));
  }
  const std::vector<float>& pos_px = pins == PinSource::kDetected ? s.detected_px : s.pos_px;
  const std::vector<std::uint8_t>& valid = pins == PinSource::kDetected ? s.detected_valid : s.valid;
  std::vector<PinFrame> frames(T);
  for (size_t f = 0; f < T; ++f) {
    PinFrame& pf = frames[f];
    pf.time_s = rec.time[f];
    pf.pos_px.resize(static_cast<Eigen::Index>(N), 2);
    pf.valid.assign(valid.begin() + f * N, valid.begin() + (f + 1) * N);
    for (size_t i = 0; i < N; ++i) {
      const float u = pos_px[(f * N + i) * 2], v = pos_px[(f * N + i) * 2 + 1];
      if (!std::isfinite(u) || !std::isfinite(v)) {
        throw InputError(fmt::format("dataset '{}' run {} frame {} pin {}: position is not a finite number", path,
                                     rec.index, f, i));
      }
      pf.pos_px(static_cast<Eigen::Index>(i), 0) = u;
      pf.pos_px(static_cast<Eigen::Index>(i), 1) = v;
    }
  }
  return frames;
}

}  // namespace

PinSource ParsePinSource(const std::string& text) {
  if (text == "camera") return PinSource::kCamera;
  if (text == "detected") return PinSource::kDetected;
  throw InputError("--pins '" + text + "': must be camera or detected");
}

OnsetLabels ParseOnsetLabels(const std::string& text) {
  if (text == "exact") return OnsetLabels::kExact;
  if (text == "marker") return OnsetLabels::kMarker;
  throw InputError("--labels '" + text + "': must be exact or marker");
}

std::vector<LabeledRun> LoadDatasetRuns(const std::string& path, const std::vector<int>& runs,
                                        bool score_onset_frame, const std::string& sensor, PinSource pins,
                                        OnsetLabels labels) {
  const DatasetReader reader(path);
  std::vector<int> wanted = runs.empty() ? reader.run_indices() : runs;
  for (int idx : wanted) {
    if (!std::binary_search(reader.run_indices().begin(), reader.run_indices().end(), idx)) {
      throw InputError(fmt::format("dataset '{}' has no run {} (it has {} runs)", path, idx,
                                   reader.run_indices().size()));
    }
  }
  // The sensor is checked before any run is read in full.
  ChooseSensor(reader.ReadRunSummary(wanted.front()), sensor, path);
  std::vector<LabeledRun> out;
  for (int idx : wanted) {
    const RunRecord rec = reader.ReadRun(idx);
    LabeledRun run;
    run.run = idx;
    const size_t T = rec.frames();
    if (T >= 2) run.frame_rate_hz = (T - 1) / (rec.time.back() - rec.time.front());
    run.frames = SensorFrames(rec, ChooseSensor(rec, sensor, path), path, pins);
    // Ground truth: labelled window from the retraction, onset from the chosen onset time.
    auto attr = [&](const char* k) {
      auto it = rec.attrs.find(k);
      return it == rec.attrs.end() ? std::nan("") : it->second;
    };
    const char* onset_key = labels == OnsetLabels::kMarker ? "marker_onset_s" : "gross_slip_onset_s";
    if (labels == OnsetLabels::kMarker && rec.attrs.count(onset_key) == 0) {
      throw InputError(fmt::format("--labels marker: dataset '{}' run {} has no hardware-style onset "
                                   "(events/marker_onset_s; datasets made before it was recorded have only the exact one)",
                                   path, idx));
    }
    const double retract = attr("retract_start_s"), onset = attr(onset_key);
    run.first_frame = 0;
    if (!std::isnan(retract)) {
      while (run.first_frame < static_cast<int>(T) && rec.time[run.first_frame] < retract) ++run.first_frame;
    }
    run.onset_frame = -1;
    if (!std::isnan(onset)) {
      for (size_t f = 0; f < T; ++f) {
        if (rec.time[f] >= onset - 1e-9) {
          run.onset_frame = static_cast<int>(f);
          // The onset frame's velocity covers both sides of the onset unless the onset
          // fell exactly on the previous frame time.
          const bool straddles = f > 0 && onset > rec.time[f - 1] + 1e-9;
          run.slip_start_frame = run.onset_frame + (straddles && !score_onset_frame ? 1 : 0);
          break;
        }
      }
    }
    out.push_back(std::move(run));
  }
  return out;
}

std::vector<LabeledRun> LoadFrames(const std::string& path, const std::vector<int>& runs,
                                   const std::string& sensor, PinSource pins) {
  auto ends_with = [&](const char* s) {
    const std::string x(s);
    return path.size() >= x.size() && path.compare(path.size() - x.size(), x.size(), x) == 0;
  };
  if (ends_with(".csv")) {
    if (!sensor.empty()) {
      throw InputError(fmt::format("--sensor '{}': '{}' is a CSV recording of one sensor; --sensor picks a sensor of "
                                   "an HDF5 dataset", sensor, path));
    }
    if (pins == PinSource::kDetected) {
      throw InputError(fmt::format("--pins detected: '{}' is a CSV recording: its pins are the only ones it has", path));
    }
    LabeledRun run;
    run.frames = ReadPinCsv(path);
    if (run.frames.size() >= 2) {
      run.frame_rate_hz = (run.frames.size() - 1) / (run.frames.back().time_s - run.frames.front().time_s);
    }
    return {std::move(run)};
  }
  return LoadDatasetRuns(path, runs, false, sensor, pins);
}

}  // namespace tactip
