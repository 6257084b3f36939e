// BallView::stillExtent and subjectBounds: what a figure's camera frames
// for one still, and how large its subject comes out.
#include <algorithm>
#include <cmath>

#include "draw/ball_view.hpp"
#include "draw/draw_style.hpp"

namespace rollspin::draw {

using geometry::Vec3;

FrameExtent BallView::stillExtent(double s) const {
  // Points on the surface (the path, a sphere's outline, the patch's edge)
  // take a quarter of the ball's radius (the outline bulges between its
  // samples; the frame's edge keeps off it); the ball's centre and the
  // plate's points its radius.
  const double R = model_.ballRadius, onSurface = 0.25 * R;
  FrameExtent still = extent_;
  still.points.clear();
  auto add = [&](const Vec3& p, double pad) {
    still.points.push_back(p);
    still.pads.push_back(pad);
  };
  const std::size_t step = std::max<std::size_t>(1, pathPoints_.size() / 240);
  for (std::size_t i = 0; i < pathPoints_.size(); i += step) add(pathPoints_[i], onSurface);
  add(pathPoints_.back(), onSurface);
  // The ball's sweep up to s, padded by R: the marker's trail so far lies
  // on it.
  const double at = std::clamp(s, 0.0, model_.path->length());
  for (std::size_t i = 0; i < pathS_.size() && pathS_[i] < at; i += step) add(model_.path->at(pathS_[i]).centre(R), R);
  add(model_.path->at(at).centre(R), R);
  // The drawn surface within 4.5 R of the path (as the patch's edge is
  // framed): a sphere the ball circles stays whole, a big one round a small
  // path does not shrink it.
  if (surfaceMesh_) {
    const std::size_t pathCount = still.points.size();
    const std::size_t every = std::max<std::size_t>(1, surfaceMesh_->vertices.size() / 2000);
    for (std::size_t v = 0; v < surfaceMesh_->vertices.size(); v += every) {
      const glm::vec3& g = surfaceMesh_->vertices[v].position;
      const Vec3 p(g.x, g.y, g.z);
      for (std::size_t i = 0; i < pathCount; ++i)
        if ((still.points[i] - p).squaredNorm() <= 20.25 * R * R) {
          add(p, onSurface);
          break;
        }
    }
  }
  for (std::size_t i = centrePoints_; i < extent_.points.size(); ++i)
    add(extent_.points[i], std::binary_search(surfacePoints_.begin(), surfacePoints_.end(), i) ? onSurface : R);
  return still;
}

std::pair<glm::vec2, glm::vec2> BallView::subjectBounds(const render::View& v, double s) const {
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  glm::vec2 lo(1e30f), hi(-1e30f);
  auto add = [&](const glm::vec3& p, float radius) {
    const glm::vec4 c = clipFromWorld * glm::vec4(p, 1.0f);
    if (c.w <= 1e-6f) return;
    const glm::vec2 ndc = glm::vec2(c) / c.w;
    // A sphere's outline: about R f / depth (a little more off the axis;
    // the clamp below keeps it inside the view).
    const glm::vec2 r = radius * glm::vec2(v.camera.clipFromView[0][0], v.camera.clipFromView[1][1]) / c.w;
    for (const glm::vec2 corner : {ndc - r, ndc + r}) {
      const glm::vec2 q = glm::clamp(corner, glm::vec2(-1.0f), glm::vec2(1.0f));
      const glm::vec2 px((q.x + 1.0f) * 0.5f * float(v.width), (1.0f - q.y) * 0.5f * float(v.height));
      lo = glm::min(lo, px), hi = glm::max(hi, px);
    }
  };
  const double R = model_.ballRadius;
  add(toGlm(model_.path->at(std::clamp(s, 0.0, model_.path->length())).centre(R)), float(R));
  if (surfaceMesh_) {
    const std::size_t every = std::max<std::size_t>(1, surfaceMesh_->vertices.size() / 4000);
    for (std::size_t i = 0; i < surfaceMesh_->vertices.size(); i += every)
      add(surfaceMesh_->vertices[i].position, 0.0f);
  }
  return {lo, hi};
}

}  // namespace rollspin::draw
