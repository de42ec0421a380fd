#pragma once
// Checks of the simulated contact against analytic anchors (physics.md), run by
// `tactip validate contact` and by the tests.

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "models/contact_rig.h"
#include "scenarios/studies/contact_checks/quasi_static_shear.h"

namespace tactip {

/// Settings of the brush-model check.
struct BrushCheckOptions {
  ContactRigSpec rig;              ///< skin (forced to coupling = none), contact, solver
  double depth_mm = 2.0;           ///< plate indentation at the apex
  double shear_speed_mm_s = 0.5;   ///< plate tangential speed during the shear ramp (quasi-static)
  double shear_damping_ratio = 0.7;  ///< pin shear damping for the check (viscous forces stay < 0.1 % of mu P)
  double overshoot = 1.3;          ///< shear to this multiple of the last pin's slip displacement
  /// Over a gel soft in shear the ramp is long; the plate then moves faster than
  /// shear_speed_mm_s so that the ramp takes at most this long.
  double max_ramp_s = 20.0;
  double sample_every_s = 0.01;    ///< sampling interval of the shear ramp
  double min_load_fraction = 0.1;  ///< load error is judged where Q_brush > this * mu P (below, the
                                   ///< shear-rate damping force is not negligible)
};

/// One sample of the shear ramp.
struct BrushSample {
  double u_m = 0.0;           ///< plate displacement since the ramp started
  double q_N = 0.0;           ///< simulated tangential load on the skin
  double q_brush_N = 0.0;     ///< sum_i min(k_t u, mu N_i) from the simulated N_i
  int slipping = 0;           ///< pins the simulation labels slipping
  int slipping_brush = 0;     ///< pins the brush model says slip (k_t u > mu N_i)
  int contacting = 0;         ///< pins in contact
};

/// Result of the brush-model check.
struct BrushCheck {
  std::string skin_pattern;      ///< the lattice's skin (smooth, fingerprint-v1, fingerprint-v2)
  std::vector<BrushSample> samples;
  double state_agreement = 0.0;  ///< fraction of contacting pin-samples whose state matches
  long pin_samples = 0;          ///< contacting pin-samples compared
  double load_error_max = 0.0;   ///< max |Q - Q_brush| / Q_brush where Q_brush is not tiny
  double mu_P_N = 0.0;           ///< mu times the total normal load (the gross-slip load)
  double k_t_N_m = 0.0;          ///< per-pin shear stiffness
  double shear_speed_mm_s = 0.0; ///< the plate's tangential speed on the ramp
  int pins_in_contact = 0;       ///< pins touching the plate after the press
  /// Spearman rank correlation between the displacement at which each pin first slipped
  /// and the one at which the brush model has it slip (k_t u > mu N_i: least-loaded pins
  /// first), both on the sample grid, so pins whose slip loads differ by less than one
  /// sample's load step tie in both (ranking by N_i itself split such ties at random).
  double slip_order_correlation = 0.0;
};

/// Presses an uncoupled pin lattice onto a flat plate, shears the plate slowly past
/// gross slip, and compares every pin's stick/slip state and the transmitted load with
/// the brush model: pin i sticks while k_t u <= mu N_i, Q = sum_i min(k_t u, mu N_i).
BrushCheck RunBrushCheck(const BrushCheckOptions& opts);

/// Settings of the dome check (coupled lattice under rising tangential load).
struct DomeCheckOptions {
  ContactRigSpec rig;               ///< skin (a membrane-coupled lattice), contact, solver
  double depth_mm = 3.0;            ///< plate indentation at the apex (3 mm: 37 v2 pins in contact)
  double shear_speed_mm_s = 0.1;    ///< plate tangential speed (quasi-static: viscous forces < 1 % of mu P)
  /// A lattice soft in shear needs a long travel to gross slip, about mu P / (N k_tip); the
  /// plate then moves faster than shear_speed_mm_s so that this travel takes at most this long.
  double max_ramp_s = 80.0;
  double sample_every_s = 0.01;     ///< sampling interval of the shear ramp
  double tolerance = 0.02;          ///< allowance on c/a for the lattice's discreteness (one pin of ~60)
  /// A contacting pin on the friction cone is labelled slipping once it slides faster than this
  /// fraction of the plate's speed (1 % of 0.1 mm/s = 1 um/s). A saturated pin that the membrane
  /// drags along with the plate slides slowly, yet it has slipped in the exact solution.
  double slip_label_fraction = 0.01;
};

/// One sample of the dome's shear ramp.
struct DomeSample {
  double q_ratio = 0.0;   ///< Q / (mu P)
  double c_ratio = 0.0;   ///< stick radius over contact radius, sqrt(sticking / contacting pins)
  /// The stick boundary as the lattice resolves it, over the fitted contact radius a:
  /// c_lo = outermost sticking pin, c_hi = innermost slipping pin (inf if none slips).
  double c_lo = 0.0, c_hi = 0.0;
  int sticking = 0;
  int contacting = 0;
};

/// One ring of contacting pins in the dome check: the loads at which its pins slip.
struct DomeRing {
  double r_over_a = 0.0;  ///< distance from the axis over the fitted contact radius
  int pins = 0;
  double sim_q_lo = std::numeric_limits<double>::infinity(), sim_q_hi = -std::numeric_limits<double>::infinity();
  double exact_q_lo = std::numeric_limits<double>::infinity(), exact_q_hi = -std::numeric_limits<double>::infinity();
};

/// Result of the dome check.
struct DomeCheck {
  std::vector<DomeSample> samples;
  double mu_P_N = 0.0;
  int pins_in_contact = 0;
  double gross_q_ratio = 0.0;     ///< Q / (mu P) when every contacting pin slides (1 = Coulomb)
  /// Fraction of samples with 0.1 <= Q/muP <= 0.9 whose c/a lies between the
  /// Cattaneo-Mindlin (1 - q)^(1/3) and brush (1 - q)^(1/4) curves (within tolerance).
  double between_fraction = 0.0;
  /// Fraction of the same samples whose resolved stick boundary [c_lo, c_hi] reaches the
  /// band between the two curves (within tolerance).
  double bracket_fraction = 0.0;
  int samples_judged = 0;
  double contact_radius_mm = 0.0;  ///< a: where the fitted parabolic pressure N = alpha - beta r^2 reaches 0
  /// Membrane coupling length of the lattice, lambda = sqrt(sum_e k_couple l_e^2 / (2 sum_i k_tip)):
  /// the distance over which the membrane spreads a pin's tangential load on the gel (the
  /// continuum of the lattice is k u - T lap u = tau with lambda^2 = T / k; 0 = brush model).
  double coupling_length_mm = 0.0;
  /// Spearman rank correlation between each pin's distance from the axis and the load at
  /// which it first slips, negated: +1 = the stick region shrinks strictly outside-in.
  double outside_in_correlation = 0.0;
  /// Of the pairs of slipped pins at different distances from the axis, the fraction whose
  /// outer pin slipped first (a tie in load counts half): 1 = strictly ring by ring inwards.
  double outside_in_order = 0.0;
  long outside_in_pairs = 0;
  /// The same lattice solved exactly (SolveQuasiStaticShear with the press's normal loads):
  /// the fraction of its stick boundaries, sampled alike, that reach the band ...
  double qs_bracket_fraction = 0.0;
  /// ... and how far each pin's simulated release load is from the exact one, in Q / (mu P).
  double release_error_mean = 0.0, release_error_max = 0.0;
  int release_pins_compared = 0;
  std::vector<DomeRing> rings;  ///< outermost first
  double sim_time_s = 0.0;      ///< simulated time of the press and the shear ramp
  double shear_speed_mm_s = 0.0;  ///< the plate's tangential speed on the ramp
};

/// Throws InputError unless the skin is the membrane-coupled lattice the dome check needs.
void CheckDomeSkin(const SkinConfig& skin);

/// The dome check's options on this solver, skin and contact (the other options at their
/// defaults); throws InputError unless the skin is a membrane-coupled lattice.
DomeCheckOptions MembraneDomeOptions(const SimConfig& sim, const SkinConfig& skin, const ContactConfig& contact);

/// The membrane coupling length (mm) of a lattice whose pins lie on a sphere of radius
/// r_out_m: lambda = sqrt(sum_edges k_couple l^2 / (2 sum_pins k_tip)).
double CouplingLengthMm(const PinLattice& lattice, const SkinMechanics& mech, double r_out_m);

/// The coupling length's reach over the contact radius in the continuum regime that the
/// Cattaneo-Mindlin-brush band assumes: the membrane spreads a pin's load over a third of a.
inline constexpr double kContinuumReach = 1.0 / 3.0;

/// The skin modulus (MPa) that gives this membrane lattice, pressed `depth_mm` onto a flat
/// plate, the continuum regime's coupling length kContinuumReach * a, with a the dome's chord
/// at that depth, sqrt(depth (2 R_out - depth)); the skin's thickness and the gel stay as
/// configured. Bisects within the config's bounds on skin.skin_modulus_mpa; throws
/// InputError when even the softest skin couples further.
double ContinuumSkinModulusMpa(const SkinConfig& skin, double depth_mm);

/// The config override that turns a configured dome into the continuum-regime one:
/// "skin.skin_modulus_mpa=<ContinuumSkinModulusMpa>".
std::string ContinuumDomeSetting(const DomeCheckOptions& configured);

/// Presses a membrane-coupled lattice onto a flat plate and shears the plate slowly to
/// gross slip (single-coefficient Coulomb friction), comparing the stick region with
/// Cattaneo-Mindlin and the brush model.
DomeCheck RunDomeCheck(const DomeCheckOptions& opts);

/// What a dome check must show to pass.
struct DomeCriteria {
  double gross_error = 0.03;      ///< gross slip within this fraction of mu P
  double outside_in = 0.9;        ///< outside-in pair order (DomeCheck::outside_in_order) at least this
  double release_error = 0.01;    ///< every pin's release within this (Q / mu P) of the exact solution
  /// Judge the continuum band (brush .. Cattaneo-Mindlin) on this lattice; false reports it
  /// only (a membrane-dominated lattice, whose exact solution lies inside the band too).
  bool judge_band = true;
  double band_required = 0.9;     ///< fraction of judged samples whose stick boundary reaches the band

  bool GrossOk(const DomeCheck& c) const;
  bool OutsideInOk(const DomeCheck& c) const;
  bool ReleaseOk(const DomeCheck& c) const;
  bool BandOk(const DomeCheck& c) const;
  /// Every criterion, the band only where judged.
  bool Pass(const DomeCheck& c) const;
};

/// Text report of a dome check against its criteria.
std::string FormatDomeCheck(const DomeCheck& c, const DomeCriteria& criteria);

/// Of the pairs of pins at different distances from the axis (given negated, as -radius or
/// -polar angle), the fraction whose outer pin has the lower load at first slip; a tie in
/// load counts half. Writes the number of such pairs to pairs_out if given.
double OutsideInOrder(const std::vector<double>& minus_radius, const std::vector<double>& load,
                      long* pairs_out = nullptr);

/// Spearman rank correlation of two equal-length samples (ties get average ranks).
double SpearmanCorrelation(const std::vector<double>& a, const std::vector<double>& b);

/// Text report of a brush check (for the command line).
std::string FormatBrushCheck(const BrushCheck& c, double agreement_required, double load_error_allowed);

}  // namespace tactip
