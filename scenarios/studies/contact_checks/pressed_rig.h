#pragma once
// The contact rig compiled and driven: the plate presses the dome by a set depth and then
// shears it. Shared by the contact checks (brush model, dome) and the marker check.

#include <vector>

#include "models/contact_rig.h"
#include "models/skin.h"
#include "sim/simulation.h"

namespace tactip {

/// The contact rig of `spec`, compiled. Press() moves the plate -x by gap + depth over 1 s
/// and lets it settle (until t = 1.3 s); Step() then holds the press and drives the
/// tangential servo; ReadContacts() fills `contacts` (one per pin, culled pins never in
/// contact). Throws ModelError if the rig does not compile.
class PressedRig {
  const CompiledModel model_;  // declared first: everything below is built from it
  Simulation sim_;

 public:
  PressedRig(const ContactRigSpec& spec, double depth_m);
  /// Presses to the depth and settles, then reads the contacts.
  void Press();
  /// One step with the press held and the plate's tangential target at y_target (m).
  void Step(double y_target) { Drive(press_, y_target); }
  void ReadContacts() { sim_.ReadContacts(slot_, contacts); }
  /// Tangential plate position (m).
  double PlateY() const { return sim_.Qpos(qy_); }
  const CompiledModel& model() const { return model_; }
  const Simulation& sim() const { return sim_; }
  Simulation& sim() { return sim_; }

  const PinLattice lattice;
  const int n;
  std::vector<GeomContact> contacts;
  double t = 0.0;  ///< simulated time (s)

 private:
  void Drive(double x_target, double y_target);
  std::vector<int> slot_;
  int servo_x_, servo_y_, qy_;
  double press_, dt_;
};

}  // namespace tactip
