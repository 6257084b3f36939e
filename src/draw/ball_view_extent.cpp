// BallView::stillExtent: what a figure's camera frames for one still.
#include <algorithm>

#include "draw/ball_view.hpp"

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

}  // namespace rollspin::draw
