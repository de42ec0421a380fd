#pragma once
// The contact-validation rig: the sensor fixed in the world and a flat plate on two
// servo-driven slide joints (normal x, tangential y), no gravity. Used to check the
// pin lattice against the brush model and continuum contact mechanics.

#include <string>

#include "models/skin.h"
#include "sim/sim_config.h"

namespace tactip {

/// Names of the rig's elements.
struct ContactRigNames {
  static constexpr const char* kPlate = "plate";
  static constexpr const char* kPlateGeom = "plate_face";
  static constexpr const char* kNormal = "plate_x";
  static constexpr const char* kShear = "plate_y";
  static constexpr const char* kServoNormal = "servo_plate_x";
  static constexpr const char* kServoShear = "servo_plate_y";
  static constexpr const char* kSensor = "sensor";
};

/// Everything the rig is built from. The plate face starts `gap_m` from the dome apex
/// (world x = 0 at the apex, plate on the +x side).
struct ContactRigSpec {
  SimConfig sim;
  SkinConfig skin;
  ContactConfig contact;
  double gap_m = 1e-3;        ///< initial apex-to-plate gap
  double max_depth_m = 3e-3;  ///< deepest indentation (for contact culling)
  double plate_mass_kg = 0.2; ///< moving mass of the plate carriage
  double servo_kp_N_m = 1e5;  ///< plate servo stiffness (both axes)
  /// Half-length of the plate along the shear axis. A lattice soft in shear travels tens of
  /// millimetres to gross slip (about mu P / (N k_tip)), and its slipped pins lag behind the
  /// plate by up to that travel: the plate is long enough that none of them runs off its
  /// trailing edge, which would drop its load and make the rest release early.
  double plate_half_length_m = 0.2;
};

/// MJCF text of the rig.
std::string BuildContactRig(const ContactRigSpec& spec);

}  // namespace tactip
