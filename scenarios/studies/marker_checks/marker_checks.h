#pragma once
// The flat-press marker check: the skin pressed onto a flat plate at several depths, the
// markers seen through the internal camera, and their outward motion compared with a real
// 127-pin TacTip's (../shared/spec/real-sensor.md section 1). Run by `tactip validate
// markers` and by the tests.

#include <string>
#include <vector>

#include "models/contact_rig.h"
#include "sensors/camera.h"

namespace tactip {

/// A real TacTip's flat-press marker field at one depth: mean outward radial displacement
/// in thousandths of the pattern radius (the outer ring's mean image radius).
struct RealFlatPress {
  double depth_mm;
  double inner_per_mille;  ///< rings 1-3
  double outer_per_mille;  ///< the outermost ring
  double factor_allowed;   ///< the simulated figures must lie within this factor
};

/// The real figures: 91 binarised 640x480 frames of a 127-pin TacTip pressed onto a flat
/// stimulus (real-sensor.md section 1); within a factor 2 at 1 mm, 1.5 deeper.
const std::vector<RealFlatPress>& RealFlatPressFigures();

/// Settings of the flat-press marker check.
struct FlatPressOptions {
  ContactRigSpec rig;     ///< skin, contact, solver (the plate presses the dome's apex)
  CameraConfig camera;    ///< the internal camera (its noise and dropouts are switched off)
};

/// The simulated field at one depth beside the real one.
struct FlatPressRow {
  RealFlatPress real;
  double inner_px = 0.0, outer_px = 0.0;                ///< mean outward displacement, px
  double inner_per_mille = 0.0, outer_per_mille = 0.0;  ///< the same over the pattern radius
  int peak_ring = 0;              ///< ring (1..) with the largest mean outward displacement
  double outer_over_peak = 0.0;   ///< outer ring's displacement over the peak ring's
  double outward_fraction = 0.0;  ///< share of the pins (all but the centre) that move outward
  int pins_in_contact = 0;
  double inner_factor = 0.0, outer_factor = 0.0;  ///< max(sim/real, real/sim); inf if either is <= 0
  bool ok = false;                ///< both factors within the allowed one
};

/// Result of the check.
struct FlatPressCheck {
  double pattern_radius_px = 0.0;  ///< outer ring's mean image radius at rest
  std::vector<FlatPressRow> rows;  ///< one per real depth
  bool ok = false;                 ///< every row within its factor
};

/// Presses the configured skin onto the rig's plate at each real depth (a fresh rig per
/// depth) and measures the markers in the camera's image. Throws SimulationError if no pin
/// touches the plate.
FlatPressCheck RunFlatPressCheck(const FlatPressOptions& opts);

/// Text report: a table of simulated beside real figures and the verdict.
std::string FormatFlatPressCheck(const FlatPressCheck& c, const std::string& skin_note);

}  // namespace tactip
