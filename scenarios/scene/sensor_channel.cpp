#include "scenarios/scene/sensor_channel.h"

#include <limits>

#include "sim/base/random.h"

namespace tactip {

SensorChannel SensorChannel::Make(const SceneSensor& s, size_t k, std::uint64_t run_seed, double mu, int object_geom,
                                  const ContactConfig& contact, const LabelConfig& labels,
                                  const TactileImageConfig& images, CompiledModel& model) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const std::uint64_t base = k == 0 ? run_seed : DeriveSeed(run_seed, 100 + k);
  const size_t n = static_cast<size_t>(s.n_pins);
  SensorChannel ch{TactileSensor(s.spec, s.ids, DeriveSeed(base, 1), DeriveSeed(base, 2)),
                   FrictionLaw(contact, labels, mu, s.ids.pin_geom, object_geom, DeriveSeed(base, 3), model),
                   std::vector<double>(n, kNaN),
                   {},
                   std::vector<double>(n, kNaN),
                   std::nullopt};
  // Rendered images only when asked for.
  if (images.enabled) ch.imaging.emplace(images, s.spec.camera, DeriveSeed(base, 4));
  return ch;
}

}  // namespace tactip
