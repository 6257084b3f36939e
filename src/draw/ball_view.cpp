#include "draw/ball_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include <glm/gtc/matrix_transform.hpp>

#include "core/stage_log.hpp"
#include "draw/clip_layout.hpp"
#include "draw/draw_facts.hpp"
#include "draw/draw_style.hpp"
#include "draw/surface_looks.hpp"
#include "draw/text_blocks.hpp"
#include "render/mesh_builders.hpp"
#include "render/procedural_textures.hpp"

namespace rollspin::draw {

using geometry::Vec3;
using motion::FrameOrientations;
using motion::MarksFact;
using motion::OrientedSample;

BallView::BallView(const scene::SceneSpec& spec, const model::RollingModel& model,
                   std::shared_ptr<const render::TextureImage> ballTexture,
                   std::shared_ptr<const motion::SceneFacts> facts, const Vec3& markerBody,
                   std::shared_ptr<render::MeshData> dotMesh, FigureText figureText)
    : spec_(spec),
      figureText_(figureText),
      model_(model),
      markerBody_(markerBody),
      ballTexture_(std::move(ballTexture)),
      facts_(std::move(facts)),
      dotMesh_(std::move(dotMesh)) {
  const double R = model.ballRadius;
  const double length = model.path->length();
  const int samples = 1 + static_cast<int>(std::clamp(480.0 * std::max(1.0, model.path->turns()), 480.0, 20000.0));
  SweptBox box;
  for (int i = 0; i < samples; ++i) {
    const double s = length * i / (samples - 1);
    const geometry::DarbouxSample f = model.path->at(s);
    pathS_.push_back(s);
    pathPoints_.push_back(f.point);
    const Vec3 c = f.centre(R);
    if (i % std::max(1, samples / 240) == 0) extent_.points.push_back(c);
    box.lo = box.lo.cwiseMin(c - Vec3::Constant(R));
    box.hi = box.hi.cwiseMax(c + Vec3::Constant(R));
  }
  centrePoints_ = extent_.points.size();
  const bool layoutShowsBall = spec.render.layout != scene::RenderLayout::Twin;
  if (!layoutShowsBall) return;  // the twin needs none of the surface geometry
  StageLog::instance().record("surface-mesh");
  if (!ballTexture_) ballTexture_ = render::tennisBallTexture();

  // Small triangles are costly on llvmpipe (each shades whole 4×4 blocks):
  // 64 segments keep the silhouette within 0.2 px of a circle up to 1440p.
  trailGridCount_ = motion::trailGrid(spec, model).count;
  sphereMesh_ = spec.render.height > 1440 ? render::uvSphere(96, 48) : render::uvSphere(64, 32);

  // Each surface says how it is shown (geometry::SurfaceLook): a board, a
  // whole sphere, or its own chart.
  const geometry::SurfaceLook look = model.surface ? model.surface->look() : geometry::SurfaceLook{};
  SurfaceAsDrawn shape{nullptr, matteCheckerMaterial(), box, {}, {}, {}, {}};
  if (model.surface && look.mesh == geometry::SurfaceLook::Mesh::Board) shape = boardSurface(look, box, R);
  else if (model.surface && look.mesh == geometry::SurfaceLook::Mesh::Sphere)
    shape = sphereSurface(look, box, spec, model, pathPoints_);
  else if (model.surface) shape = chartSurface(*model.surface, box, R, pathPoints_, extent_.points);
  surfaceIsBoard_ = !model.surface || look.mesh == geometry::SurfaceLook::Mesh::Board;
  surfaceMesh_ = std::move(shape.mesh);
  surfaceMaterial_ = shape.material;
  cutRim_ = std::move(shape.cutRim);
  framedEdges_ = std::move(shape.framedEdges);
  extent_.outline = std::move(shape.outline);
  for (const Vec3& p : shape.framedPoints) {
    extent_.points.push_back(p);
    surfacePoints_.push_back(extent_.points.size() - 1);
  }
  box = shape.box;
  if (model.plate) framePlate(box.lo, box.hi);
  extent_.centre = 0.5 * (box.lo + box.hi);
  extent_.radius = 0.5 * (box.hi - box.lo).norm();
  // A curved surface can stand between the eye and the ball: the camera
  // tests sight lines against it as drawn (a plane's board lies under the
  // ball and hides nothing).
  if (surfaceMesh_ && look.canHideBall) {
    const glm::vec4 cut = surfaceMaterial_.cutPlane;
    extent_.surface = std::make_shared<SightLines>(*surfaceMesh_, Eigen::Vector4d(cut.x, cut.y, cut.z, cut.w));
  }
}

// Brockett's plate translates with the top point: on a plane the top moves
// contactSpeedRatio (= 2) times as fast as the contact point, so the plate
// point above the circle's centre-opposite point traces the circle of
// radius R1 about the contact circle's centre.
void BallView::framePlate(Vec3& lo, Vec3& hi) {
  const double R = model_.ballRadius;
  const double length = model_.path->length();
  const geometry::DarbouxSample start = model_.path->at(0.0);
  discMesh_ = render::unitCylinder(96);
  const double kg = start.geodesicCurvature;
  plateCircleCentre_ = std::abs(kg) > 1e-12 ? Vec3(start.point + start.tangentNormal / kg) : Vec3(start.point);
  hi = hi.cwiseMax(model_.plate->initialTopPoint + 0.2 * R * start.normal.cwiseAbs());
  const std::size_t pathFramePoints = extent_.points.size();
  for (std::size_t i = 0; i < pathFramePoints; ++i)
    extent_.points.push_back(extent_.points[i] + 1.2 * R * start.normal);
  // The glass disc reaches beyond the path (the plate's marked point
  // circles at R1 = 2r): its rim, wherever the plate moves, must stay in
  // frame and inside the far plane.
  for (int i = 0; i < 24; ++i) {
    const double s = length * i / 24.0;
    const geometry::DarbouxSample f = model_.path->at(s);
    const Vec3 e1 = geometry::defaultTangentFor(f.normal), e2 = f.normal.cross(e1);
    const auto [centre, radius] = plateDisc(s);
    for (int k = 0; k < 16; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / 16.0;
      const Vec3 p = centre + radius * (std::cos(phi) * e1 + std::sin(phi) * e2) + 0.1 * R * f.normal;
      extent_.points.push_back(p);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
}

namespace {

// Where the scalar field `value` (given per vertex, linear along edges)
// is zero on a mesh: its crossings of the triangles chained into polylines
// through the edges they share (a parametric patch's seam, whose vertices
// are doubled, ends a polyline).
std::vector<std::vector<Vec3>> zeroSet(const render::MeshData& mesh, const std::vector<double>& value) {
  auto at = [&](std::uint32_t i) {
    const glm::vec3& p = mesh.vertices[i].position;
    return Vec3(p.x, p.y, p.z);
  };
  struct Crossing {
    std::uint64_t edge[2];
    Vec3 point[2];
  };
  std::vector<Crossing> crossings;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> byEdge;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    Crossing c{};
    int found = 0;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = mesh.indices[t + std::size_t(e)], b = mesh.indices[t + std::size_t((e + 1) % 3)];
      const double va = value[a], vb = value[b];
      if ((va < 0.0) == (vb < 0.0) || found == 2) continue;
      c.edge[found] = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      c.point[found] = at(a) + (va / (va - vb)) * (at(b) - at(a));
      ++found;
    }
    if (found != 2) continue;
    for (const std::uint64_t e : c.edge) byEdge[e].push_back(crossings.size());
    crossings.push_back(c);
  }
  // Walk from each unused crossing both ways along shared edges.
  std::vector<char> used(crossings.size(), 0);
  std::vector<std::vector<Vec3>> lines;
  for (std::size_t first = 0; first < crossings.size(); ++first) {
    if (used[first]) continue;
    used[first] = 1;
    std::vector<Vec3> halves[2];
    for (int way = 0; way < 2; ++way) {
      std::uint64_t edge = crossings[first].edge[way];
      halves[way].push_back(crossings[first].point[way]);
      for (;;) {
        std::size_t next = crossings.size();
        for (const std::size_t k : byEdge[edge])
          if (!used[k]) next = k;
        if (next == crossings.size()) break;
        used[next] = 1;
        const int exit = crossings[next].edge[0] == edge ? 1 : 0;
        edge = crossings[next].edge[exit];
        halves[way].push_back(crossings[next].point[exit]);
      }
    }
    std::vector<Vec3> line(halves[0].rbegin(), halves[0].rend());
    line.insert(line.end(), halves[1].begin(), halves[1].end());
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace

// The porthole opens as the sight lines (finer than the camera search's,
// so that it opens smoothly) find the ball hidden: from 99.5 % of its disc
// seen, where it starts as a point, to 93 % seen, where its radius at the
// ball is kPortholeRadius R (the ball's whole disc, and a ring of what lies
// behind it); seen from the eye it is a disc about the ball.
render::Material BallView::cutTowardEye(const Vec3& eye, const Vec3& centre,
                                        std::vector<std::vector<Vec3>>& rim) const {
  render::Material material = surfaceMaterial_;
  if (!extent_.surface || !surfaceMesh_) return material;
  const double R = model_.ballRadius;
  const double share = extent_.surface->visibleShare(eye, centre, R, 97);
  const double x = std::clamp((0.995 - share) / (0.995 - 0.93), 0.0, 1.0);
  const double open = x * x * (3.0 - 2.0 * x);
  if (open <= 0.0) return material;
  constexpr double kPortholeRadius = 1.8;
  const double radius = open * kPortholeRadius * R;
  material.cutCone = glm::vec4(toGlm(centre), float(radius));
  // Its rim: where max(distance inside the cone's wall, depth past the
  // ball's centre) is zero on the surface (mesh.frag cuts where both are
  // negative).
  const Vec3 axis = centre - eye;
  const double length = axis.norm();
  std::vector<double> value(surfaceMesh_->vertices.size());
  for (std::size_t i = 0; i < value.size(); ++i) {
    const glm::vec3& p = surfaceMesh_->vertices[i].position;
    const Vec3 q = Vec3(p.x, p.y, p.z) - eye;
    const double along = q.dot(axis) / length;
    const double inside = (q - along * axis / length).norm() - radius * along / length;
    value[i] = std::max(inside, along - length);
  }
  rim = zeroSet(*surfaceMesh_, value);
  return material;
}

void BallView::add(render::DrawList& list, const FrameOrientations& frame, int view,
                   const std::optional<Vec3>& cutAwayFrom) const {
  const double s = frame.current.s;
  addSurface(list, s, view, cutAwayFrom);
  addPath(list, s, view);
  if (frame.strobe.empty()) {
    addBall(list, frame.current, view);
  } else {
    for (const auto& pose : frame.strobe) addBall(list, pose, view);
  }
  addMarkerTrail(list, frame, view);
  if (model_.plate && frame.strobe.empty()) addPlate(list, s, view);
  if (facts_ && facts_->marks) addMarks(list, s, frame.strobe.empty(), view);
}

// The surface, cut away toward `cutAwayFrom` where it hides the ball, with
// the rims of its cuts.
void BallView::addSurface(render::DrawList& list, double s, int view, const std::optional<Vec3>& cutAwayFrom) const {
  const double R = model_.ballRadius;
  if (surfaceMesh_) {
    std::vector<std::vector<Vec3>> rims;
    const render::Material material =
        cutAwayFrom ? cutTowardEye(*cutAwayFrom, model_.path->at(s).centre(R), rims) : surfaceMaterial_;
    list.meshes.push_back({surfaceMesh_, glm::mat4(1.0f), material, view});
    for (const std::vector<Vec3>& line : rims) {
      render::PolylineItem rim;  // the cut's edge, as inside a sphere
      rim.color = glm::vec4(0.25f, 0.27f, 0.30f, 1.0f);
      rim.widthPx = std::max(1.2f, float(list.height) / 450.0f);
      rim.view = view;
      rim.dynamic = true;
      for (const Vec3& p : line) rim.points.push_back(toGlm(p));
      list.polylines.push_back(std::move(rim));
    }
  }
  if (!cutRim_.empty()) {
    render::PolylineItem rim;
    rim.color = glm::vec4(0.25f, 0.27f, 0.30f, 1.0f);
    rim.widthPx = std::max(1.2f, float(list.height) / 450.0f);
    rim.view = view;
    for (const Vec3& p : cutRim_) rim.points.push_back(toGlm(p));
    list.polylines.push_back(rim);
  }
}

// The contact path, lifted a hair along the normal; travelled part on top.
void BallView::addPath(render::DrawList& list, double s, int view) const {
  const double R = model_.ballRadius;
  render::PolylineItem full, travelled;
  full.color = kPathLineColor;
  full.widthPx = std::max(1.5f, float(list.height) / 400.0f);
  travelled.color = kTravelledColor;
  travelled.widthPx = std::max(2.5f, float(list.height) / 200.0f);
  full.view = travelled.view = view;
  full.labelsKeepOff = travelled.labelsKeepOff = true;
  for (std::size_t i = 0; i < pathS_.size(); ++i) {
    const Vec3 p = pathPoints_[i] + 0.004 * R * model_.path->normal(pathS_[i]);
    full.points.push_back(toGlm(p));
    if (pathS_[i] <= s) travelled.points.push_back(toGlm(p));
  }
  const std::size_t travelledSettled = settledPoints(travelled.points.size(), pathS_.size());
  travelled.points.push_back(toGlm(model_.path->point(s) + 0.004 * R * model_.path->normal(s)));
  list.polylines.push_back(full);
  addGrowingLine(list, travelled, travelledSettled);  // grows with s
}

// A ball at `pose`: texture in body coordinates, rotated by worldFromBody,
// and its marker dot.
void BallView::addBall(render::DrawList& list, const OrientedSample& pose, int view) const {
  const double R = model_.ballRadius;
  render::Material ballMaterial;
  ballMaterial.pattern = render::Pattern::Texture;
  ballMaterial.texture = ballTexture_;
  ballMaterial.color = glm::vec3(1.0f);
  ballMaterial.specular = 0.12f;
  ballMaterial.shininess = 24.0f;
  render::Material markerMaterial;
  markerMaterial.color = kMarkerColor;
  markerMaterial.specular = 0.5f;
  markerMaterial.shininess = 80.0f;
  const Vec3 c = model_.path->at(pose.s).centre(R);
  const glm::mat4 worldFromBody = rotationOf(pose.q);
  list.meshes.push_back(
      {sphereMesh_,
       glm::translate(glm::mat4(1.0f), toGlm(c)) * worldFromBody * glm::scale(glm::mat4(1.0f), glm::vec3(float(R))),
       ballMaterial, view});
  list.meshes.back().dynamic = true;
  list.meshes.back().sphere = true;
  const Vec3 marker = c + 0.97 * R * pose.q.rotate(markerBody_);
  list.meshes.push_back(
      {dotMesh_,
       glm::translate(glm::mat4(1.0f), toGlm(marker)) * glm::scale(glm::mat4(1.0f), glm::vec3(float(0.13 * R))),
       markerMaterial, view});
  list.meshes.back().dynamic = true;
  list.meshes.back().sphere = true;
}

// The marker's path through space: cusps where it touches the surface.
void BallView::addMarkerTrail(render::DrawList& list, const FrameOrientations& frame, int view) const {
  const double R = model_.ballRadius;
  if (frame.trail.size() >= 2) {
    render::PolylineItem markerTrail;
    markerTrail.color = kMarkerTrailColor;
    markerTrail.widthPx = std::max(1.5f, float(list.height) / 360.0f);  // no hairline: ~3 px at 1080p
    markerTrail.view = view;
    markerTrail.labelsKeepOff = true;
    for (const auto& t : frame.trail)
      markerTrail.points.push_back(toGlm(model_.path->at(t.s).centre(R) + R * t.q.rotate(markerBody_)));
    // All its points but the last lie on the trail grid.
    addGrowingLine(list, markerTrail, settledPoints(frame.trail.size() - 1, trailGridCount_));
  }
}

// Brockett's plate at s: the glass disc and its rim, the plate's marker
// dot and the trail it has drawn so far.
void BallView::addPlate(render::DrawList& list, double s, int view) const {
  const double R = model_.ballRadius;
  const geometry::DarbouxSample f = model_.path->at(s);
  const double thickness = 0.08 * R;
  // The plate point above the circle's far side traces the circle of
  // radius R1 = ratio · r about the contact circle's centre.
  const Vec3 plateCentre = platePoint(s, 0.0);
  const auto [discCentre, discRadius] = plateDisc(s);
  const glm::vec3 n = toGlm(f.normal);
  const glm::vec3 e1 = toGlm(geometry::defaultTangentFor(f.normal)), e2 = glm::cross(n, e1);
  glm::mat4 disc(1.0f);
  disc[0] = glm::vec4(e1 * float(discRadius), 0.0f);
  disc[1] = glm::vec4(e2 * float(discRadius), 0.0f);
  disc[2] = glm::vec4(n * float(thickness), 0.0f);
  disc[3] = glm::vec4(toGlm(discCentre), 1.0f);
  list.meshes.push_back({discMesh_, disc, glassMaterial({0.55f, 0.80f, 0.95f}, 0.14f, 0.9f, 120.0f), view});
  list.meshes.back().dynamic = true;  // the plate moves with the ball
  render::PolylineItem rim;           // the glass edge, so the plate reads as a sheet
  rim.color = opaqueLine({0.85f, 0.95f, 1.0f}, 0.9f);
  rim.widthPx = std::max(1.2f, float(list.height) / 450.0f);
  rim.view = view;
  rim.dynamic = true;
  for (int k = 0; k <= 128; ++k) {
    const float phi = 2.0f * std::numbers::pi_v<float> * float(k) / 128.0f;
    rim.points.push_back(glm::vec3(disc * glm::vec4(std::cos(phi), std::sin(phi), 1.0f, 1.0f)));
  }
  list.polylines.push_back(rim);
  // The plate's own marker: a dot at its centre, and the circle it traces.
  render::Material dot;
  dot.color = kPlateColor;
  glm::mat4 dotModel(1.0f);
  dotModel[0] = glm::vec4(e1 * float(0.12 * R), 0.0f);
  dotModel[1] = glm::vec4(e2 * float(0.12 * R), 0.0f);
  dotModel[2] = glm::vec4(n * float(0.02 * R), 0.0f);
  dotModel[3] = glm::vec4(toGlm(plateCentre + thickness * f.normal), 1.0f);
  list.meshes.push_back({discMesh_, dotModel, dot, view});
  list.meshes.back().dynamic = true;
  render::PolylineItem plateTrail;
  plateTrail.color = kPlateTrailColor;
  plateTrail.widthPx = std::max(1.2f, float(list.height) / 450.0f);
  plateTrail.view = view;
  plateTrail.labelsKeepOff = true;
  for (std::size_t i = 0; i < pathS_.size(); ++i) {
    if (pathS_[i] > s) break;
    plateTrail.points.push_back(toGlm(platePoint(pathS_[i], thickness * 1.05)));
  }
  addGrowingLine(list, plateTrail, settledPoints(plateTrail.points.size(), pathS_.size()));
}

Vec3 BallView::platePoint(double s, double lift) const {
  const geometry::DarbouxSample f = model_.path->at(s);
  return plateCircleCentre_ + model_.plate->contactSpeedRatio * (f.point - plateCircleCentre_) +
         (2.0 * model_.ballRadius + lift) * f.normal;
}

// Centred between the marked point and the ball's top (the plate is an
// unbounded plane; a disc around both keeps the picture, and its framing,
// as small as they can be), with a margin of 0.8 R.
std::pair<Vec3, double> BallView::plateDisc(double s) const {
  const geometry::DarbouxSample f = model_.path->at(s);
  const Vec3 marked = platePoint(s, 0.0);
  const Vec3 top = f.point + 2.0 * model_.ballRadius * f.normal;
  return {0.5 * (marked + top), 0.5 * (marked - top).norm() + 0.8 * model_.ballRadius};
}

// The marks every β of path angle: dots on the contact path (dark once
// passed) and, where the plate is drawn (not in a strobe), on its trail;
// numbered.
void BallView::addMarks(render::DrawList& list, double s, bool plateShown, int view) const {
  const double R = model_.ballRadius;
  const float text = bodyTextPx(list.width, list.height, spec_.render.fontScale);
  const MarksFact& m = *facts_->marks;
  const int passed = facts_->marksPassed(s);
  // Labels are drawn over everything: leave out a number the ball hides
  // (its segment from the eye to the mark passes through the ball).
  const Vec3 eye(list.views[static_cast<std::size_t>(view)].camera.position.x,
                 list.views[static_cast<std::size_t>(view)].camera.position.y,
                 list.views[static_cast<std::size_t>(view)].camera.position.z);
  const Vec3 ball = model_.path->at(s).centre(R);
  auto hiddenByBall = [&](const Vec3& p) {
    const Vec3 d = p - eye;
    const double t = std::clamp((ball - eye).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (eye + t * d - ball).norm() < R && t < 1.0;
  };
  for (std::size_t k = 0; k < m.s.size(); ++k) {
    const bool done = int(k) < passed;
    render::Material dot;
    dot.color = done ? glm::vec3(0.05f, 0.05f, 0.08f) : glm::vec3(0.45f, 0.45f, 0.5f);
    dot.castsShadow = false;
    const geometry::DarbouxSample f = model_.path->at(m.s[k]);
    const Vec3 onPath = f.point + 0.02 * R * f.normal;
    list.meshes.push_back(
        {dotMesh_,
         glm::translate(glm::mat4(1.0f), toGlm(onPath)) * glm::scale(glm::mat4(1.0f), glm::vec3(float(0.06 * R))), dot,
         view});
    list.meshes.back().figureDisc = true;  // a vector disc in PDF/SVG figures
    list.meshes.back().sphere = true;
    if (model_.plate && plateShown && done) {
      const Vec3 onPlate = platePoint(m.s[k], 0.06 * R);
      list.meshes.push_back(
          {dotMesh_,
           glm::translate(glm::mat4(1.0f), toGlm(onPlate)) * glm::scale(glm::mat4(1.0f), glm::vec3(float(0.05 * R))),
           dot, view});
      list.meshes.back().figureDisc = true;
      list.meshes.back().sphere = true;
    }
    if (!spec_.render.labels || (plateShown && hiddenByBall(onPath))) continue;
    render::LabelItem number;
    number.view = view;
    number.text = fmt::format("{}", k);
    // Outward from the circle's centre, so the number sits beside the path.
    // Outward: u = n × t points to the centre where κ_g > 0.
    number.anchor = toGlm(onPath - std::copysign(0.4 * R, f.geodesicCurvature) * f.tangentNormal);
    number.worldAnchored = true;
    number.align = render::Align::Center;
    number.sizePx = std::max(text * 0.9f, text * float(figureText_.leastScale));  // a figure's 6 pt at least
    number.bold = true;
    number.color = done ? kTextColor : glm::vec4(0.12f, 0.13f, 0.16f, 1.0f);
    list.labels.push_back(number);
  }
}
std::vector<TextBlock> BallView::textBlocks(const FrameOrientations& frame, float text) const {
  std::vector<TextBlock> blocks(2);
  if (!spec_.render.labels) return blocks;
  // The heading and the scene's facts (draw_facts formats them), top left
  // where there is room.
  TextBlock& facts = blocks[0];
  facts.slots = {Slot::TopLeft, Slot::TopRight};
  facts.keep = 3;      // the heading and the first fact; later lines give way where there is no room
  facts.givesWay = 0;  // before the running values
  facts.lines.push_back(
      {frame.strobe.empty() ? "rolling ball" : fmt::format("rolling ball at {} positions", frame.strobe.size()),
       text * 1.1f, true, kTextColor, false});
  if (facts_) {
    const std::vector<FactLine> lines = factLines(*facts_, frame, model_.path->length());
    // Lines too long for the view shrink rather than leave it.
    for (const FactLine& line : lines) facts.lines.push_back({line.text, text, false, kTextColor, line.live});
  }
  // The running values, bottom left.
  if (frame.strobe.empty()) {
    TextBlock& live = blocks[1];
    live.slots = {Slot::BottomLeft, Slot::BottomRight, Slot::TopLeft};
    const spin::AngleAxis aa = spin::rotationAngleAxis(frame.current.q);
    const double psi = spin::spinorAngle(frame.current.q);
    std::vector<std::string> lines{fmt::format("s = {:.2f} of {:.2f}", shownStart_ + frame.current.s,
                                               shownLength_.value_or(model_.path->length())),
                                   fmt::format("lab rotation angle = {:.1f}°", aa.angle / kDeg),
                                   fmt::format("spinor angle ψ = {:.1f}°", psi / kDeg)};
    live.keep = 1;
    if (compactText(int(spec_.render.width), int(spec_.render.height))) {
      // Where room is short, the two angles (the story) stay; s gives way.
      std::rotate(lines.begin(), lines.begin() + 1, lines.end());
      live.keep = 2;
    }
    for (const std::string& line : lines) live.lines.push_back({line, text, false, kTextColor});
  }
  return blocks;
}

void BallView::markImportant(Occupancy& occupancy, const render::View& v, double s, bool withPath) const {
  const double R = model_.ballRadius;
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  const float focalPx = 0.5f * float(v.height) * v.camera.clipFromView[1][1];
  auto project = [&](const Vec3& p, float& depth) {
    const glm::vec4 c = clipFromWorld * glm::vec4(toGlm(p), 1.0f);
    depth = c.w;
    return glm::vec2((c.x / c.w * 0.5f + 0.5f) * float(v.width), (0.5f - c.y / c.w * 0.5f) * float(v.height));
  };
  float depth = 0.0f;
  const glm::vec2 ball = project(model_.path->at(s).centre(R), depth);
  // A sphere's outline is a little wider than R f / depth; its shadow and
  // the marker dot stay within 1.15 R of the centre.
  if (depth > float(R))
    occupancy.disc(ball, 1.15f * float(R) * focalPx / std::sqrt(depth * depth - float(R * R)) + 2.0f);
  // The marker's trail lies on the ball's positions before s: seen by this
  // camera (which may move with s: follow, orbit), their discs bound it.
  if (withPath && spec_.render.trails)
    for (int i = 0; i < 96; ++i) {
      const glm::vec2 earlier = project(model_.path->at(s * i / 96.0).centre(R), depth);
      if (depth > float(R))
        occupancy.disc(earlier, 1.05f * float(R) * focalPx / std::sqrt(depth * depth - float(R * R)) + 2.0f);
    }
  const float lineHalf = std::max(2.0f, float(v.height) / 250.0f);
  auto markCurve = [&](auto pointAt, std::size_t count) {
    glm::vec2 previous;
    bool havePrevious = false;
    for (std::size_t i = 0; i < count; ++i) {
      const glm::vec2 p = project(pointAt(i), depth);
      if (depth <= 0.0f) {
        havePrevious = false;
        continue;
      }
      if (havePrevious) occupancy.segment(previous, p, lineHalf);
      previous = p;
      havePrevious = true;
    }
  };
  // The surface's edge the framing holds (a cylinder's rims): text would
  // hide where the surface ends.
  for (const std::vector<geometry::Vec3>& edge : framedEdges_)
    markCurve([&](std::size_t i) { return edge[i]; }, edge.size());
  const std::size_t step = std::max<std::size_t>(1, pathPoints_.size() / 400);
  if (withPath)
    markCurve([&](std::size_t i) { return pathPoints_[std::min(i * step, pathPoints_.size() - 1)]; },
              (pathPoints_.size() + step - 1) / step + 1);
  if (model_.plate && spec_.render.strobe <= 1)
    markCurve(
        [&](std::size_t i) { return platePoint(std::min(pathS_[std::min(i * step, pathS_.size() - 1)], s), 0.0); },
        (pathS_.size() + step - 1) / step + 1);
}

}  // namespace rollspin::draw
