#include "scenarios/studies/accuracy/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tactip {

namespace {

double AttrOr(const RunRecord& r, const char* key) {
  auto it = r.attrs.find(key);
  return it == r.attrs.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

// |a - b| for events: 0 when neither happened, inf when only one did.
double EventError(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return 0.0;
  if (std::isnan(a) || std::isnan(b)) return std::numeric_limits<double>::infinity();
  return std::abs(a - b);
}

}  // namespace

RunDifference CompareRuns(const RunRecord& run, const RunRecord& ref) {
  const SensorRecord& a = run.sensors.front();
  const SensorRecord& b = ref.sensors.front();
  if (a.n_pins != b.n_pins) throw std::invalid_argument("CompareRuns: the runs have different pin counts");
  RunDifference d;
  const double onset = AttrOr(run, "gross_slip_onset_s"), onset_ref = AttrOr(ref, "gross_slip_onset_s");
  d.onset_error_s = EventError(onset, onset_ref);
  d.incipient_error_s = EventError(AttrOr(run, "incipient_onset_s"), AttrOr(ref, "incipient_onset_s"));
  // Frames both runs have, up to the earlier onset (after it the runs diverge by design).
  const double until = std::min(std::isnan(onset) ? 1e300 : onset, std::isnan(onset_ref) ? 1e300 : onset_ref);
  const size_t N = static_cast<size_t>(a.n_pins);
  const size_t T = std::min(run.frames(), ref.frames());
  double sq = 0.0;
  long pin_frames = 0, contacting = 0, differ = 0;
  for (size_t f = 0; f < T && run.time[f] < until; ++f) {
    ++d.frames_compared;
    for (size_t i = 0; i < N; ++i) {
      const size_t k = f * N + i;
      const double du = a.pos_px[2 * k] - b.pos_px[2 * k], dv = a.pos_px[2 * k + 1] - b.pos_px[2 * k + 1];
      sq += du * du + dv * dv;
      ++pin_frames;
      if (!a.pin_contact[k] && !b.pin_contact[k]) continue;
      ++contacting;
      differ += (a.pin_contact[k] != b.pin_contact[k] || a.pin_slip[k] != b.pin_slip[k]) ? 1 : 0;
    }
  }
  d.traj_rms_px = pin_frames > 0 ? std::sqrt(sq / static_cast<double>(pin_frames)) : 0.0;
  d.label_disagreement = contacting > 0 ? static_cast<double>(differ) / static_cast<double>(contacting) : 0.0;
  return d;
}

}  // namespace tactip
