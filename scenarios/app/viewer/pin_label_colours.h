#pragma once
// The colour of each pin in the viewer from its contact labels: stick green, slip red, no
// contact grey.

#include <cstdint>
#include <vector>

#include "sim/render_types.h"

namespace tactip {

/// One colour per pin that has a contact geom (`pin_geom[i]` >= 0; culled pins, -1, have
/// none to colour): PinColours::kSlip when `slip[i]`, else kStick when `contact[i]`, else
/// kNoContact. `contact` and `slip` hold one label per pin.
std::vector<GeomColour> PinLabelColours(const std::vector<int>& pin_geom, const std::uint8_t* contact,
                                        const std::uint8_t* slip);

}  // namespace tactip
