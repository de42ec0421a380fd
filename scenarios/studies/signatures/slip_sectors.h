#pragma once
// Where on the sensor incipient slip starts: each pin's compass sector in the image (east
// = image u right, west = u left, south = v down = towards gravity, north = v up) and the
// order in which the sectors get their first slipping pin.

#include <string>
#include <vector>

#include "sensors/dataset.h"

namespace tactip {

struct IncipientWindow;  // scenarios/studies/run_signals/run_signals.h

/// True when `sectors` ("E", "E=W", "S=W", ...) is not empty and holds east and/or west only.
bool EastWestOnly(const std::string& sectors);

/// Order of the sectors by their first ground-truth slipping pin.
struct SectorOrder {
  /// The sectors whose first slip is the earliest, joined by '=' ("E", "E=W"); "" when no
  /// pin slipped.
  std::string first;
  /// Every sector that slipped, earliest first; '<' separates frames (physics steps when
  /// `at_steps`), '=' joins sectors whose first slip shares one ("E=W<S<N"). Sectors without
  /// a slipping pin are left out.
  std::string order;
  /// True when ordered by the pins' first slipping physics steps (labels/pin_first_slip_s),
  /// false when by the camera frames' labels.
  bool at_steps = false;
  /// True when `first` holds east and/or west only (the hardware's finding).
  bool EastWestFirst() const { return EastWestOnly(first); }
  /// True when `first` holds east or west together with south or north: they started to
  /// slip in the same frame (or step), so it cannot order them.
  bool EastWestTiedWithNorthSouth() const;
  /// True when south slipped in an earlier frame (or step) than north, or north never did.
  bool SouthBeforeNorth() const;
  /// True when all four sectors slipped in the hardware's order: east and west (in either
  /// order) before south, south before north, each '<' a later frame (or step).
  bool HardwareOrder() const;
};

/// Sector ('E', 'W', 'S' or 'N') of image offset (du, dv) from the contact centre: the
/// dominant axis, u on a tie; '-' for a zero offset.
char ImageSector(double du_px, double dv_px);

/// Orders the sectors by each one's first frame in [from_frame, end_frame) with a pin in
/// contact and labelled slipping. A pin's sector is taken from its image position at
/// from_frame relative to the centroid of the pins in contact then (of all valid pins if
/// none is).
SectorOrder OrderSlipSectors(const SensorRecord& sensor, size_t from_frame, size_t end_frame);

/// The same at step resolution: each sector's earliest labels/pin_first_slip_s in
/// [from_s, end_s), sectors from the pins' image positions at from_frame as above. Needs the
/// sensor's pin_first_slip_s (std::invalid_argument without it).
SectorOrder OrderSlipSectorsAtSteps(const SensorRecord& sensor, size_t from_frame, double from_s, double end_s);

/// The sector(s) holding the most of `pins` (pin indices), each pin's sector from its image
/// position at from_frame as above; a tie joins them by '=' in E, W, S, N order ("E",
/// "E=S"); "-" when every pin lies on the centroid (no sector); "" for no pins. What a
/// camera-side observer calls the first-moving sector when `pins` is the detector's slipping
/// set at its first alarm.
std::string MostCommonSector(const SensorRecord& sensor, size_t from_frame, const std::vector<int>& pins);

/// The sectors of `sensor`'s recording in a run's incipient window (IncipientWindowOf): at
/// step resolution where the sensor has pin_first_slip_s and `by_frame` is false, else by
/// frame.
SectorOrder OrderIncipientSectors(const SensorRecord& sensor, const IncipientWindow& window, bool by_frame);

}  // namespace tactip
