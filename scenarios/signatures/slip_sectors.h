#pragma once
// Where on the sensor incipient slip starts: each pin's compass sector in the image (east
// = image u right, west = u left, south = v down = towards gravity, north = v up) and the
// order in which the sectors get their first slipping pin.

#include <string>

#include "sensors/dataset.h"

namespace tactip {

/// Order of the sectors by their first ground-truth slipping pin.
struct SectorOrder {
  /// The sectors whose first slip is the earliest, joined by '=' ("E", "E=W"); "" when no
  /// pin slipped.
  std::string first;
  /// Every sector that slipped, earliest first; '<' separates frames, '=' joins sectors
  /// whose first slip shares a frame ("E=W<S<N"). Sectors without a slipping pin are left out.
  std::string order;
  /// True when `first` holds east and/or west only (the hardware's finding).
  bool EastWestFirst() const;
  /// True when `first` holds east or west together with south or north: they started to
  /// slip in the same frame, so the frames cannot order them.
  bool EastWestTiedWithNorthSouth() const;
};

/// Sector ('E', 'W', 'S' or 'N') of image offset (du, dv) from the contact centre: the
/// dominant axis, u on a tie; '-' for a zero offset.
char ImageSector(double du_px, double dv_px);

/// Orders the sectors by each one's first frame in [from_frame, end_frame) with a pin in
/// contact and labelled slipping. A pin's sector is taken from its image position at
/// from_frame relative to the centroid of the pins in contact then (of all valid pins if
/// none is).
SectorOrder OrderSlipSectors(const SensorRecord& sensor, size_t from_frame, size_t end_frame);

}  // namespace tactip
