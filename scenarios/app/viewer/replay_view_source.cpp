#include "scenarios/app/viewer/replay_view_source.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "scenarios/app/viewer/pin_label_colours.h"

namespace tactip {

ReplayViewSource::ReplayViewSource(const std::string& path, int index) : ReplayViewSource(ReadStoredRun(path, index)) {}

ReplayViewSource::ReplayViewSource(StoredRun&& stored)
    : RailViewSource(stored.config, stored.record.index, stored.header.seed), stored_(std::move(stored)) {
  const SensorRecord* kept = stored_.record.FindSensor(sensor().name());
  if (kept == nullptr) {
    throw InputError(fmt::format("--replay {}: run {} has no sensor '{}' (its sensors: {})", stored_.path,
                                 stored_.record.index, sensor().name(), SensorNames(stored_.record)));
  }
  if (kept->n_pins != sensor().n_pins()) {
    throw InputError(fmt::format("--replay {}: run {} stores {} pins, but its config builds {}", stored_.path,
                                 stored_.record.index, kept->n_pins, sensor().n_pins()));
  }
  stored_sensor_ = kept;
}

bool ReplayViewSource::Step() {
  const bool stepped = RailViewSource::Step();
  CompareNewFrames();
  return stepped;
}

void ReplayViewSource::CompareNewFrames() {
  // Frame by frame, as far as both have frames.
  const size_t per_frame = 2 * static_cast<size_t>(stored_sensor_->n_pins);
  const size_t frames = std::min(record().frames(), stored_.record.frames());
  const std::vector<float>& resim = record().FindSensor(sensor().name())->pos_px;
  const std::vector<float>& kept = stored_sensor_->pos_px;
  for (size_t i = compared_ * per_frame; i < frames * per_frame; ++i) {
    max_difference_px_ = std::max(max_difference_px_, std::abs(static_cast<double>(kept[i]) - resim[i]));
  }
  compared_ = std::max(compared_, frames);
}

size_t ReplayViewSource::NearestStoredFrame() const {
  const std::vector<double>& t = stored_.record.time;
  const auto after = std::lower_bound(t.begin(), t.end(), time());
  if (after == t.begin()) return 0;
  if (after == t.end()) return t.size() - 1;
  const auto before = after - 1;
  return static_cast<size_t>((time() - *before <= *after - time() ? before : after) - t.begin());
}

std::vector<GeomColour> ReplayViewSource::Colours() const {
  const size_t at = NearestStoredFrame() * static_cast<size_t>(stored_sensor_->n_pins);
  return PinLabelColours(sensor().ids().pin_geom, stored_sensor_->pin_contact.data() + at,
                         stored_sensor_->pin_slip.data() + at);
}

std::string ReplayViewSource::DifferenceReport() const {
  std::string report = fmt::format("largest pos_px difference from the stored run: {:g} px over {} frames",
                                   max_difference_px_, compared_);
  if (finished() && record().frames() != stored_.record.frames()) {
    report += fmt::format(" (the file has {} frames, the re-simulation {})", stored_.record.frames(), record().frames());
  }
  return report;
}

std::string ReplayViewSource::Status() const {
  return fmt::format("replay of run {} of {}: {}", index(), stored_.path, DifferenceReport());
}

}  // namespace tactip
