#include "scenarios/studies/marker_checks/marker_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "scenarios/studies/contact_checks/pressed_rig.h"
#include "sensors/tactile_sensor.h"

namespace tactip {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Image positions (N x 2, px) of the markers at rest and after the press.
struct PressImages {
  std::vector<float> rest_px, pressed_px;
  int pins_in_contact = 0;
};

PressImages PressAndCapture(const FlatPressOptions& opts, double depth_m) {
  ContactRigSpec spec = opts.rig;
  spec.max_depth_m = depth_m;
  PressedRig rig(spec, depth_m);
  // The sensor sees its markers through a noise-free camera.
  TactileSensorSpec sensor_spec;
  sensor_spec.camera = opts.camera;
  sensor_spec.camera.pixel_noise_px = 0.0;
  sensor_spec.camera.noise_model = "independent";
  sensor_spec.camera.dropout_prob = 0.0;
  sensor_spec.gel_field = GelField::Build(spec.skin, rig.lattice);
  sensor_spec.apex_x_m = spec.skin.OuterRadiusMm() * 1e-3;
  const std::vector<bool> outer(static_cast<size_t>(rig.n), true);
  TactileSensor sensor(sensor_spec, TactileSensorIds::Find(rig.model(), ContactRigNames::kSensor, rig.n, outer), 1, 2);
  rig.sim().Forward();
  sensor.Rest(rig.sim());
  sensor.ReadContacts(rig.sim());
  PressImages out;
  sensor.Capture(rig.sim(), 0.0);
  out.rest_px = sensor.clean_px();
  rig.Press();
  sensor.ReadContacts(rig.sim());
  sensor.Capture(rig.sim(), rig.t);
  out.pressed_px = sensor.clean_px();
  out.pins_in_contact = sensor.labels().n_contact;
  return out;
}

double Factor(double sim, double real) {
  if (!(sim > 0.0) || !(real > 0.0)) return kInf;
  return std::max(sim / real, real / sim);
}

// Mean outward radial displacement per ring, and the share of pins moving outward.
FlatPressRow MeasureRow(const PinLattice& lattice, const PressImages& im, const CameraConfig& cam, double radius_px,
                        const RealFlatPress& real) {
  std::map<int, std::pair<double, int>> ring_sum;
  int outward = 0, moved = 0;
  for (size_t i = 0; i < lattice.size(); ++i) {
    const int ring = lattice.pins[i].ring;
    if (ring == 0) continue;
    const double x0 = im.rest_px[2 * i] - cam.cx_px, y0 = im.rest_px[2 * i + 1] - cam.cy_px;
    const double r0 = std::hypot(x0, y0);
    const double dr = ((im.pressed_px[2 * i] - im.rest_px[2 * i]) * x0 +
                       (im.pressed_px[2 * i + 1] - im.rest_px[2 * i + 1]) * y0) / r0;
    ring_sum[ring].first += dr;
    ring_sum[ring].second += 1;
    outward += dr > 0.0 ? 1 : 0;
    ++moved;
  }
  FlatPressRow row;
  row.real = real;
  double inner = 0.0, peak = -kInf;
  int inner_n = 0;
  for (const auto& [ring, sum] : ring_sum) {
    const double mean = sum.first / sum.second;
    if (ring <= 3) {
      inner += sum.first;
      inner_n += sum.second;
    }
    if (mean > peak) {
      peak = mean;
      row.peak_ring = ring;
    }
  }
  const auto& outer = ring_sum.rbegin()->second;
  row.inner_px = inner / inner_n;
  row.outer_px = outer.first / outer.second;
  row.inner_per_mille = 1e3 * row.inner_px / radius_px;
  row.outer_per_mille = 1e3 * row.outer_px / radius_px;
  row.outer_over_peak = peak > 0.0 ? row.outer_px / peak : 0.0;
  row.outward_fraction = static_cast<double>(outward) / moved;
  row.pins_in_contact = im.pins_in_contact;
  row.inner_factor = Factor(row.inner_per_mille, real.inner_per_mille);
  row.outer_factor = Factor(row.outer_per_mille, real.outer_per_mille);
  row.ok = row.inner_factor <= real.factor_allowed && row.outer_factor <= real.factor_allowed;
  return row;
}

// Mean image radius of the outermost ring at rest.
double PatternRadiusPx(const PinLattice& lattice, const std::vector<float>& rest_px, const CameraConfig& cam) {
  int outer_ring = 0;
  for (const auto& p : lattice.pins) outer_ring = std::max(outer_ring, p.ring);
  double sum = 0.0;
  int n = 0;
  for (size_t i = 0; i < lattice.size(); ++i) {
    if (lattice.pins[i].ring != outer_ring) continue;
    sum += std::hypot(rest_px[2 * i] - cam.cx_px, rest_px[2 * i + 1] - cam.cy_px);
    ++n;
  }
  return sum / n;
}

}  // namespace

const std::vector<RealFlatPress>& RealFlatPressFigures() {
  static const std::vector<RealFlatPress> kReal{
      {1.0, 26.8, 11.5, 2.0}, {2.0, 41.3, 23.0, 1.5}, {3.0, 44.2, 25.6, 1.5}, {4.0, 52.3, 39.6, 1.5}};
  return kReal;
}

FlatPressCheck RunFlatPressCheck(const FlatPressOptions& opts) {
  FlatPressCheck out;
  out.ok = true;
  const PinLattice lattice = PinLattice::Build(opts.rig.skin);
  for (const RealFlatPress& real : RealFlatPressFigures()) {
    const PressImages im = PressAndCapture(opts, real.depth_mm * 1e-3);
    if (im.pins_in_contact == 0) {
      throw SimulationError(fmt::format("flat-press check: no pin touches the plate at {} mm", real.depth_mm));
    }
    if (out.pattern_radius_px == 0.0) out.pattern_radius_px = PatternRadiusPx(lattice, im.rest_px, opts.camera);
    out.rows.push_back(MeasureRow(lattice, im, opts.camera, out.pattern_radius_px, real));
    out.ok = out.ok && out.rows.back().ok;
  }
  return out;
}

std::string FormatFlatPressCheck(const FlatPressCheck& c, const std::string& skin_note) {
  std::string s = fmt::format(
      "Flat press: mean outward marker displacement, thousandths of the pattern radius ({:.1f} px){}\n"
      "depth  pins in  rings 1-3: sim / real (factor)   outer ring: sim / real (factor)   outer/peak  peak ring  "
      "outward  allowed  verdict\n",
      c.pattern_radius_px, skin_note);
  for (const FlatPressRow& r : c.rows) {
    s += fmt::format("{:>4.0f} mm {:>7d}  {:>6.1f} / {:>5.1f} (x{:.2f})  {:>6.1f} / {:>5.1f} (x{:.2f})  {:>17.2f}  {:>9d}  "
                     "{:>6.0f} %  x{:.1f}     {}\n",
                     r.real.depth_mm, r.pins_in_contact, r.inner_per_mille, r.real.inner_per_mille, r.inner_factor,
                     r.outer_per_mille, r.real.outer_per_mille, r.outer_factor, r.outer_over_peak, r.peak_ring,
                     100.0 * r.outward_fraction, r.real.factor_allowed, r.ok ? "ok" : "OUTSIDE");
  }
  s += fmt::format("flat-press marker field: {}\n", c.ok ? "within the real TacTip's figures" : "FAILED");
  return s;
}

}  // namespace tactip
