#include "sim/scene_draw.h"

#include <algorithm>

namespace tactip {

namespace {

// Room in the abstract scene: every model geom plus decorations (contact force arrows,
// two per contact when split) with a wide margin.
int SceneCapacity(const mjModel* m) { return 1000 + 2 * m->ngeom + 4 * m->nconmax; }

}  // namespace

SceneDraw::SceneDraw(const CompiledModel& model, int offscreen_width, int offscreen_height)
    : model_(mj_copyModel(nullptr, model.raw())) {
  mjModel* m = model_.get();
  default_force_scale_ = m->vis.map.force;
  // The offscreen buffer is sized from the model's visual settings when the context is made.
  m->vis.global.offwidth = offscreen_width;
  m->vis.global.offheight = offscreen_height;
  mjv_defaultScene(&scene_);
  mjv_makeScene(m, &scene_, SceneCapacity(m));
  mjv_defaultOption(&option_);
  mjv_defaultFreeCamera(m, &camera_);
  mjr_defaultContext(&context_);
  mjr_makeContext(m, &context_, mjFONTSCALE_150);
}

SceneDraw::~SceneDraw() {
  mjr_freeContext(&context_);
  mjv_freeScene(&scene_);
}

void SceneDraw::SetView(const CameraView& view) {
  // A free camera framing the model's extent, then the view's own pose.
  mjv_defaultFreeCamera(model_.get(), &camera_);
  if (view.distance_m > 0.0) camera_.distance = view.distance_m;
  camera_.azimuth = view.azimuth_deg;
  camera_.elevation = view.elevation_deg;
  follow_ = view.look_at_bodies;
}

void SceneDraw::Orbit(double dx, double dy) {
  mjv_moveCamera(model_.get(), mjMOUSE_ROTATE_V, dx, dy, &scene_, &camera_);
}

void SceneDraw::Zoom(double dy) { mjv_moveCamera(model_.get(), mjMOUSE_ZOOM, 0.0, dy, &scene_, &camera_); }

void SceneDraw::FollowBodies(const mjData* d) {
  // Look at the mean position of the followed bodies.
  if (follow_.empty()) return;
  mjtNum centre[3] = {0, 0, 0};
  for (int b : follow_) mju_addTo3(centre, d->xpos + 3 * b);
  mju_scl3(camera_.lookat, centre, 1.0 / static_cast<double>(follow_.size()));
}

void SceneDraw::Draw(const Simulation& sim, const RenderOptions& options, mjrRect viewport) {
  mjModel* m = model_.get();
  // mjv_updateScene only reads the state (it counts a VGEOMFULL warning in mjData when the
  // scene is full, which SceneCapacity avoids and Simulation ignores).
  mjData* d = const_cast<mjData*>(sim.raw());
  // MuJoCo draws a force F as an arrow F * map.force / meanmass long.
  m->vis.map.force = options.force_scale_m_N > 0.0 ? options.force_scale_m_N * m->stat.meanmass : default_force_scale_;
  option_.flags[mjVIS_CONTACTFORCE] = options.contact_forces ? 1 : 0;
  FollowBodies(d);
  mjv_updateScene(m, d, &option_, nullptr, &camera_, mjCAT_ALL, &scene_);
  ApplyOverrides(options);
  mjr_render(viewport, &scene_, &context_);
}

void SceneDraw::ApplyOverrides(const RenderOptions& options) {
  // Per-geom lookups for this frame.
  const auto n = static_cast<size_t>(model_->ngeom);
  colour_of_geom_.assign(n, nullptr);
  hidden_.assign(n, 0);
  for (const GeomColour& c : options.colours) {
    if (c.geom >= 0 && static_cast<size_t>(c.geom) < n) colour_of_geom_[c.geom] = &c.rgba;
  }
  for (int g : options.hidden_geoms) {
    if (g >= 0 && static_cast<size_t>(g) < n) hidden_[g] = 1;
  }
  // Recolour the model geoms in the scene and drop the hidden ones.
  int kept = 0;
  for (int i = 0; i < scene_.ngeom; ++i) {
    mjvGeom& g = scene_.geoms[i];
    const bool model_geom = g.objtype == mjOBJ_GEOM && g.objid >= 0 && static_cast<size_t>(g.objid) < n;
    if (model_geom && hidden_[g.objid]) continue;
    if (model_geom && colour_of_geom_[g.objid]) std::copy_n(colour_of_geom_[g.objid]->begin(), 4, g.rgba);
    scene_.geoms[kept++] = g;
  }
  scene_.ngeom = kept;
}

void SceneDraw::UseBuffer(int framebuffer) { mjr_setBuffer(framebuffer, &context_); }

RgbImage SceneDraw::Read(mjrRect viewport) const {
  // OpenGL returns the bottom row first; flip to top-first.
  RgbImage image;
  image.width = viewport.width;
  image.height = viewport.height;
  const size_t row = 3 * static_cast<size_t>(viewport.width);
  std::vector<unsigned char> bottom_up(row * static_cast<size_t>(viewport.height));
  mjr_readPixels(bottom_up.data(), nullptr, viewport, &context_);
  image.rgb.resize(bottom_up.size());
  for (int y = 0; y < viewport.height; ++y) {
    std::copy_n(bottom_up.data() + row * static_cast<size_t>(viewport.height - 1 - y), row,
                image.rgb.data() + row * static_cast<size_t>(y));
  }
  return image;
}

void SceneDraw::Overlay(mjrRect viewport, const std::string& text) {
  mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport, text.c_str(), nullptr, &context_);
}

}  // namespace tactip
