#include "sensors/tactile_sensor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/skin.h"

namespace tactip {

namespace {

double Dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The external camera's noise: the configured pixel noise, independent per marker, no
// dropouts.
CameraConfig ExternalNoise(const ExternalCameraConfig& e) {
  CameraConfig c;
  c.noise_model = "independent";
  c.pixel_noise_px = e.pixel_noise_px;
  c.dropout_prob = 0.0;
  return c;
}

}  // namespace

TactileSensorIds TactileSensorIds::Find(const CompiledModel& m, const std::string& body_name, int n_pins,
                                        const std::vector<bool>& outer, const SkinNames& names) {
  TactileSensorIds ids;
  ids.body = m.BodyId(body_name);
  ids.slot_of_geom.assign(m.ngeom(), -1);
  for (int i = 0; i < n_pins; ++i) {
    ids.pin_site.push_back(m.SiteId(names.PinSite(i)));
    ids.pin_outer_site.push_back(outer[i] ? m.SiteId(names.PinOuterSite(i)) : -1);
    int g = -1;
    try {
      g = m.GeomId(names.PinGeom(i));
    } catch (const ModelError&) {
      g = -1;  // culled: this pin cannot touch the stimulus
    }
    ids.pin_geom.push_back(g);
    if (g >= 0) ids.slot_of_geom[g] = i;
    ids.pin_dome_spring.push_back(m.FindTendon(names.PinDomeSpring(i)));
  }
  return ids;
}

TactileSensor::TactileSensor(const TactileSensorSpec& spec, const TactileSensorIds& ids, std::uint64_t noise_seed,
                             std::uint64_t external_seed)
    : spec_(spec),
      ids_(ids),
      n_(static_cast<int>(ids.pin_site.size())),
      camera_(spec.camera),
      ext_camera_(spec.external, spec.apex_x_m),
      noise_(spec.camera, noise_seed),
      ext_noise_(ExternalNoise(spec.external), external_seed),
      contacts_(n_),
      tangential_(n_),
      samples_(n_),
      pin_contact_(n_),
      pin_slip_(n_),
      px_(2 * n_),
      ext_px_(2 * n_),
      clean_px_(2 * n_),
      valid_(n_),
      ext_valid_(n_),
      marker_shift_m_(n_),
      normal_N_(n_) {
  if (!spec.gel_field.empty() && spec.gel_field.n_pins() != n_) {
    throw std::logic_error("TactileSensor: the gel field is built for another lattice");
  }
}

void TactileSensor::Rest(const Simulation& sim) {
  pose_ = {sim.BodyPos(ids_.body), sim.BodyRot(ids_.body)};
  rest_marker_m_.clear();
  for (int i = 0; i < n_; ++i) rest_marker_m_.push_back(pose_.Point(sim.SitePos(ids_.pin_site[i])));
  rest_dome_spring_m_.assign(n_, 0.0);
  for (size_t i = 0; i < ids_.pin_dome_spring.size(); ++i) {
    if (ids_.pin_dome_spring[i] >= 0) rest_dome_spring_m_[i] = sim.TendonLength(ids_.pin_dome_spring[i]);
  }
}

void TactileSensor::ReadContacts(Simulation& sim) {
  sim.ReadContacts(ids_.slot_of_geom, contacts_);
  for (int i = 0; i < n_; ++i) {
    const GeomContact& gc = contacts_[i];
    const double fn = Dot(gc.force_world, gc.normal_world);
    for (int k = 0; k < 3; ++k) tangential_[i][k] = gc.force_world[k] - fn * gc.normal_world[k];
    // On the cone as the friction rows hold it (see GeomContact::cone_use).
    samples_[i] = {gc.in_contact, gc.slip_speed_m_s, gc.in_contact ? gc.cone_use : 0.0};
  }
  labels_ = LabelFrame(samples_, spec_.labels, pin_contact_.data(), pin_slip_.data());
}

const PinFrame& TactileSensor::Capture(const Simulation& sim, double time_s) {
  pose_ = {sim.BodyPos(ids_.body), sim.BodyRot(ids_.body)};
  SensorReading& r = reading_;
  for (auto* v : {&r.pos_m, &r.pos_px, &r.external_m, &r.external_px, &r.normal_N, &r.tangential_N}) v->clear();
  CapturePins(sim);
  if (spec_.external.enabled) CaptureExternal(sim);
  CaptureContacts();
  FillFrame(time_s);
  return frame_;
}

void TactileSensor::CapturePins(const Simulation& sim) {
  // Pin inner ends in the sensor frame, as the pin bodies carry them.
  marker_m_.resize(n_);
  for (int i = 0; i < n_; ++i) {
    const auto p = pose_.Point(sim.SitePos(ids_.pin_site[i]));
    marker_shift_m_[i] = std::sqrt((p[0] - rest_marker_m_[i][0]) * (p[0] - rest_marker_m_[i][0]) +
                                   (p[1] - rest_marker_m_[i][1]) * (p[1] - rest_marker_m_[i][1]) +
                                   (p[2] - rest_marker_m_[i][2]) * (p[2] - rest_marker_m_[i][2]));
    marker_m_[i] = p;
  }
  MoveMarkersWithGel(sim);
  // A fingerprint ridge rocks under its tangential contact force (quasi-statically,
  // deflection f_t / k_rock at the contact point), which moves the inner marker the other
  // way. Then the image positions.
  image_gain_px_m_ = 0.0;
  for (int i = 0; i < n_; ++i) {
    auto& p = marker_m_[i];
    if (spec_.marker_rock_m_N > 0.0) {
      const auto fs = pose_.Vector(tangential_[i]);
      for (int k = 0; k < 3; ++k) p[k] -= spec_.marker_rock_m_N * fs[k];
    }
    for (int k = 0; k < 3; ++k) reading_.pos_m.push_back(static_cast<float>(p[k]));
    image_gain_px_m_ = std::max(image_gain_px_m_, camera_.ImageGain(p));
    const auto uv = camera_.Project(p);
    px_[2 * i] = static_cast<float>(uv[0]);
    px_[2 * i + 1] = static_cast<float>(uv[1]);
  }
  // What the tracker reports: noise and dropouts on the clean positions.
  clean_px_ = px_;
  noise_.Apply(px_, valid_, prev_px_);
  prev_px_ = px_;
  reading_.pos_px = px_;
  reading_.valid = valid_;
}

double TactileSensor::ColumnCompression(const Simulation& sim, int i) const {
  const int spring = static_cast<size_t>(i) < ids_.pin_dome_spring.size() ? ids_.pin_dome_spring[i] : -1;
  if (spring >= 0) return rest_dome_spring_m_[i] - sim.TendonLength(spring);
  return rest_marker_m_[i][0] - marker_m_[i][0];
}

void TactileSensor::MoveMarkersWithGel(const Simulation& sim) {
  // Each pin's gel column's compression squeezes gel sideways; the flow moves every
  // marker (GelField).
  if (spec_.gel_field.empty()) return;
  indentation_m_.resize(n_);
  for (int i = 0; i < n_; ++i) indentation_m_[i] = ColumnCompression(sim, i);
  spec_.gel_field.Shifts(indentation_m_, gel_shift_m_);
  for (int i = 0; i < n_; ++i) {
    for (int k = 0; k < 3; ++k) marker_m_[i][k] += gel_shift_m_[i][k];
  }
}

void TactileSensor::CaptureExternal(const Simulation& sim) {
  // External markers: the outer contact points, seen through the plate.
  for (int i = 0; i < n_; ++i) {
    const auto q = pose_.Point(sim.SitePos(ids_.pin_outer_site[i]));
    for (int k = 0; k < 3; ++k) reading_.external_m.push_back(static_cast<float>(q[k]));
    const auto uv = ext_camera_.Project(q);
    ext_px_[2 * i] = static_cast<float>(uv[0]);
    ext_px_[2 * i + 1] = static_cast<float>(uv[1]);
  }
  ext_noise_.Apply(ext_px_, ext_valid_, prev_ext_px_);
  prev_ext_px_ = ext_px_;
  reading_.external_px = ext_px_;
}

void TactileSensor::CaptureContacts() {
  // Contact forces (tangential in sensor y, z) and the stick/slip labels.
  for (int i = 0; i < n_; ++i) {
    normal_N_[i] = contacts_[i].normal_N;
    reading_.normal_N.push_back(static_cast<float>(contacts_[i].normal_N));
    const auto fts = pose_.Vector(tangential_[i]);
    reading_.tangential_N.push_back(static_cast<float>(fts[1]));
    reading_.tangential_N.push_back(static_cast<float>(fts[2]));
  }
  reading_.pin_contact = pin_contact_;
  reading_.pin_slip = pin_slip_;
  // Partial slip: some contacting pins slide while others stick.
  reading_.incipient = labels_.n_slip > 0 && labels_.n_slip < labels_.n_contact ? 1 : 0;
}

void TactileSensor::FillFrame(double time_s) {
  // The frame as hardware delivers it: reported positions, detections, external markers.
  frame_.time_s = time_s;
  frame_.pos_px.resize(n_, 2);
  frame_.valid.assign(valid_.begin(), valid_.end());
  for (int i = 0; i < n_; ++i) {
    frame_.pos_px(i, 0) = px_[2 * i];
    frame_.pos_px(i, 1) = px_[2 * i + 1];
  }
  if (!spec_.external.enabled) return;
  frame_.external_px.resize(n_, 2);
  for (int i = 0; i < n_; ++i) {
    frame_.external_px(i, 0) = ext_px_[2 * i];
    frame_.external_px(i, 1) = ext_px_[2 * i + 1];
  }
}

}  // namespace tactip
