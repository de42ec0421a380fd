#include "scenarios/app/viewer/pin_label_colours.h"

#include <cstddef>

namespace tactip {

std::vector<GeomColour> PinLabelColours(const std::vector<int>& pin_geom, const std::uint8_t* contact,
                                        const std::uint8_t* slip) {
  std::vector<GeomColour> colours;
  colours.reserve(pin_geom.size());
  for (std::size_t i = 0; i < pin_geom.size(); ++i) {
    if (pin_geom[i] < 0) continue;
    const Rgba& rgba = slip[i] ? PinColours::kSlip : (contact[i] ? PinColours::kStick : PinColours::kNoContact);
    colours.push_back({pin_geom[i], rgba});
  }
  return colours;
}

}  // namespace tactip
