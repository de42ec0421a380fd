#include "scenarios/app/cli/track_command.h"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

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
  double fps_hz = 100.0;    // frame rate of the recording
  TactileImageConfig blobs; // detector and gate settings (the images section's defaults)
};

// tactip track: every frame read and tracked before the CSV is written (atomically).
int RunTrack(const TrackArgs& a) {
  const std::vector<std::string> files = PngFramesIn(a.images, "--images");
  std::vector<NamedPath> inputs;
  for (const std::string& f : files) inputs.push_back({"--images", f});
  CheckOutputsAreNotInputs({{"--out", a.out}}, inputs);
  CheckWritableLocation(a.out);
  const std::vector<PinFrame> frames = TrackPngFrames(files, a.fps_hz, a.blobs);
  WritePinCsv(a.out, frames);
  long long misses = 0;
  for (const PinFrame& f : frames) {
    for (unsigned char v : f.valid) misses += v ? 0 : 1;
  }
  ProgressF("tracked %d pins through %zu frames (%lld misses); wrote %s\n", frames.front().size(),
               frames.size(), misses, a.out.c_str());
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
  c->add_option("--gate-px", a->blobs.gate_px,
                "Farthest a pin may move between frames, px (default 10; below half the marker spacing).")
      ->check(NumberAbove(0.0));
  c->add_option("--min-blob-area-px", a->blobs.min_blob_area_px,
                "Smallest blob kept, px^2 (default 12; drops noise specks).")
      ->check(NumberWithin(1.0, 1e6));
  return [a, c]() -> int { return *c ? RunTrack(*a) : -1; };
}

}  // namespace tactip::cli
