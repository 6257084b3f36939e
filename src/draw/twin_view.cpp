#include "draw/twin_view.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "core/stage_log.hpp"
#include "draw/clip_layout.hpp"
#include "draw/draw_facts.hpp"
#include "draw/draw_style.hpp"
#include "draw/text_blocks.hpp"
#include "motion/frame_sampling.hpp"
#include "render/mesh_builders.hpp"
#include "spin/field.hpp"

namespace rollspin::draw {

using geometry::Vec3;

TwinView::TwinView(const scene::SceneSpec& spec, const model::RollingModel& model,
                   const std::shared_ptr<const motion::SceneFacts>& facts, const Vec3& markerBody,
                   std::shared_ptr<render::MeshData> dotMesh, FigureText figureText)
    : spec_(spec), figureText_(figureText), model_(model), markerBody_(markerBody), dotMesh_(std::move(dotMesh)) {
  StageLog::instance().record("twin-geometry");
  blochSphereMesh_ = render::uvSphere(64, 32);
  trailGridCount_ = motion::trailGrid(spec, model).count;
  if (facts && facts->phaseSplit) fieldConeMesh_ = coneMesh(facts->phaseSplit->fieldLoop);
}

namespace {
const glm::vec3 kTwinAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const char* const kTwinAxisNames[3] = {"x", "y", "z"};
}  // namespace

void TwinView::add(render::DrawList& list, const motion::FrameOrientations& frame, int view,
                   const CameraFraming::Aim& aim) const {
  render::View& v = list.views[static_cast<std::size_t>(view)];
  aimAtSphere(v, aim);
  addSphereAndAxes(list, view);
  addTrails(list, frame, view);
  addArrows(list, frame, view);
  if (spec_.render.labels) addLabels(list, v, view);
}

// The view's camera and light.
void TwinView::aimAtSphere(render::View& v, const CameraFraming::Aim& aim) const {
  // Same viewing direction as the ball's camera, so the marker on the ball
  // and the Bloch arrow point the same way on screen.
  const OrbitAngles a{aim.azimuth, aim.elevation};
  const double aspect = double(v.width) / double(std::max(v.height, 1));
  // A plain image frames the sphere, its axes and the labels at 1.3 of the
  // origin into the window. A figure (text set at a printed size, or larger
  // than an image's own share) draws the sphere as large as the window the
  // text leaves (its axes' ends at its edge) and sets the labels close
  // against the points they name (label_placement keeps them off the arrows).
  const double sceneRadius = closeLabels() ? kFigureSceneRadius : 1.42;
  // Framed into the window the text leaves free (the whole view by default).
  const Lens lens = windowLens(window_, aim.fovDeg, aspect);
  const double distance = fitDistance(sceneRadius, lens.fovDeg, lens.aspect);
  render::View oriented =
      orbitView(v.x, v.y, v.width, v.height, glm::vec3(0.0f, 0.0f, -0.04f), distance, a, aim.fovDeg, sceneRadius);
  if (!isWholeView(window_))
    oriented.camera.clipFromView =
        offAxisProjection(window_, aim.fovDeg, aspect, float(std::max(0.02 * distance, distance - 2.5 * sceneRadius)),
                          float(distance + 4.0 * sceneRadius));
  v.camera = oriented.camera;
  v.light = keyLight(glm::vec3(0, 0, 1), glm::normalize(v.camera.position), glm::vec3(0.0f), 1.5f);
  v.light.shadow = false;
  v.light.ambient = 0.45f;
  if (v.frame) {
    v.backgroundTop = glm::vec3(0.97f, 0.98f, 0.99f);
    v.backgroundBottom = glm::vec3(0.86f, 0.89f, 0.93f);
  }
}

// The glass Bloch sphere, its origin, the equator and two meridians, and
// the axes.
void TwinView::addSphereAndAxes(render::DrawList& list, int view) const {
  const auto& blochSphere = blochSphereMesh_;
  list.meshes.push_back({blochSphere, glm::mat4(1.0f), glassMaterial({0.62f, 0.76f, 0.95f}, 0.16f, 0.5f, 90.0f), view});
  list.meshes.back().sphere = true;
  render::Material origin;
  origin.color = {0.2f, 0.2f, 0.22f};
  list.meshes.push_back({dotMesh_, glm::scale(glm::mat4(1.0f), glm::vec3(0.035f)), origin, view});
  list.meshes.back().sphere = true;

  const glm::vec4 gridColor = opaqueLine({0.30f, 0.36f, 0.45f}, 0.75f);
  const float gridWidth = std::max(1.0f, float(list.height) / 600.0f);
  for (int circle = 0; circle < 3; ++circle) {
    render::PolylineItem c;
    c.color = gridColor;
    c.widthPx = gridWidth;
    c.view = view;
    for (int i = 0; i <= 180; ++i) {
      const float t = 2.0f * std::numbers::pi_v<float> * float(i) / 180.0f;
      const float x = std::cos(t), y = std::sin(t);
      c.points.push_back(circle == 0 ? glm::vec3(x, y, 0) : circle == 1 ? glm::vec3(x, 0, y) : glm::vec3(0, x, y));
    }
    list.polylines.push_back(c);
  }
  for (int k = 0; k < 3; ++k) {
    render::PolylineItem axis;
    axis.color = opaqueLine({0.15f, 0.17f, 0.2f}, 0.9f);
    axis.widthPx = gridWidth;
    axis.view = view;
    axis.points = {-kAxisLength * kTwinAxes[k], kAxisLength * kTwinAxes[k]};
    // A figure's labels, set close, keep off the axes too (not the grid).
    axis.labelsKeepOff = closeLabels();
    list.polylines.push_back(axis);
  }
}

Vec3 TwinView::fieldDirection(double s) const {
  const Vec3 b = spin::fieldB(model_.path->at(s), model_.ballRadius);
  return b.norm() > 1e-12 ? Vec3(b.normalized()) : Vec3(Vec3::Zero());
}

// Trails: the Bloch vector X(s') = Q(s') X(0) and the field direction; the
// cone the field direction sweeps.
void TwinView::addTrails(render::DrawList& list, const motion::FrameOrientations& frame, int view) const {
  render::PolylineItem blochTrail, fieldTrail;
  blochTrail.color = kBlochTrailColor;
  fieldTrail.color = kFieldTrailColor;
  blochTrail.widthPx = fieldTrail.widthPx = std::max(1.5f, float(list.height) / 360.0f);
  blochTrail.view = fieldTrail.view = view;
  blochTrail.labelsKeepOff = fieldTrail.labelsKeepOff = true;
  // The trail's points but the last lie on the trail grid (frame_sampling.hpp).
  const std::size_t settled =
      settledPoints(frame.trail.size() - std::min<std::size_t>(1, frame.trail.size()), trailGridCount_);
  std::size_t fieldSettled = 0;
  for (std::size_t i = 0; i < frame.trail.size(); ++i) {
    const auto& t = frame.trail[i];
    blochTrail.points.push_back(toGlm(t.q.rotate(markerBody_)));
    const Vec3 b = fieldDirection(t.s);
    if (b.norm() > 0.5) {
      fieldTrail.points.push_back(toGlm(b));
      if (i < settled) fieldSettled = fieldTrail.points.size();
    }
  }
  addGrowingLine(list, fieldTrail, fieldSettled);
  addGrowingLine(list, blochTrail, settled);
  if (fieldConeMesh_) {
    // The cone B̂ sweeps over the whole circuit: its solid angle is Berry's phase.
    render::Material cone;
    cone.color = kFieldColor;
    cone.opacity = 0.18f;
    cone.lit = false;
    cone.castsShadow = false;
    cone.cull = render::Cull::None;
    list.meshes.push_back({fieldConeMesh_, glm::mat4(1.0f), cone, view});
  }
}

// The Bloch vector and the field direction now (a strobe's Bloch vectors
// paler).
void TwinView::addArrows(render::DrawList& list, const motion::FrameOrientations& frame, int view) const {
  const float arrowRadius = 0.028f;
  const Vec3 x = frame.current.q.rotate(markerBody_);
  list.arrows.push_back({glm::vec3(0.0f), toGlm(x), arrowRadius, kMarkerColor, view, true});
  const Vec3 b = fieldDirection(frame.current.s);
  if (b.norm() > 0.5) list.arrows.push_back({glm::vec3(0.0f), toGlm(b), arrowRadius * 0.8f, kFieldColor, view, true});
  for (const auto& pose : frame.strobe)
    list.arrows.push_back({glm::vec3(0.0f), toGlm(pose.q.rotate(markerBody_)), arrowRadius * 0.55f,
                           glm::mix(kMarkerColor, glm::vec3(1.0f), 0.35f), view});
}

// The axes' names and the poles' states.
void TwinView::addLabels(render::DrawList& list, const render::View& v, int view) const {
  const float text = bodyTextPx(list.width, list.height, spec_.render.fontScale);
  auto worldLabel = [&](const std::string& s, const glm::vec3& at, float size, glm::vec4 color) {
    render::LabelItem l;
    l.view = view;
    l.text = s;
    l.anchor = at;
    l.worldAnchored = true;
    l.align = render::Align::Center;
    l.sizePx = size;
    l.color = color;
    list.labels.push_back(l);
  };
  if (closeLabels()) {
    // Each axis name at its axis's end, pushed out along the projected
    // axis by its own half size and a little: against the line's tip.
    const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
    auto pixel = [&](const glm::vec3& p) {
      const glm::vec4 c = clipFromWorld * glm::vec4(p, 1.0f);
      return glm::vec2(c.x / c.w * 0.5f * float(v.width), -c.y / c.w * 0.5f * float(v.height));
    };
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 end = kAxisLength * kTwinAxes[k];
      worldLabel(kTwinAxisNames[k], end, text, kTextColor);
      const glm::vec2 along = pixel(end) - pixel(glm::vec3(0.0f));
      const float length = glm::length(along);
      if (length > 1e-3f) list.labels.back().offsetPx = 0.75f * text * along / length;
    }
  } else {
    for (int k = 0; k < 3; ++k) worldLabel(kTwinAxisNames[k], 1.3f * kTwinAxes[k], text, kTextColor);
  }
  // The poles' states beside them, to the right.
  const float poleOffset = closeLabels() ? 1.25f : 1.6f;
  worldLabel("|0⟩", glm::vec3(0, 0, 1.0f), text, kTextColor);
  worldLabel("|1⟩", glm::vec3(0, 0, -1.0f), text, kTextColor);
  list.labels.back().offsetPx = glm::vec2(poleOffset * text, 0.0f);
  list.labels[list.labels.size() - 2].offsetPx = glm::vec2(poleOffset * text, 0.0f);
}

