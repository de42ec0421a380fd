#pragma once
// The markers' lateral motion through the gel: an indented pin squeezes the incompressible
// gel under the skin sideways, and the gel carries the skin and every pin's inner end
// (the marker the camera sees) outwards with it. A linear influence of every pin's squeeze
// on every marker, computed once per skin geometry (docs/model.md "Marker kinematics: the gel
// field"). The contact dynamics stay in MuJoCo; this moves only what the camera sees.

#include <array>
#include <vector>

#include "models/skin.h"

namespace tactip {

/// The gel's marker field of one skin. Default-constructed: no field (markers follow the
/// pin bodies alone, skin.marker_model = pins).
class GelField {
 public:
  GelField() = default;
  /// Precomputes the influence of each pin's squeeze on each marker for `skin`'s lattice
  /// (skin.marker_model = gel; an empty field for pins).
  static GelField Build(const SkinConfig& skin, const PinLattice& lattice);

  /// True when the field moves nothing (marker_model = pins).
  bool empty() const { return n_ == 0; }
  int n_pins() const { return n_; }
  /// The squeezed gel volume per unit cell area of a pin indented by `indentation_m` (m):
  /// h_sat tanh(w / h_sat), so it saturates at the squeeze depth h_sat.
  double Squeeze(double indentation_m) const;
  /// Marker shifts (sensor frame, m; N x 3) from each pin's inward displacement along the
  /// sensor axis (m; N values, negative values count as 0). `shift` is resized to N.
  void Shifts(const std::vector<double>& indentation_m, std::vector<std::array<double, 3>>& shift) const;

 private:
  int n_ = 0;
  double squeeze_m_ = 0.0;
  // (N, N, 3), source-major: [j][i][c] is marker i's shift (m) per metre of pin j's squeeze,
  // so one squeezing pin's flow on every marker is one contiguous run.
  std::vector<double> influence_;
};

}  // namespace tactip
