#pragma once
// What a rendered view of a scene is made of: colours, the camera, per-frame options and
// the RGB image that comes out. No OpenGL or windowing here.

#include <array>
#include <cstdint>
#include <vector>

namespace tactip {

/// A colour: red, green, blue, alpha, each in [0, 1].
using Rgba = std::array<float, 4>;

/// The colours of pins in the viewer, by contact state.
struct PinColours {
  static constexpr Rgba kStick{0.1f, 0.8f, 0.2f, 1.0f};      ///< in contact, not slipping: green
  static constexpr Rgba kSlip{0.9f, 0.1f, 0.1f, 1.0f};       ///< in contact, slipping: red
  static constexpr Rgba kNoContact{0.5f, 0.5f, 0.5f, 1.0f};  ///< not in contact: grey
};

/// A colour that replaces one geom's model colour in a rendered frame.
struct GeomColour {
  int geom = -1;  ///< geom id in the model
  Rgba rgba{};    ///< its colour in this frame
};

/// Where the camera looks from. A free camera: mouse orbit and zoom change it.
struct CameraView {
  /// Bodies whose mean position the camera looks at, followed as they move (empty: the
  /// centre of the model's extent).
  std::vector<int> look_at_bodies;
  double distance_m = 0.0;      ///< from the look-at point (0: 1.5 x the model's extent)
  double azimuth_deg = 90.0;    ///< about world z; 90 looks along +y
  double elevation_deg = -20.0; ///< negative: from above
};

/// What a frame shows beyond the model and its state.
struct RenderOptions {
  std::vector<GeomColour> colours;  ///< per-geom colour overrides (others keep the model's)
  std::vector<int> hidden_geoms;    ///< geom ids left out of the frame
  bool contact_forces = false;      ///< arrows for the contact forces (MuJoCo's mjVIS_CONTACTFORCE)
  double force_scale_m_N = 0.0;     ///< arrow length per newton (0: the model's visual setting)
};

/// An 8-bit RGB image, rows from top to bottom, 3 bytes per pixel.
struct RgbImage {
  int width = 0;                  ///< pixels
  int height = 0;                 ///< pixels
  std::vector<std::uint8_t> rgb;  ///< width * height * 3 bytes

  /// The pixel in column x, row y (0: top row).
  std::array<std::uint8_t, 3> At(int x, int y) const {
    const auto i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

}  // namespace tactip