bool TwinView::closeLabels() const { return spec_.render.fontScale > 1.0 || figureText_.figure(); }

std::vector<TextBlock> TwinView::textBlocks(bool inset, float text, float maxWidth) const {
  std::vector<TextBlock> blocks(2);
  if (!spec_.render.labels || inset) return blocks;  // an inset is too small for a heading or a legend
  blocks[0].slots = {Slot::TopLeft, Slot::TopRight};
  blocks[0].lines.push_back({"Bloch sphere", text * 1.1f, true, kTextColor, false});
  blocks[0].keep = 0;  // where the sphere needs the room, the heading goes first
  blocks[0].givesWay = 0;
  blocks[1].slots = {Slot::BottomLeft, Slot::BottomRight};
  blocks[1].keep = 1;
  if (compactText(int(spec_.render.width), int(spec_.render.height))) {
    // Narrow: the two entries share one band, one in each bottom corner.
    blocks[1].slots = {Slot::BottomLeft};
    blocks[1].lines.push_back({"● spin X(s)", text, false, glm::vec4(kMarkerColor, 1.0f), false});
    TextBlock field;
    field.slots = {Slot::BottomRight};
    field.keep = 1;
    field.lines.push_back({"● field B/|B|", text, false, glm::vec4(kFieldColor, 1.0f), false});
    blocks.push_back(field);
    return blocks;
  }
  // The spin's formula where a line holds it, else its name alone.
  const std::string spin = "● spin  X(s) = Q(s) X(0)";
  const bool formula = textWidthPx(spin, text, false) + 2.0f * kBlockPad * text <= maxWidth;
  blocks[1].lines.push_back({formula ? spin : "● spin X(s)", text, false, glm::vec4(kMarkerColor, 1.0f), false});
  blocks[1].lines.push_back({"● field  B/|B|", text, false, glm::vec4(kFieldColor, 1.0f), false});
  return blocks;
}

void TwinView::markImportant(Occupancy& occupancy, const render::View& v) const {
  // Everything the twin shows lies within the axes' labels at 1.3 of the
  // origin (a figure's: the axes' ends): the sphere, the arrows, the
  // trails, the cone.
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  const glm::vec4 c = clipFromWorld * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  const glm::vec2 centre((c.x / c.w * 0.5f + 0.5f) * float(v.width), (0.5f - c.y / c.w * 0.5f) * float(v.height));
  const float focalPx = 0.5f * float(v.height) * v.camera.clipFromView[1][1];
  // (A figure's labels lie against the axes' ends: the disc the camera frames.)
  const float reach = closeLabels() ? kAxisLength : 1.3f;
  occupancy.disc(centre, reach * focalPx / std::sqrt(c.w * c.w - reach * reach) + 4.0f);
}

}  // namespace rollspin::draw
