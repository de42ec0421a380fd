#include "scenarios/figures/run_tables.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "sim/base/nan.h"
#include "sim/config.h"

namespace tactip {

namespace {

constexpr double kMmPerM = 1e3;
/// A rest radius below this is the image centre itself: no radial direction (px).
constexpr double kCentreRadiusPx = 1e-9;

/// A number for a CSV cell: empty when NaN, else 9 significant digits (a float exactly).
std::string Cell(double v) { return std::isnan(v) ? "" : fmt::format("{:.9g}", v); }

/// (u, v) of pin i at frame f of a (T,N,2) array.
struct Px {
  double u, v;
};
Px At(const std::vector<float>& a, size_t n, size_t f, size_t i) {
  return {a[(f * n + i) * 2], a[(f * n + i) * 2 + 1]};
}

/// |a(f) − a(g)| of pin i (px).
double Distance(const std::vector<float>& a, size_t n, size_t f, size_t g, size_t i) {
  const Px p = At(a, n, f, i), q = At(a, n, g, i);
  return std::hypot(p.u - q.u, p.v - q.v);
}

/// Mean over pins of |a(f) − a(g)| (px).
double MeanDistance(const std::vector<float>& a, size_t n, size_t f, size_t g) {
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) sum += Distance(a, n, f, g, i);
  return n == 0 ? 0.0 : sum / static_cast<double>(n);
}

/// Rest radius of pin i in the image: frame 0's distance from `c` (px).
double RestRadius(const SensorRecord& s, size_t i, const ImageCentre& c) {
  const Px p = At(s.pos_px, static_cast<size_t>(s.n_pins), 0, i);
  return std::hypot(p.u - c.u_px, p.v - c.v_px);
}

/// First frame at or after `t` (s), or -1 when none or `t` is NaN.
int FrameAtOrAfter(const RunRecord& run, double t) {
  if (std::isnan(t)) return -1;
  const auto it = std::lower_bound(run.time.begin(), run.time.end(), t);
  return it == run.time.end() ? -1 : static_cast<int>(it - run.time.begin());
}

/// A run attribute, NaN when absent.
double AttrOrNaN(const RunRecord& run, const char* key) {
  const auto it = run.attrs.find(key);
  return it == run.attrs.end() ? kNaN : it->second;
}

/// Mean inward displacement of the pins along the camera axis at frame f (m).
double MeanInward(const SensorRecord& s, size_t f) {
  const auto n = static_cast<size_t>(s.n_pins);
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) sum += s.pos_m[i * 3] - s.pos_m[(f * n + i) * 3];
  return n == 0 ? 0.0 : sum / static_cast<double>(n);
}

}  // namespace

RunEvents EventsOf(const RunRecord& run) {
  return {AttrOrNaN(run, "gross_slip_onset_s"), AttrOrNaN(run, "incipient_onset_s"), AttrOrNaN(run, "object_fall_s")};
}

std::string EventsCsv(const RunRecord& run) {
  const RunEvents e = EventsOf(run);
  std::string out = "event,time_s,frame\n";
  for (const auto& [name, t] : {std::pair{"gross_slip_onset", e.gross_slip_onset_s},
                                std::pair{"incipient_onset", e.incipient_onset_s},
                                std::pair{"object_fall", e.object_fall_s}}) {
    const int f = FrameAtOrAfter(run, t);
    out += fmt::format("{},{},{}\n", name, Cell(t), f < 0 ? "" : std::to_string(f));
  }
  return out;
}

