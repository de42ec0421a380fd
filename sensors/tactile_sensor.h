#pragma once
// A tactile sensor in a running scene: at every step that needs it, it reads its pins'
// contacts and labels them (no contact / stick / slip); at each camera frame it turns its
// pins into what its camera sees (a PinFrame, with noise and dropouts), its external
// markers and the ground truth (true positions, forces, labels), appended to a record.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "detectors/pin_frame.h"
#include "models/skin.h"
#include "sensors/camera.h"
#include "sensors/gel_field.h"
#include "sensors/labels.h"
#include "sensors/pin_noise.h"
#include "sensors/sensor_frame.h"
#include "sim/simulation.h"

namespace tactip {

/// Element ids of one sensor's parts in a compiled scene.
struct TactileSensorIds {
  int body = -1;                    ///< the sensor body (its frame is the sensor frame)
  std::vector<int> pin_site;        ///< per pin: the inner end, the marker the camera sees
  std::vector<int> pin_outer_site;  ///< per pin: the outer contact point, or -1 (none)
  std::vector<int> pin_geom;        ///< per pin: the contact geom, or -1 (culled: cannot touch)
  std::vector<int> slot_of_geom;    ///< geom id -> pin index, or -1
  std::vector<int> pin_dome_spring; ///< per pin: its gel spring's tendon (skin.normal_spring = dome), or -1

  /// Looks the sensor's elements up by name (body `body_name`, pins named by `names`);
  /// `outer[i]`: pin i carries an outer site. Throws ModelError naming a missing element.
  static TactileSensorIds Find(const CompiledModel& model, const std::string& body_name, int n_pins,
                               const std::vector<bool>& outer, const SkinNames& names = {});
};

/// What one sensor is, besides its MJCF part: cameras, noise, labelling.
struct TactileSensorSpec {
  std::string name = "tactip";       ///< the sensor's name (its group in a dataset)
  CameraConfig camera;               ///< the internal camera and its tracker noise
  ExternalCameraConfig external;     ///< the external camera (records when enabled)
  LabelConfig labels;                ///< stick/slip labelling
  double marker_rock_m_N = 0.0;      ///< inner marker moves by -this * tangential contact force (ridge pivot)
  GelField gel_field;                ///< the gel's lateral flow of the markers (empty: none)
  double apex_x_m = 0.0;             ///< dome apex in the sensor frame (m)
};

/// What one sensor measured at one camera frame, as a dataset stores it: one frame of each
/// per-pin array of a SensorRecord (N pins; positions in the sensor frame).
struct SensorReading {
  std::vector<float> pos_m;                          ///< (N,3) inner markers, m
  std::vector<float> pos_px;                         ///< (N,2) reported image positions (noise, dropouts)
  std::vector<std::uint8_t> valid;                   ///< (N) detected in this frame
  std::vector<float> external_m, external_px;        ///< (N,3), (N,2) outer contact points; empty without the external camera
  std::vector<float> normal_N;                       ///< (N) contact normal force
  std::vector<float> tangential_N;                   ///< (N,2) contact tangential force along sensor y, z
  std::vector<std::uint8_t> pin_contact, pin_slip;   ///< (N) ground-truth labels
  std::uint8_t incipient = 0;                        ///< partial slip: some contacting pins slide, others stick
};

/// One tactile sensor of a run. Not thread-safe; one per run.
class TactileSensor {
 public:
  /// `noise_seed` and `external_seed` seed the two cameras' noise streams.
  TactileSensor(const TactileSensorSpec& spec, const TactileSensorIds& ids, std::uint64_t noise_seed,
                std::uint64_t external_seed);

  /// Remembers the markers' rest positions (call once, at the initial state).
  void Rest(const Simulation& sim);
  /// Reads the pins' contacts at the current step and labels them.
  void ReadContacts(Simulation& sim);
  /// One camera frame of the current state (contacts as last read): measures positions,
  /// forces and labels (reading(); not the gross-slip label, which the run decides) and
  /// returns the frame the camera delivers, time-stamped `time_s`.
  const PinFrame& Capture(const Simulation& sim, double time_s);

  const std::string& name() const { return spec_.name; }
  int n_pins() const { return n_; }
  const TactileSensorIds& ids() const { return ids_; }
  /// This step's contacts and labels (after ReadContacts).
  const std::vector<GeomContact>& contacts() const { return contacts_; }
  const std::vector<PinContactSample>& samples() const { return samples_; }
  const std::vector<std::uint8_t>& pin_contact() const { return pin_contact_; }
  const std::vector<std::uint8_t>& pin_slip() const { return pin_slip_; }
  const FrameLabels& labels() const { return labels_; }
  /// The last frame's: sensor pose, noise-free image positions (N x 2), largest image motion
  /// per metre of pin motion, per-pin marker displacement from rest (m) and normal force (N).
  const SensorPose& pose() const { return pose_; }
  const std::vector<float>& clean_px() const { return clean_px_; }
  double image_gain_px_m() const { return image_gain_px_m_; }
  const std::vector<double>& marker_shift_m() const { return marker_shift_m_; }
  const std::vector<double>& normal_N() const { return normal_N_; }
  /// The last frame as the camera delivered it, and everything measured with it.
  const PinFrame& frame() const { return frame_; }
  const SensorReading& reading() const { return reading_; }

 private:
  void CapturePins(const Simulation& sim);
  void MoveMarkersWithGel(const Simulation& sim);
  /// How far pin i's gel column is compressed: its dome spring's shortening, or else its
  /// marker's inward displacement along the sensor axis.
  double ColumnCompression(const Simulation& sim, int i) const;
  void CaptureExternal(const Simulation& sim);
  void CaptureContacts();
  void FillFrame(double time_s);

  const TactileSensorSpec spec_;
  const TactileSensorIds ids_;
  const int n_;
  PinholeCamera camera_;
  const ExternalCamera ext_camera_;
  DetectionNoise noise_, ext_noise_;

  // Per step: contacts and labels.
  std::vector<GeomContact> contacts_;
  std::vector<std::array<double, 3>> tangential_;  // world frame
  std::vector<PinContactSample> samples_;
  std::vector<std::uint8_t> pin_contact_, pin_slip_;
  FrameLabels labels_;

  // Per frame: pose, image positions and detections.
  SensorPose pose_;
  std::vector<std::array<double, 3>> rest_marker_m_;
  std::vector<double> rest_dome_spring_m_;  ///< per pin: its dome spring's length at rest (0 without one)
  std::vector<std::array<double, 3>> marker_m_, gel_shift_m_;
  std::vector<double> indentation_m_;
  std::vector<float> px_, prev_px_, ext_px_, prev_ext_px_, clean_px_;
  std::vector<std::uint8_t> valid_, ext_valid_;
  double image_gain_px_m_ = 0.0;
  std::vector<double> marker_shift_m_, normal_N_;
  PinFrame frame_;
  SensorReading reading_;
};

}  // namespace tactip
