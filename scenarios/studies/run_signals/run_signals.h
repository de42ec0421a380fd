#pragma once
// Signals of one recorded run that several reports read: event attributes, frame lookup,
// pin velocities in the image and the mean pin speed (px/frame) with and without a
// moving average. MuJoCo-free: they read RunRecord / SensorRecord only.

#include <array>
#include <cstddef>
#include <optional>

#include "sensors/dataset.h"

namespace tactip {

/// Run attribute `key` (an event time in s, a speed, ...); NaN when the run lacks it.
double RunAttr(const RunRecord& run, const char* key);

/// Index of the first frame at or after time `t_s` (run.frames() if none).
size_t FrameAt(const RunRecord& run, double t_s);

/// A run's incipient window: from the retraction start to the gross-slip onset (the fall
/// without one). The reports that read partial slip all use it.
struct IncipientWindow {
  double from_s = 0.0;     ///< retraction start (the first frame's time without one)
  double end_s = 0.0;      ///< gross-slip onset, else the fall; +infinity without either
  size_t from_frame = 0;   ///< first frame at or after the retraction start (0 without one)
  size_t end_frame = 0;    ///< first frame at or after end_s (run.frames() without it)
};
IncipientWindow IncipientWindowOf(const RunRecord& run);

/// Image velocity (du, dv) of pin `pin` from frame f-1 to frame f, px/frame; nullopt when f
/// is 0 or the pin was missed (valid = 0) in either frame.
std::optional<std::array<double, 2>> PinVelocityPx(const SensorRecord& sensor, size_t f, size_t pin);

/// Moving average of pin `pin`'s velocity vector over the `window` frames ending at f (the
/// hardware detector's W; averaging vectors, not speeds), px/frame; frames without a
/// velocity are left out of the average. nullopt when none of them has one.
std::optional<std::array<double, 2>> SmoothedPinVelocityPx(const SensorRecord& sensor, size_t f, size_t pin,
                                                           int window);

/// Mean over the pins of |smoothed velocity| at frame f (window 1 = unsmoothed), px/frame;
/// NaN when no pin has a velocity there.
double MeanPinSpeedPx(const SensorRecord& sensor, size_t f, int window = 1);

/// Peak of MeanPinSpeedPx(window) over the frames from the first at or after `from_s` (at
/// least frame 1) to the first at or after from_s + span_s, px/frame; 0 when none has a
/// speed.
double PeakMeanPinSpeedPx(const RunRecord& run, const SensorRecord& sensor, double from_s, double span_s,
                          int window = 1);

}  // namespace tactip