std::vector<ShownPin> RepresentativePins(const SensorRecord& s, const ImageCentre& centre) {
  const auto n = static_cast<size_t>(s.n_pins);
  const size_t t = n == 0 ? 0 : s.pos_px.size() / (2 * n);
  // Rest radii and peak displacements, per pin.
  std::vector<double> radius(n), peak(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    radius[i] = RestRadius(s, i, centre);
    for (size_t f = 1; f < t; ++f) peak[i] = std::max(peak[i], Distance(s.pos_px, n, f, 0, i));
  }
  // Centre, mid radius, outermost, farthest moving; the first index wins ties.
  const double r_max = n == 0 ? 0.0 : *std::max_element(radius.begin(), radius.end());
  size_t mid = 0;
  for (size_t i = 0; i < n; ++i) {
    if (std::abs(radius[i] - 0.5 * r_max) < std::abs(radius[mid] - 0.5 * r_max)) mid = i;
  }
  const auto inner = static_cast<size_t>(std::min_element(radius.begin(), radius.end()) - radius.begin());
  const auto outer = static_cast<size_t>(std::max_element(radius.begin(), radius.end()) - radius.begin());
  const auto moving = static_cast<size_t>(std::max_element(peak.begin(), peak.end()) - peak.begin());
  std::vector<ShownPin> pins;
  for (const auto& [i, role] : {std::pair{inner, "centre"}, std::pair{mid, "mid radius"},
                                std::pair{outer, "outermost"}, std::pair{moving, "farthest moving"}}) {
    if (i >= n) continue;
    const auto same = std::find_if(pins.begin(), pins.end(), [&](const ShownPin& p) { return p.pin == int(i); });
    if (same == pins.end()) {
      pins.push_back({static_cast<int>(i), role});
    } else {
      same->role += std::string(" and ") + role;
    }
  }
  return pins;
}

std::string MotionCsv(const RunRecord& run, const SensorRecord& s, const std::vector<ShownPin>& pins) {
  const auto n = static_cast<size_t>(s.n_pins);
  // Header: one displacement column per representative pin.
  std::string out = "frame,time_s,mean_disp_px";
  for (const ShownPin& p : pins) out += fmt::format(",pin{}_disp_px", p.pin);
  out += ",mean_speed_px_frame,max_speed_px_frame,gross_slip,incipient\n";
  // Rows: displacement from frame 0, speed from the previous frame.
  for (size_t f = 0; f < run.frames(); ++f) {
    out += fmt::format("{},{},{}", f, Cell(run.time[f]), Cell(MeanDistance(s.pos_px, n, f, 0)));
    for (const ShownPin& p : pins) out += "," + Cell(Distance(s.pos_px, n, f, 0, static_cast<size_t>(p.pin)));
    double mean = kNaN, max = kNaN;
    if (f > 0) {
      mean = MeanDistance(s.pos_px, n, f, f - 1);
      max = 0.0;
      for (size_t i = 0; i < n; ++i) max = std::max(max, Distance(s.pos_px, n, f, f - 1, i));
    }
    out += fmt::format(",{},{},{},{}\n", Cell(mean), Cell(max), int{s.gross_slip[f]}, int{s.incipient[f]});
  }
  return out;
}

QuiverFrames ChooseQuiverFrames(const RunRecord& run, const SensorRecord& s) {
  const int t = static_cast<int>(run.frames());
  if (t < 2) throw InputError(fmt::format("run {} has {} frame(s): pin velocities need at least 2", run.index, t));
  const RunEvents e = EventsOf(run);
  QuiverFrames q;
  // The onset: gross slip, else incipient slip (either must fall inside the run).
  for (const auto& [name, time] : {std::pair{"gross-slip onset", e.gross_slip_onset_s},
                                   std::pair{"incipient onset", e.incipient_onset_s}}) {
    if (const int f = FrameAtOrAfter(run, time); f >= 0) {
      q.onset_name = name;
      q.onset_s = time;
      q.at = f;
      break;
    }
  }
  // Neither: the frame of the largest mean pin speed.
  if (q.onset_name.empty()) {
    const auto n = static_cast<size_t>(s.n_pins);
    double best = -1.0;
    for (int f = 1; f < t; ++f) {
      const double v = MeanDistance(s.pos_px, n, static_cast<size_t>(f), static_cast<size_t>(f - 1));
      if (v > best) {
        best = v;
        q.at = f;
      }
    }
    q.onset_name = "peak mean pin speed";
    q.onset_s = run.time[static_cast<size_t>(q.at)];
  }
  q.at = std::clamp(q.at, 1, t - 1);
  q.before = std::clamp(q.at - kQuiverOffsetFrames, 1, t - 1);
  q.after = std::clamp(q.at + kQuiverOffsetFrames, 1, t - 1);
  return q;
}

