#pragma once
// The friction rows' velocity target in MuJoCo's constraint solve, faded out for fast
// sliding contacts when a friction post-pass owns the tangential velocities.
//
// MuJoCo gives every friction row the reference acceleration -B v_t (B = 2 / (d_max
// timeconst)): the solve tries to stop a sliding contact within one contact time
// constant. In an elliptic cone that demand, far outside the cone for a contact sliding
// at v_t, is projected onto the cone's surface, and the projection raises the normal
// force with it: a contact sliding at 0.3 m/s pushes its pin off the surface, the pin
// springs back, and the normal forces of a sliding object chatter (on the rail rig the
// total normal force swung between 0.02 and 1.2 N while the object fell, the number of
// contacting pins between 1 and 31). Coulomb friction does not change the normal force.
// With a post-pass (tactip's exact friction pass or MuJoCo's noslip) the friction forces
// of the solve are replaced anyway; all the solve's friction rows must still do is
// share the acceleration balance, so a fast contact's target becomes zero tangential
// acceleration and the normal forces of sliding contacts stay what the penetration gives.

struct mjData_;

namespace tactip {

/// Fades out the reference acceleration of the friction rows of every elliptic contact
/// sliding faster than `sliding_speed_m_s`: scaled by 2 - v / v_free, so it is continuous
/// at the threshold and zero from twice it on (a step to zero at the threshold kicked the
/// normal forces of the rail's falling object as it sped through 30 mm/s: 13 of 19 pins in
/// contact for a frame). Slower contacts keep MuJoCo's target: sticking
/// and creeping ones (um/s), and the quasi-static partial slip of a fingerprint skin's edge
/// pins (mm/s), whose light contacts flickered open and shut without it (stability suite,
/// v2 cases, at thresholds of 1 and 10 mm/s; 30 mm/s, the default, is clean). Call after
/// the velocity stage (efc_vel) and before mj_fwdConstraint.
void FadeFrictionReference(mjData_* d, double sliding_speed_m_s);

}  // namespace tactip
