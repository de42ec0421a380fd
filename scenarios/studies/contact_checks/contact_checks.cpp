#include "scenarios/studies/contact_checks/contact_checks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

#include <fmt/format.h>

#include "scenarios/studies/contact_checks/pressed_rig.h"
#include "sensors/labels.h"
#include "sim/simulation.h"

namespace tactip {

namespace {

constexpr double kSameRing = 1e-9;  // pins of one ring differ in radius (m, rad or r/a) by rounding only
// Tangential contact force on a pin, world y and z (the plate shears along y).
std::array<double, 2> TangentialYZ(const GeomContact& c) {
  const double fn = c.force_world[0] * c.normal_world[0] + c.force_world[1] * c.normal_world[1] +
                    c.force_world[2] * c.normal_world[2];
  return {c.force_world[1] - fn * c.normal_world[1], c.force_world[2] - fn * c.normal_world[2]};
}
// Slip order against the brush model's (by normal force), over the pins that slipped in
// both (a pin out of contact never slips).
double SlipOrderCorrelation(const std::vector<double>& first_slip_u, const std::vector<double>& brush_first_slip_u) {
  std::vector<double> brush_order, order;
  for (size_t i = 0; i < first_slip_u.size(); ++i) {
    if (std::isnan(first_slip_u[i]) || std::isnan(brush_first_slip_u[i])) continue;
    brush_order.push_back(brush_first_slip_u[i]);
    order.push_back(first_slip_u[i]);
  }
  return SpearmanCorrelation(brush_order, order);
}
}  // namespace

BrushCheck RunBrushCheck(const BrushCheckOptions& opts) {
  // The brush model is the uncoupled lattice with single-coefficient Coulomb friction.
  ContactRigSpec spec = opts.rig;
  spec.skin.coupling = "none";
  spec.skin.shear_damping_ratio = opts.shear_damping_ratio;
  spec.max_depth_m = opts.depth_mm * 1e-3;
  PressedRig rig(spec, spec.max_depth_m);
  rig.Press();
  const SkinMechanics mech = SkinMechanics::From(spec.skin, rig.lattice.size());
  const int N = rig.n;
  const double mu = spec.contact.friction;
  const std::vector<GeomContact>& contacts = rig.contacts;

  // Normal loads after the press fix the brush prediction's slip displacements.
  BrushCheck out;
  out.skin_pattern = spec.skin.pattern;
  out.k_t_N_m = mech.k_tip_N_m;  // the gel column in series with a ridge (= k_shear on a smooth skin)
  double sum_n = 0.0, n_max = 0.0;
  for (const auto& c : contacts) {
    if (!c.in_contact) continue;
    ++out.pins_in_contact;
    sum_n += c.normal_N;
    n_max = std::max(n_max, c.normal_N);
  }
  out.mu_P_N = mu * sum_n;
  if (out.pins_in_contact == 0) throw SimulationError("brush check: no pin touches the plate after the press");

  // Shear ramp at constant speed past the last pin's slip displacement, sampled.
  const double u_max = opts.overshoot * mu * n_max / out.k_t_N_m;
  out.shear_speed_mm_s = std::max(opts.shear_speed_mm_s, 1e3 * u_max / opts.max_ramp_s);
  const double v = out.shear_speed_mm_s * 1e-3;
  const double y0 = rig.PlateY();
  const double t0 = rig.t;
  LabelConfig labels;
  std::vector<PinContactSample> samples(N);
  std::vector<std::uint8_t> pin_contact(N), pin_slip(N);
  long agree = 0;
  // Each pin's first slipping sample, simulated and by the brush model (the same sample grid,
  // so pins whose slip loads differ by less than one sample's load step tie in both).
  std::vector<double> first_slip_u(N, std::nan("")), brush_first_slip_u(N, std::nan(""));
  double next_sample = t0 + opts.sample_every_s;
  while (rig.t - t0 < u_max / v) {
    rig.Step(v * (rig.t - t0));
    if (rig.t < next_sample) continue;
    next_sample += opts.sample_every_s;
    rig.ReadContacts();
    BrushSample s;
    s.u_m = rig.PlateY() - y0;
    for (int i = 0; i < N; ++i) {
      const GeomContact& c = contacts[i];
      const auto [fty, ftz] = TangentialYZ(c);
      samples[i] = {c.in_contact, c.slip_speed_m_s, c.in_contact ? c.cone_use : 0.0};
      if (!c.in_contact) continue;
      s.q_N += std::abs(fty);
      const double spring = out.k_t_N_m * s.u_m;
      s.q_brush_N += std::min(spring, mu * c.normal_N);
      s.slipping_brush += spring > mu * c.normal_N ? 1 : 0;
    }
    const FrameLabels fl = LabelFrame(samples, labels, pin_contact.data(), pin_slip.data());
    s.contacting = fl.n_contact;
    s.slipping = fl.n_slip;
    // Per-pin agreement with the brush state.
    for (int i = 0; i < N; ++i) {
      if (!pin_contact[i]) continue;
      const bool brush_slip = out.k_t_N_m * s.u_m > mu * contacts[i].normal_N;
      if (pin_slip[i] && std::isnan(first_slip_u[i])) first_slip_u[i] = s.u_m;
      if (brush_slip && std::isnan(brush_first_slip_u[i])) brush_first_slip_u[i] = s.u_m;
      agree += (brush_slip == static_cast<bool>(pin_slip[i])) ? 1 : 0;
      ++out.pin_samples;
    }
    if (s.q_brush_N > opts.min_load_fraction * out.mu_P_N) {
      out.load_error_max = std::max(out.load_error_max, std::abs(s.q_N - s.q_brush_N) / s.q_brush_N);
    }
    out.samples.push_back(s);
  }
  out.state_agreement = out.pin_samples > 0 ? static_cast<double>(agree) / static_cast<double>(out.pin_samples) : 0.0;
  out.slip_order_correlation = SlipOrderCorrelation(first_slip_u, brush_first_slip_u);
  return out;
}

void CheckDomeSkin(const SkinConfig& skin) {
  if (skin.coupling != "membrane") {
    throw InputError("dome check: skin.coupling = '" + skin.coupling + "': needs the membrane-coupled lattice");
  }
  if (skin.normal_spring != "axial") {
    throw InputError("dome check: skin.normal_spring = '" + skin.normal_spring +
                     "': the lattice's exact quasi-static solution rests each gel spring at its pin's height (axial)");
  }
}

namespace {

// What the dome check needs from the press: each pin's normal load and contact, its
// distance from the axis in the plate plane, and the contact radius.
struct DomePress {
  std::vector<double> normal_N;
  std::vector<std::uint8_t> contact;
  std::vector<double> r_pin;  // m
  double a_m = 0.0;           // contact radius
};

// Reads the pressed rig; sets out's pins_in_contact, mu_P_N and contact_radius_mm. The
// contact radius comes from a least-squares fit of the parabolic pressure N_i = alpha -
// beta r_i^2 (the gel columns are a Winkler foundation): a^2 = alpha / beta.
DomePress ReadDomePress(const PressedRig& rig, const ContactRigSpec& spec, DomeCheck& out) {
  const int N = rig.n;
  const std::vector<GeomContact>& contacts = rig.contacts;
  DomePress press;
  press.normal_N.assign(N, 0.0);
  press.contact.assign(N, 0);
  press.r_pin.assign(N, 0.0);
  const double r_out = spec.skin.OuterRadiusMm() * 1e-3;
  double sum_n = 0.0, s1 = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < N; ++i) {
    press.r_pin[i] = r_out * std::sin(rig.lattice.pins[i].polar_rad);
    if (!contacts[i].in_contact) continue;
    ++out.pins_in_contact;
    sum_n += contacts[i].normal_N;
    press.contact[i] = 1;
    press.normal_N[i] = contacts[i].normal_N;
    const double x = press.r_pin[i] * press.r_pin[i], y = contacts[i].normal_N;
    s1 += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  if (out.pins_in_contact == 0) throw SimulationError("dome check: no pin touches the plate after the press");
  out.mu_P_N = spec.contact.friction * sum_n;
  const double slope = (s1 * sxy - sx * sy) / (s1 * sxx - sx * sx);
  const double icpt = (sy - slope * sx) / s1;
  if (!(slope < 0.0) || !(icpt > 0.0)) throw SimulationError("dome check: the pressure does not fall off from the apex");
  press.a_m = std::sqrt(-icpt / slope);
  out.contact_radius_mm = press.a_m * 1e3;
  return press;
}

// One sample of the shear ramp: load ratio, stick/slip counts and the stick boundary's
// bracket; records each pin's load ratio at its first slip.
DomeSample SampleDome(const PressedRig& rig, const DomePress& press, double mu, const LabelConfig& labels,
                      std::vector<double>& first_slip_q, bool* gross_slip) {
  const int N = rig.n;
  std::vector<PinContactSample> samples(N);
  std::vector<std::uint8_t> pin_contact(N), pin_slip(N);
  double q = 0.0, p = 0.0;
  for (int i = 0; i < N; ++i) {
    const GeomContact& c = rig.contacts[i];
    const auto [fty, ftz] = TangentialYZ(c);
    samples[i] = {c.in_contact, c.slip_speed_m_s, c.in_contact ? c.cone_use : 0.0};
    q += fty;
    p += c.normal_N;
  }
  const FrameLabels fl = LabelFrame(samples, labels, pin_contact.data(), pin_slip.data());
  DomeSample s;
  s.q_ratio = std::abs(q) / (mu * p);
  s.contacting = fl.n_contact;
  s.sticking = fl.n_contact - fl.n_slip;
  s.c_ratio = fl.n_contact > 0 ? std::sqrt(static_cast<double>(s.sticking) / fl.n_contact) : 0.0;
  s.c_hi = std::numeric_limits<double>::infinity();
  for (int i = 0; i < N; ++i) {
    if (!pin_contact[i]) continue;
    if (pin_slip[i]) {
      s.c_hi = std::min(s.c_hi, press.r_pin[i] / press.a_m);
      if (std::isnan(first_slip_q[i])) first_slip_q[i] = s.q_ratio;
    } else {
      s.c_lo = std::max(s.c_lo, press.r_pin[i] / press.a_m);
    }
  }
  *gross_slip = fl.gross_slip;
  return s;
}

// Shear ramp until every contacting pin slides (or well past the Coulomb load); fills
// out.samples and out.gross_q_ratio, returns each pin's load ratio at its first slip.
std::vector<double> ShearDome(PressedRig& rig, const DomeCheckOptions& opts, const SkinMechanics& mech,
                              const DomePress& press, DomeCheck& out) {
  const double v = out.shear_speed_mm_s * 1e-3, mu = opts.rig.contact.friction;
  LabelConfig labels;
  labels.slip_speed_m_s = opts.slip_label_fraction * v;
  const double u_limit = 4.0 * out.mu_P_N / (out.pins_in_contact * mech.k_tip_N_m);
  const double y0 = rig.PlateY(), t0 = rig.t;
  std::vector<double> first_slip_q(rig.n, std::nan(""));
  double next_sample = t0 + opts.sample_every_s;
  out.gross_q_ratio = std::nan("");
  while (rig.PlateY() - y0 < u_limit) {
    rig.Step(v * (rig.t - t0));
    if (rig.t < next_sample) continue;
    next_sample += opts.sample_every_s;
    rig.ReadContacts();
    bool gross = false;
    out.samples.push_back(SampleDome(rig, press, mu, labels, first_slip_q, &gross));
    if (gross) {
      out.gross_q_ratio = out.samples.back().q_ratio;
      break;
    }
  }
  return first_slip_q;
}

// The Cattaneo-Mindlin-brush band for the stick radius at load ratios 0.1-0.9.
struct DomeBand {
  double tolerance;
  static bool Judged(double q) { return q >= 0.1 && q <= 0.9; }
  bool Contains(double q, double c_lo, double c_hi) const {
    return c_lo <= c_hi + kSameRing && c_hi >= std::cbrt(1.0 - q) - tolerance &&
           c_lo <= std::pow(1.0 - q, 0.25) + tolerance;
  }
};

// Share of the simulated samples in the band (stick boundary bracket, and the sticking
// count's radius).
void JudgeSamples(const DomeBand& band, DomeCheck& out) {
  for (const auto& s : out.samples) {
    if (!DomeBand::Judged(s.q_ratio)) continue;
    ++out.samples_judged;
    const double cm = std::cbrt(1.0 - s.q_ratio), brush = std::pow(1.0 - s.q_ratio, 0.25);
    if (s.c_ratio >= cm - band.tolerance && s.c_ratio <= brush + band.tolerance) out.between_fraction += 1.0;
    if (band.Contains(s.q_ratio, s.c_lo, s.c_hi)) out.bracket_fraction += 1.0;
  }
  if (out.samples_judged > 0) {
    out.between_fraction /= out.samples_judged;
    out.bracket_fraction /= out.samples_judged;
  }
}

// Share of the exact quasi-static solution's load grid in the band.
void JudgeExact(const QuasiStaticShear& qs, const DomePress& press, const DomeBand& band, DomeCheck& out) {
  int judged = 0;
  for (size_t g = 0; g < qs.grid_q.size(); ++g) {
    const double q = qs.grid_q[g];
    if (!DomeBand::Judged(q)) continue;
    double c_lo = 0.0, c_hi = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < press.contact.size(); ++i) {
      if (!press.contact[i]) continue;
      if (qs.StuckAt(static_cast<int>(i), qs.grid_delta_m[g])) {
        c_lo = std::max(c_lo, press.r_pin[i] / press.a_m);
      } else {
        c_hi = std::min(c_hi, press.r_pin[i] / press.a_m);
      }
    }
    ++judged;
    if (band.Contains(q, c_lo, c_hi)) out.qs_bracket_fraction += 1.0;
  }
  if (judged > 0) out.qs_bracket_fraction /= judged;
}

// Releases ring by ring (pins at one distance from the axis), simulated against exact.
void CompareRingReleases(const QuasiStaticShear& qs, const DomePress& press, const std::vector<double>& first_slip_q,
                         DomeCheck& out) {
  const int N = static_cast<int>(press.contact.size());
  std::vector<int> by_radius(N);
  for (int i = 0; i < N; ++i) by_radius[i] = i;
  std::sort(by_radius.begin(), by_radius.end(), [&](int p, int q) { return press.r_pin[p] > press.r_pin[q]; });
  for (int i : by_radius) {
    if (!press.contact[i]) continue;
    const double r_over_a = press.r_pin[i] / press.a_m;
    if (out.rings.empty() || std::abs(out.rings.back().r_over_a - r_over_a) > kSameRing) {
      DomeRing ring;
      ring.r_over_a = r_over_a;
      out.rings.push_back(ring);
    }
    DomeRing& ring = out.rings.back();
    ++ring.pins;
    const double sim = first_slip_q[i], exact = qs.release_q[i];
    ring.exact_q_lo = std::min(ring.exact_q_lo, exact);
    ring.exact_q_hi = std::max(ring.exact_q_hi, exact);
    if (std::isnan(sim)) continue;  // still stuck when gross slip was declared
    ring.sim_q_lo = std::min(ring.sim_q_lo, sim);
    ring.sim_q_hi = std::max(ring.sim_q_hi, sim);
    const double err = std::abs(sim - exact);
    out.release_error_mean += err;
    out.release_error_max = std::max(out.release_error_max, err);
    ++out.release_pins_compared;
  }
  if (out.release_pins_compared > 0) out.release_error_mean /= out.release_pins_compared;
}

}  // namespace