std::string QuiverCsv(const RunRecord& run, const SensorRecord& s, const QuiverFrames& q) {
  const auto n = static_cast<size_t>(s.n_pins);
  std::string out = "panel,frame,time_s,pin,u_px,v_px,du_px,dv_px,contact\n";
  for (const auto& [panel, frame] : {std::pair{"before", q.before}, std::pair{"at", q.at}, std::pair{"after", q.after}}) {
    const auto f = static_cast<size_t>(frame);
    for (size_t i = 0; i < n; ++i) {
      const Px p = At(s.pos_px, n, f, i), prev = At(s.pos_px, n, f - 1, i);
      out += fmt::format("{},{},{},{},{},{},{},{},{}\n", panel, f, Cell(run.time[f]), i, Cell(p.u), Cell(p.v),
                         Cell(p.u - prev.u), Cell(p.v - prev.v), int{s.pin_contact[f * n + i]});
    }
  }
  return out;
}

std::string MarkersCsv(const RunRecord& run, const SensorRecord& s) {
  if (s.external_px.empty()) throw std::logic_error("MarkersCsv: sensor '" + s.name + "' has no external markers");
  const auto n = static_cast<size_t>(s.n_pins);
  std::string out =
      "frame,time_s,internal_disp_px,external_disp_px,internal_speed_px_frame,external_speed_px_frame\n";
  for (size_t f = 0; f < run.frames(); ++f) {
    const double in_speed = f == 0 ? kNaN : MeanDistance(s.pos_px, n, f, f - 1);
    const double ex_speed = f == 0 ? kNaN : MeanDistance(s.external_px, n, f, f - 1);
    out += fmt::format("{},{},{},{},{},{}\n", f, Cell(run.time[f]), Cell(MeanDistance(s.pos_px, n, f, 0)),
                       Cell(MeanDistance(s.external_px, n, f, 0)), Cell(in_speed), Cell(ex_speed));
  }
  return out;
}

ChosenFrame DeepestPressFrame(const RunRecord& run, const SensorRecord& s) {
  // Search up to the first onset (gross or incipient), or the whole run.
  const RunEvents e = EventsOf(run);
  int end = static_cast<int>(run.frames());
  std::string reason = "deepest press of the run (no onset)";
  for (double t : {e.gross_slip_onset_s, e.incipient_onset_s}) {
    const int f = FrameAtOrAfter(run, t);
    if (f > 0 && f < end) {
      end = f;
      reason = "deepest press before the onset";
    }
  }
  ChosenFrame c;
  double best = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < end; ++f) {
    if (const double in = MeanInward(s, static_cast<size_t>(f)); in > best) {
      best = in;
      c.frame = f;
    }
  }
  c.time_s = run.time[static_cast<size_t>(c.frame)];
  c.reason = reason;
  return c;
}

int RestFrame(const SensorRecord& s) {
  const auto n = static_cast<size_t>(s.n_pins);
  const auto touch = std::find(s.pin_contact.begin(), s.pin_contact.end(), std::uint8_t{1});
  if (n == 0 || touch == s.pin_contact.end()) return 0;
  const auto first = static_cast<size_t>(touch - s.pin_contact.begin()) / n;
  return first == 0 ? 0 : static_cast<int>(first - 1);
}

std::string IndentationCsv(const SensorRecord& s, int rest_frame, int frame, const ImageCentre& centre) {
  const auto n = static_cast<size_t>(s.n_pins);
  const auto f = static_cast<size_t>(frame), f0 = static_cast<size_t>(rest_frame);
  std::string out = "pin,rest_u_px,rest_v_px,rest_radius_px,radial_disp_px,axial_in_mm,contact,normal_N\n";
  for (size_t i = 0; i < n; ++i) {
    // Radial: the image displacement along the outward direction of the rest position.
    const Px rest = At(s.pos_px, n, f0, i), now = At(s.pos_px, n, f, i);
    const double r = std::hypot(rest.u - centre.u_px, rest.v - centre.v_px);
    const double radial = r < kCentreRadiusPx ? 0.0
                                              : ((now.u - rest.u) * (rest.u - centre.u_px) +
                                                 (now.v - rest.v) * (rest.v - centre.v_px)) / r;
    const double axial_in_mm = (s.pos_m[(f0 * n + i) * 3] - s.pos_m[(f * n + i) * 3]) * kMmPerM;
    out += fmt::format("{},{},{},{},{},{},{},{}\n", i, Cell(rest.u), Cell(rest.v), Cell(r), Cell(radial),
                       Cell(axial_in_mm), int{s.pin_contact[f * n + i]}, Cell(s.normal_N[f * n + i]));
  }
  return out;
}

}  // namespace tactip
