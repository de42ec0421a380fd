#include "scenarios/app/cli/track_command.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "detectors/pin_csv.h"
#include "scenarios/app/cli/option_checks.h"
#include "scenarios/app/cli/output_checks.h"
#include "sensors/frame_tracking.h"
#include "sim/base/files.h"
#include "sim/base/progress.h"

namespace tactip::cli {

namespace {

// Options of `tactip track`.
struct TrackArgs {
  std::string images;       // folder of PNG frames
  std::string out;          // pin CSV
  std::string counts;       // per-frame counts CSV (optional)
  double fps_hz = 100.0;    // frame rate of the recording
  double gate_px = 0.0, min_area_px = 0.0;  // 0: chosen from the first frame
};

// The per-frame counts: frame,time_s,pins_found,markers.
std::string CountsCsv(const TrackedRecording& r) {
  std::string csv = "frame,time_s,pins_found,markers\n";
  for (size_t k = 0; k < r.frames.size(); ++k) {
    csv += fmt::format("{},{},{},{}\n", k, r.frames[k].time_s, r.found[k], r.blobs[k]);
  }
  return csv;
}

// One line on the settings chosen and one on what the frames showed.
void PrintSummary(const TrackedRecording& r) {
  const FrameBlobParams& p = r.params;
  ProgressF("markers: %s on %s, threshold %.0f, areas %.0f-%.0f px (first frame: %d markers, median %.0f px), "
            "gate %.1f px\n",
            p.inverted ? "dark" : "bright", p.inverted ? "bright" : "dark", p.threshold, p.min_area_px,
            p.max_area_px, p.markers, p.median_area_px, p.gate_px);
  const int n = r.frames.front().size();
  long long found = 0;
  int all = 0, fewest = n;
  for (int f : r.found) {
    found += f;
    all += f == n ? 1 : 0;
    fewest = std::min(fewest, f);
  }
  ProgressF("pins found: all %d in %d of %zu frames (%.1f %%), at least %d in every frame; %.2f %% of pin "
            "detections\n",
            n, all, r.frames.size(), 100.0 * all / r.frames.size(), fewest,
            100.0 * static_cast<double>(found) / (static_cast<double>(n) * r.frames.size()));
}

// tactip track: every frame read and tracked before the CSV is written (atomically).
int RunTrack(const TrackArgs& a) {
  const std::vector<std::string> files = PngFramesIn(a.images, "--images");
  std::vector<NamedPath> inputs;
  for (const std::string& f : files) inputs.push_back({"--images", f});
  CheckOutputsAreNotInputs({{"--out", a.out}}, inputs);
  CheckWritableLocation(a.out);
  if (!a.counts.empty()) {
    inputs.push_back({"--out", a.out});
    CheckOutputsAreNotInputs({{"--counts", a.counts}}, inputs);
    CheckWritableLocation(a.counts);
  }
  TrackSettings settings;
  settings.fps_hz = a.fps_hz;
  if (a.gate_px > 0.0) settings.gate_px = a.gate_px;
  if (a.min_area_px > 0.0) settings.min_area_px = a.min_area_px;
  const TrackedRecording r = TrackPngFrames(files, settings);
  WritePinCsv(a.out, r.frames);
  if (!a.counts.empty()) WriteFileAtomic(a.counts, CountsCsv(r));
  PrintSummary(r);
  ProgressF("tracked %d pins through %zu frames; wrote %s%s%s\n", r.frames.front().size(), r.frames.size(),
            a.out.c_str(), a.counts.empty() ? "" : " and ", a.counts.c_str());
  return 0;
}

}  // namespace

std::function<int()> AddTrackCommand(CLI::App& app) {
  auto a = std::make_shared<TrackArgs>();
  auto* c = app.add_subcommand(
      "track",
      "Track the pins of a real TacTip recording (a folder of PNG frames) with the simulator's blob pipeline and "
      "write the pin CSV that 'tactip detect' reads.");
  c->add_option("--images", a->images,
                "Folder of camera frames (*.png, greyscale or colour, one size), taken in file-name order.")
      ->required()
      ->check(NonEmpty("a folder of PNG frames"));
  c->add_option("--out", a->out, "Output pin CSV (frame,time_s,pin,x_px,y_px,valid); written atomically.")
      ->required()
      ->check(NonEmpty("a file name"));
  c->add_option("--fps", a->fps_hz, "Frame rate of the recording, Hz: frame k is at k / fps s (default 100).")
      ->check(NumberAbove(0.0));
  c->add_option("--counts", a->counts, "Also write frame,time_s,pins_found,markers per frame to this CSV.")
      ->check(NonEmpty("a file name"));
  c->add_option("--gate-px", a->gate_px,
                "Farthest a pin may move between frames, px (default: half the first frame's median marker spacing).")
      ->check(NumberAbove(0.0));
  c->add_option("--min-blob-area-px", a->min_area_px,
                "Smallest marker kept, px^2 (default: a fifth of the first frame's median marker area, at least 3).")
      ->check(NumberWithin(1.0, 1e6));
  return [a, c]() -> int { return *c ? RunTrack(*a) : -1; };
}

}  // namespace tactip::cli