// Coupling length of the sheared (y) component: with edges of every direction,
// sum_e k_yy (l_e . grad u)^2 averages to (1/2) sum_e k_yy l_e^2 |grad u|^2 over the
// lattice's area, against sum_i k_tip u^2. k_yy is k_couple on isotropic links and k e_y^2
// on central ones (the transverse coupling they add is left out).
double CouplingLengthMm(const PinLattice& lattice, const SkinMechanics& mech, double r_out_m) {
  const LatticeShearStiffness stiffness = LatticeShearStiffness::Of(lattice, mech);
  double edge_sum = 0.0;
  for (const auto& link : stiffness.links) {
    const auto& p = lattice.pins[link.a].normal;
    const auto& q = lattice.pins[link.b].normal;
    const double l = r_out_m * std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
    edge_sum += link.k_yy * l * l;
  }
  // The orthotropic membrane's modes: the same sum, the y component's energy under a unit
  // gradient along y plus that along z.
  for (const auto& mode : stiffness.modes) {
    for (int d = 1; d <= 2; ++d) {
      double stretch = 0.0;
      for (int p = 0; p < 3; ++p) stretch += mode.coef[2 * p] * r_out_m * lattice.pins[mode.pins[p]].normal[d];
      edge_sum += mode.k_N_m * stretch * stretch;
    }
  }
  return 1e3 * std::sqrt(edge_sum / (2.0 * static_cast<double>(lattice.pins.size()) * mech.k_tip_N_m));
}

