#include "scenarios/studies/signatures/slip_sectors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "scenarios/studies/run_signals/run_signals.h"

namespace tactip {

namespace {

constexpr std::array<char, 4> kSectors = {'E', 'W', 'S', 'N'};

// Centroid of the image positions at frame f of the pins in contact (of the valid pins if none).
std::array<double, 2> ContactCentroid(const SensorRecord& sensor, size_t f) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  for (bool contact_only : {true, false}) {
    double su = 0.0, sv = 0.0;
    int count = 0;
    for (size_t i = 0; i < n; ++i) {
      if (contact_only ? !sensor.pin_contact[f * n + i] : !sensor.valid[f * n + i]) continue;
      su += sensor.pos_px[(f * n + i) * 2];
      sv += sensor.pos_px[(f * n + i) * 2 + 1];
      ++count;
    }
    if (count > 0) return {su / count, sv / count};
  }
  return {0.0, 0.0};
}

// Each pin's sector in the image at frame f (index into kSectors; kSectors.size() for none).
std::vector<size_t> PinSectors(const SensorRecord& sensor, size_t f) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  const auto centre = ContactCentroid(sensor, f);
  std::vector<size_t> sectors(n);
  for (size_t i = 0; i < n; ++i) {
    const char sector =
        ImageSector(sensor.pos_px[(f * n + i) * 2] - centre[0], sensor.pos_px[(f * n + i) * 2 + 1] - centre[1]);
    sectors[i] = static_cast<size_t>(std::find(kSectors.begin(), kSectors.end(), sector) - kSectors.begin());
  }
  return sectors;
}

constexpr double kNever = std::numeric_limits<double>::infinity();

// The order text from each sector's first slip (kNever: none), E, W, S, N within a tie.
SectorOrder OrderByFirst(const std::array<double, kSectors.size()>& first) {
  SectorOrder out;
  std::vector<size_t> slipped;
  for (size_t k = 0; k < kSectors.size(); ++k) {
    if (first[k] != kNever) slipped.push_back(k);
  }
  std::stable_sort(slipped.begin(), slipped.end(), [&](size_t a, size_t b) { return first[a] < first[b]; });
  for (size_t j = 0; j < slipped.size(); ++j) {
    if (j > 0) out.order += first[slipped[j]] == first[slipped[j - 1]] ? '=' : '<';
    out.order += kSectors[slipped[j]];
    if (first[slipped[j]] == first[slipped.front()]) out.first = out.order;
  }
  return out;
}

constexpr size_t kNotSlipped = std::numeric_limits<size_t>::max();

// The position of `sector` among the order's '<'-separated groups (kNotSlipped: absent).
size_t SlipGroup(const std::string& order, char sector) {
  const size_t at = order.find(sector);
  if (at == std::string::npos) return kNotSlipped;
  return static_cast<size_t>(std::count(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(at), '<'));
}

}  // namespace

bool EastWestOnly(const std::string& sectors) {
  return !sectors.empty() && sectors.find_first_of("SN") == std::string::npos;
}

bool SectorOrder::EastWestTiedWithNorthSouth() const {
  return first.find_first_of("EW") != std::string::npos && first.find_first_of("SN") != std::string::npos;
}

bool SectorOrder::SouthBeforeNorth() const {
  const size_t south = SlipGroup(order, 'S');
  return south != kNotSlipped && south < SlipGroup(order, 'N');
}

bool SectorOrder::HardwareOrder() const {
  const size_t east = SlipGroup(order, 'E'), west = SlipGroup(order, 'W');
  const size_t south = SlipGroup(order, 'S'), north = SlipGroup(order, 'N');
  if (east == kNotSlipped || west == kNotSlipped || north == kNotSlipped) return false;
  return std::max(east, west) < south && south < north;
}

char ImageSector(double du_px, double dv_px) {
  if (du_px == 0.0 && dv_px == 0.0) return '-';
  if (std::abs(du_px) >= std::abs(dv_px)) return du_px > 0.0 ? 'E' : 'W';
  return dv_px > 0.0 ? 'S' : 'N';
}

std::string MostCommonSector(const SensorRecord& sensor, size_t from_frame, const std::vector<int>& pins) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  const size_t frames = n == 0 ? 0 : sensor.valid.size() / n;
  if (pins.empty() || from_frame >= frames) return "";
  const std::vector<size_t> sectors = PinSectors(sensor, from_frame);
  std::array<int, kSectors.size()> count{};
  for (int i : pins) {
    const size_t k = sectors.at(static_cast<size_t>(i));
    if (k < kSectors.size()) ++count[k];
  }
  const int most = *std::max_element(count.begin(), count.end());
  if (most == 0) return "-";  // every pin on the centroid: an alarm without a sector
  std::string out;
  for (size_t k = 0; k < kSectors.size(); ++k) {
    if (count[k] != most) continue;
    if (!out.empty()) out += '=';
    out += kSectors[k];
  }
  return out;
}

SectorOrder OrderSlipSectors(const SensorRecord& sensor, size_t from_frame, size_t end_frame) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  const size_t frames = n == 0 ? 0 : sensor.valid.size() / n;
  if (from_frame >= frames) return {};
  end_frame = std::min(end_frame, frames);
  // Each sector's first frame with a slipping pin in contact.
  std::array<double, kSectors.size()> first{kNever, kNever, kNever, kNever};
  const std::vector<size_t> sectors = PinSectors(sensor, from_frame);
  for (size_t i = 0; i < n; ++i) {
    const size_t k = sectors[i];
    if (k == kSectors.size()) continue;
    for (size_t f = from_frame; f < end_frame && static_cast<double>(f) < first[k]; ++f) {
      if (sensor.pin_contact[f * n + i] && sensor.pin_slip[f * n + i]) {
        first[k] = static_cast<double>(f);
        break;
      }
    }
  }
  return OrderByFirst(first);
}

SectorOrder OrderSlipSectorsAtSteps(const SensorRecord& sensor, size_t from_frame, double from_s, double end_s) {
  const auto n = static_cast<size_t>(sensor.n_pins);
  if (sensor.pin_first_slip_s.size() != n) {
    throw std::invalid_argument("OrderSlipSectorsAtSteps: sensor '" + sensor.name + "' has no pin_first_slip_s");
  }
  const size_t frames = n == 0 ? 0 : sensor.valid.size() / n;
  // Each sector's earliest first slip in the window (NaN, never, compares false).
  std::array<double, kSectors.size()> first{kNever, kNever, kNever, kNever};
  if (from_frame < frames) {
    const std::vector<size_t> sectors = PinSectors(sensor, from_frame);
    for (size_t i = 0; i < n; ++i) {
      const double t = sensor.pin_first_slip_s[i];
      if (sectors[i] == kSectors.size() || !(t >= from_s && t < end_s)) continue;
      first[sectors[i]] = std::min(first[sectors[i]], t);
    }
  }
  SectorOrder out = OrderByFirst(first);
  out.at_steps = true;
  return out;
}

SectorOrder OrderIncipientSectors(const SensorRecord& sensor, const IncipientWindow& window, bool by_frame) {
  if (by_frame || sensor.pin_first_slip_s.empty()) return OrderSlipSectors(sensor, window.from_frame, window.end_frame);
  return OrderSlipSectorsAtSteps(sensor, window.from_frame, window.from_s, window.end_s);
}

}  // namespace tactip
