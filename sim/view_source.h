#pragma once
// What the viewer shows: a simulation that advances one physics step at a time, with the
// colour of each pin now. No windowing here.

#include <string>
#include <vector>

#include "sim/render_types.h"
#include "sim/simulation.h"

namespace tactip {

/// A steppable scene the viewer pulls frames from.
struct ViewSource {
  /// Advances one physics step; false when the run has finished (nothing was advanced).
  virtual bool Step() = 0;
  /// The simulation whose state is shown.
  virtual const Simulation& sim() const = 0;
  /// Colour overrides for the current state (the pins: stick, slip, no contact).
  virtual std::vector<GeomColour> Colours() const = 0;
  /// Simulated time in seconds.
  virtual double time() const = 0;
  /// Where the camera looks when the viewer opens (default: the whole model).
  virtual CameraView Camera() const { return {}; }
  /// Length of the contact force arrows per newton (0: the model's visual setting).
  virtual double force_scale_m_N() const { return 0.0; }
  /// One line about what is shown now, under the playback status and in the window title
  /// (empty: none).
  virtual std::string Status() const { return {}; }
  virtual ~ViewSource() = default;
};

}  // namespace tactip
