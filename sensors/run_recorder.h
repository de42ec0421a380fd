#pragma once
// The recorder: builds a run's record frame by frame from what its parts measured (each
// sensor's reading, the object's height, the actuators' controls), in the dataset's layout,
// apart from the physics and the sensors that produce it.

#include <cstdint>
#include <string>
#include <vector>

#include "sensors/dataset.h"
#include "sensors/image_pipeline.h"
#include "sensors/tactile_sensor.h"

namespace tactip {

/// One sensor group of a record: its name and pin count.
struct SensorGroup {
  std::string name;
  int n_pins = 0;
};

/// Appends a run's frames to a RunRecord. The record must outlive the recorder.
class RunRecorder {
 public:
  /// Starts `rec` afresh for run `index`: one group per sensor of `sensors` (in order), the
  /// `actuators` whose controls each frame records; room for `expected_frames`.
  RunRecorder(RunRecord& rec, int index, const std::vector<SensorGroup>& sensors,
              const std::vector<std::string>& actuators, size_t expected_frames);

  /// One frame at `time_s`: each sensor's reading (one per group, in order), the gross-slip
  /// label (the object's, the same in every group), the object's height and the controls in
  /// actuator order. Throws std::logic_error, recording nothing, if a reading or the controls do
  /// not fit.
  void Frame(double time_s, const std::vector<const SensorReading*>& readings, std::uint8_t gross_slip,
             double object_height_m, const std::vector<double>& controls);

  /// Labels every frame from index `first_frame` on as gross slip, in every group: the onset
  /// found at a later step is dated back to the step of `first_frame` (RailRun::TrackOnset).
  void LabelGrossFrom(size_t first_frame);

  /// Appends the image pipeline's output of the frame just recorded by Frame() to sensor
  /// group `sensor` (frames `width` x `height` px). Call it for every frame of a run or for
  /// none. Throws std::logic_error, recording nothing, if the sensor index, the pin count or
  /// the frame size does not fit.
  void Images(size_t sensor, const ImageReading& reading, int width, int height);

  /// Sets sensor group `sensor`'s per-pin first-slip times (SensorRecord::pin_first_slip_s).
  /// Throws std::logic_error, recording nothing, if the sensor index or the pin count does
  /// not fit.
  void FirstSlips(size_t sensor, const std::vector<double>& first_slip_s);

 private:
  static void Append(const SensorReading& reading, std::uint8_t gross_slip, SensorRecord& group);

  RunRecord& rec_;
};

}  // namespace tactip