double ContinuumSkinModulusMpa(const SkinConfig& skin, double depth_mm) {
  SkinConfig s = skin;
  const PinLattice lattice = PinLattice::Build(s);
  const double r_out_mm = s.OuterRadiusMm();
  const double target_mm = kContinuumReach * std::sqrt(depth_mm * (2.0 * r_out_mm - depth_mm));
  const auto reach_mm = [&](double modulus_mpa) {
    s.skin_modulus_mpa = modulus_mpa;
    return CouplingLengthMm(lattice, SkinMechanics::From(s, lattice), r_out_mm * 1e-3);
  };
  double lo = kSkinModulusMinMpa, hi = kSkinModulusMaxMpa;
  if (reach_mm(lo) > target_mm) {
    throw InputError(fmt::format("the continuum-regime dome needs a membrane coupling length of {:.2f} mm, a third of "
                                 "the contact radius, but even a {:g} MPa skin couples over {:.2f} mm",
                                 target_mm, lo, reach_mm(lo)));
  }
  if (reach_mm(hi) < target_mm) return hi;
  // The coupling length grows with the modulus: the membrane's tension and its valley
  // hinges both scale with E.
  while (hi / lo > 1.0001) {
    const double mid = std::sqrt(lo * hi);
    (reach_mm(mid) < target_mm ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

DomeCheckOptions MembraneDomeOptions(const SimConfig& sim, const SkinConfig& skin, const ContactConfig& contact) {
  CheckDomeSkin(skin);
  DomeCheckOptions d;
  d.rig.sim = sim;
  d.rig.skin = skin;
  d.rig.contact = contact;
  return d;
}

std::string ContinuumDomeSetting(const DomeCheckOptions& configured) {
  return fmt::format("skin.skin_modulus_mpa={:.4g}", ContinuumSkinModulusMpa(configured.rig.skin, configured.depth_mm));
}

DomeCheck RunDomeCheck(const DomeCheckOptions& opts) {
  ContactRigSpec spec = opts.rig;
  CheckDomeSkin(spec.skin);
  spec.max_depth_m = opts.depth_mm * 1e-3;
  PressedRig rig(spec, spec.max_depth_m);
  rig.Press();
  const PinLattice& lattice = rig.lattice;
  const SkinMechanics mech = SkinMechanics::From(spec.skin, lattice);
  DomeCheck out;
  const DomePress press = ReadDomePress(rig, spec, out);
  out.coupling_length_mm = CouplingLengthMm(lattice, mech, spec.skin.OuterRadiusMm() * 1e-3);
  const double travel_mm = 1e3 * out.mu_P_N / (out.pins_in_contact * mech.k_tip_N_m);
  out.shear_speed_mm_s = std::max(opts.shear_speed_mm_s, travel_mm / opts.max_ramp_s);
  const std::vector<double> first_slip_q = ShearDome(rig, opts, mech, press, out);
  const DomeBand band{opts.tolerance};
  JudgeSamples(band, out);
  // The same lattice solved exactly (quasi-static Coulomb): where the simulated releases
  // differ from it is the dynamics' and the soft contact's doing; where both miss the band
  // it is the lattice's mechanics.
  const QuasiStaticShear qs =
      SolveQuasiStaticShear(LatticeShearStiffness::Of(lattice, mech), press.normal_N, press.contact,
                            spec.contact.friction, 4000,
                            spec.sim.noslip == "exact" ? spec.contact.presliding_mm * 1e-3 : 0.0);
  JudgeExact(qs, press, band, out);
  CompareRingReleases(qs, press, first_slip_q, out);
  // Outside-in: distance from the axis against the load at first slip.
  std::vector<double> radius, order;
  for (int i = 0; i < rig.n; ++i) {
    if (std::isnan(first_slip_q[i])) continue;
    radius.push_back(-lattice.pins[i].polar_rad);
    order.push_back(first_slip_q[i]);
  }
  out.outside_in_correlation = SpearmanCorrelation(radius, order);
  out.outside_in_order = OutsideInOrder(radius, order, &out.outside_in_pairs);
  out.sim_time_s = rig.t;
  return out;
}

bool DomeCriteria::GrossOk(const DomeCheck& c) const { return std::abs(c.gross_q_ratio - 1.0) <= gross_error; }
bool DomeCriteria::OutsideInOk(const DomeCheck& c) const { return c.outside_in_order >= outside_in; }
bool DomeCriteria::ReleaseOk(const DomeCheck& c) const {
  return c.release_pins_compared == c.pins_in_contact && c.release_error_max <= release_error;
}
bool DomeCriteria::BandOk(const DomeCheck& c) const { return c.bracket_fraction >= band_required; }
bool DomeCriteria::Pass(const DomeCheck& c) const {
  return GrossOk(c) && OutsideInOk(c) && ReleaseOk(c) && (!judge_band || BandOk(c));
}

std::string FormatDomeCheck(const DomeCheck& c, const DomeCriteria& k) {
  const auto verdict = [](bool ok) { return ok ? "PASS" : "FAIL"; };
  std::string out = fmt::format("  {} pins in contact, mu P = {:.4f} N, contact radius a = {:.2f} mm (fitted parabolic "
                                "pressure), membrane coupling length lambda = {:.2f} mm = {:.2f} a; sheared at "
                                "{:.2g} mm/s\n",
                                c.pins_in_contact, c.mu_P_N, c.contact_radius_mm, c.coupling_length_mm,
                                c.coupling_length_mm / c.contact_radius_mm, c.shear_speed_mm_s);
  out += fmt::format("  {:>8} {:>8} {:>15} {:>10} {:>10} {:>9}\n", "Q/muP", "c/a_sim", "c/a_resolved", "c/a_CM",
                     "c/a_brush", "stick/in");
  const size_t stride = std::max<size_t>(1, c.samples.size() / 12);
  for (size_t n = 0; n < c.samples.size(); n += stride) {
    const DomeSample& s = c.samples[n];
    const double q = std::min(1.0, s.q_ratio);
    const std::string hi = std::isinf(s.c_hi) ? "-" : fmt::format("{:.3f}", s.c_hi);
    out += fmt::format("  {:>8.3f} {:>8.3f} {:>15} {:>10.3f} {:>10.3f} {:>5}/{}\n", s.q_ratio, s.c_ratio,
                       fmt::format("{:.3f}..{}", s.c_lo, hi), std::cbrt(1.0 - q), std::pow(1.0 - q, 0.25), s.sticking,
                       s.contacting);
  }
  out += fmt::format("  releases ring by ring, Q/muP at which the ring's pins slip (exact = the same lattice solved "
                     "quasi-statically):\n");
  out += fmt::format("  {:>6} {:>5} {:>13} {:>13} {:>7} {:>7}\n", "r/a", "pins", "simulated", "exact", "CM", "brush");
  for (const DomeRing& r : c.rings) {
    const std::string sim = std::isfinite(r.sim_q_lo) ? fmt::format("{:.3f}..{:.3f}", r.sim_q_lo, r.sim_q_hi) : "-";
    out += fmt::format("  {:>6.3f} {:>5} {:>13} {:>13} {:>7.3f} {:>7.3f}\n", r.r_over_a, r.pins, sim,
                       fmt::format("{:.3f}..{:.3f}", r.exact_q_lo, r.exact_q_hi), 1.0 - std::pow(r.r_over_a, 3.0),
                       1.0 - std::pow(r.r_over_a, 4.0));
  }
  out += fmt::format("  gross slip at Q = {:.4f} mu P (required within {:.0f} %): {}\n", c.gross_q_ratio,
                     100.0 * k.gross_error, verdict(k.GrossOk(c)));
  out += fmt::format("  stick region shrinks outside-in: of {} pin pairs on different rings, the outer pin slips first "
                     "in {:.1f} % (ties half; required >= {:.0f} %): {}; Spearman(-radius, load at first slip) {:.3f}\n",
                     c.outside_in_pairs, 100.0 * c.outside_in_order, 100.0 * k.outside_in,
                     verdict(k.OutsideInOk(c)), c.outside_in_correlation);
  out += fmt::format("  every pin slips at the exact quasi-static load: mean |error| {:.4f}, max {:.4f} Q/muP over {} of "
                     "{} pins (allowed {:.2f}): {}\n",
                     c.release_error_mean, c.release_error_max, c.release_pins_compared, c.pins_in_contact,
                     k.release_error, verdict(k.ReleaseOk(c)));
  const std::string band = fmt::format(
      "  stick boundary (outermost sticking .. innermost slipping pin) reaches the band between Cattaneo-Mindlin and "
      "brush in {:.1f} % of {} samples with 0.1 <= Q/muP <= 0.9 (exact solution: {:.1f} %)",
      100.0 * c.bracket_fraction, c.samples_judged, 100.0 * c.qs_bracket_fraction);
  if (k.judge_band) {
    out += fmt::format("{} (required >= {:.0f} %): {}\n", band, 100.0 * k.band_required,
                       verdict(k.BandOk(c)));
  } else {
    out += band + " (reported; the band is judged on the continuum-regime lattice)\n";
  }
  out += fmt::format("  (area estimate c/a_sim = sqrt(stick/in) lies in the band in {:.1f} % of them; it places a "
                     "whole ring's slip at the ring's area boundary)\n",
                     100.0 * c.between_fraction);
  return out;
}

double OutsideInOrder(const std::vector<double>& minus_radius, const std::vector<double>& load, long* pairs_out) {
  // Pins of one ring tie in radius, so a rank correlation stays below 1 even for a strict
  // ring-by-ring release; the pair count does not. A tie in load counts half, so a lattice
  // whose pins all let go at once scores 0.5.
  double in_order = 0.0;
  long pairs = 0;
  for (size_t p = 0; p < minus_radius.size(); ++p) {
    for (size_t q = p + 1; q < minus_radius.size(); ++q) {
      if (std::abs(minus_radius[p] - minus_radius[q]) <= kSameRing) continue;
      const bool p_outer = minus_radius[p] < minus_radius[q];
      const double outer = p_outer ? load[p] : load[q], inner = p_outer ? load[q] : load[p];
      in_order += outer < inner ? 1.0 : (outer == inner ? 0.5 : 0.0);
      ++pairs;
    }
  }
  if (pairs_out != nullptr) *pairs_out = pairs;
  return pairs > 0 ? in_order / static_cast<double>(pairs) : 0.0;
}

double SpearmanCorrelation(const std::vector<double>& a, const std::vector<double>& b) {
  // Ranks with ties averaged, then the Pearson correlation of the ranks.
  auto ranks = [](const std::vector<double>& x) {
    std::vector<size_t> idx(x.size());
    for (size_t i = 0; i < idx.size(); ++i) idx[i] = i;
    std::sort(idx.begin(), idx.end(), [&](size_t p, size_t q) { return x[p] < x[q]; });
    std::vector<double> r(x.size());
    for (size_t i = 0; i < idx.size();) {
      size_t j = i;
      while (j + 1 < idx.size() && x[idx[j + 1]] == x[idx[i]]) ++j;
      for (size_t k = i; k <= j; ++k) r[idx[k]] = 0.5 * static_cast<double>(i + j);
      i = j + 1;
    }
    return r;
  };
  if (a.size() != b.size() || a.size() < 2) return std::nan("");
  const std::vector<double> ra = ranks(a), rb = ranks(b);
  const double n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (size_t i = 0; i < ra.size(); ++i) {
    ma += ra[i] / n;
    mb += rb[i] / n;
  }
  double sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < ra.size(); ++i) {
    sab += (ra[i] - ma) * (rb[i] - mb);
    saa += (ra[i] - ma) * (ra[i] - ma);
    sbb += (rb[i] - mb) * (rb[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : std::nan("");
}

std::string FormatBrushCheck(const BrushCheck& c, double agreement_required, double load_error_allowed) {
  std::string out = fmt::format(
      "brush model (uncoupled {} lattice, {} pins in contact, k_t = {:.3g} N/m, mu P = {:.4f} N; sheared at {:.2g} "
      "mm/s)\n",
      c.skin_pattern, c.pins_in_contact, c.k_t_N_m, c.mu_P_N, c.shear_speed_mm_s);
  out += fmt::format("  {:>8} {:>10} {:>10} {:>8} {:>10} {:>10}\n", "u_mm", "Q_sim_N", "Q_brush_N", "err_%",
                     "slip_sim", "slip_brush");
  const size_t stride = std::max<size_t>(1, c.samples.size() / 12);
  for (size_t k = 0; k < c.samples.size(); k += stride) {
    const BrushSample& s = c.samples[k];
    out += fmt::format("  {:>8.3f} {:>10.5f} {:>10.5f} {:>8.2f} {:>10} {:>10}\n", s.u_m * 1e3, s.q_N, s.q_brush_N,
                       s.q_brush_N > 0 ? 100.0 * (s.q_N - s.q_brush_N) / s.q_brush_N : 0.0, s.slipping,
                       s.slipping_brush);
  }
  const bool ok_state = c.state_agreement >= agreement_required;
  const bool ok_load = c.load_error_max <= load_error_allowed;
  out += fmt::format("  stick/slip state agrees for {:.2f} % of {} contacting pin-samples (required >= {:.0f} %): {}\n",
                     100.0 * c.state_agreement, c.pin_samples, 100.0 * agreement_required, ok_state ? "PASS" : "FAIL");
  out += fmt::format("  transmitted load within {:.2f} % of sum min(k_t u, mu N_i) (allowed {:.0f} %): {}\n",
                     100.0 * c.load_error_max, 100.0 * load_error_allowed, ok_load ? "PASS" : "FAIL");
  out += fmt::format(
      "  slip order follows normal force (brush order, sampled): Spearman rank correlation {:.3f} (required >= 0.9): {}\n",
      c.slip_order_correlation, c.slip_order_correlation >= 0.9 ? "PASS" : "FAIL");
  return out;
}

}  // namespace tactip
