#pragma once
// A stored run replayed in the viewer: re-simulated from the file's scenario, config and
// seed (the simulation is deterministic, so this is the run that was stored), with the
// stored pin labels shown and the stored pin positions compared with the re-simulated ones.

#include <string>

#include "scenarios/app/viewer/rail_view_source.h"
#include "scenarios/app/viewer/stored_run.h"

namespace tactip {

/// Run `index` of the dataset `path`, re-simulated as it steps. Its pins are coloured by
/// the stored labels of the stored frame nearest the simulated time; each frame the
/// re-simulation records is compared with the stored one.
class ReplayViewSource : public RailViewSource {
 public:
  /// Reads the run and its config and sets the re-simulation up. Throws InputError in one
  /// line for a file or run that does not exist or cannot be re-simulated (see
  /// ReadStoredRun; also when its pin count is not what its config builds).
  ReplayViewSource(const std::string& path, int index);

  /// One step of the re-simulation, comparing the frame it recorded, if any.
  bool Step() override;
  /// Stick green, slip red, no contact grey, from the stored labels.
  std::vector<GeomColour> Colours() const override;
  /// The replayed run and the largest difference so far (DifferenceReport).
  std::string Status() const override;

  /// The largest |stored - re-simulated| image coordinate of any pin in the frames compared
  /// so far (px; 0 when the replay is exact).
  double max_pos_px_difference() const { return max_difference_px_; }
  /// Frames compared so far.
  size_t frames_compared() const { return compared_; }
  /// "largest pos_px difference from the stored run: D px over F frames" (and the frame
  /// counts when the re-simulation ended with another count than the file's).
  std::string DifferenceReport() const;
  /// Time of the stored run's last frame (s).
  double stored_end_s() const { return stored_.record.time.back(); }
  const StoredRun& stored() const { return stored_; }

 private:
  explicit ReplayViewSource(StoredRun&& stored);
  void CompareNewFrames();
  size_t NearestStoredFrame() const;

  const StoredRun stored_;
  const SensorRecord* stored_sensor_ = nullptr;  // the shown sensor's recording in stored_
  double max_difference_px_ = 0.0;
  size_t compared_ = 0;  // frames compared
};

}  // namespace tactip
