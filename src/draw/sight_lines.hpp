// Sight lines through the surface as it is drawn: a bounding-volume tree of
// the surface mesh's triangles (world space, less the part a cut plane
// removes) answers whether the segment eye → p crosses the surface before p
// (Möller–Trumbore per triangle). The default camera uses it to keep the
// ball in sight; no GL.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "render/draw_list.hpp"

namespace rollspin::draw {

class SightLines {
 public:
  using Vec3 = Eigen::Vector3d;

  // The triangles of `mesh` (model = world space); those wholly on the
  // removed side of `cutPlane` (dot(n, p) + d < 0, see render::Material)
  // are left out, and a hit on the removed side of a kept one is ignored.
  SightLines(const render::MeshData& mesh, const Eigen::Vector4d& cutPlane);

  // Whether the open segment from → to crosses a triangle (hits closer to
  // `to` than `endGap` are not counted: a point on the ball touches the
  // surface at the contact point).
  [[nodiscard]] bool blocked(const Vec3& from, const Vec3& to, double endGap = 1e-9) const;

  // The share of a ball's disc (centre, radius) seen from `eye`: rays to
  // `rays` points spread evenly over its near hemisphere (sunflower order).
  [[nodiscard]] double visibleShare(const Vec3& eye, const Vec3& centre, double radius, int rays = 25) const;

  [[nodiscard]] std::size_t triangleCount() const { return triangles_.size(); }

 private:
  struct Triangle {
    Vec3 a, ab, ac;
  };
  struct Node {
    Eigen::Array3d lo, hi;
    int first = 0, count = 0;  // leaf: triangles_[first, first + count); inner: count = 0, children at first, first + 1
  };
  void build(int node, int first, int count);

  std::vector<Triangle> triangles_;
  std::vector<Node> nodes_;
  Eigen::Vector4d cut_;
};

}  // namespace rollspin::draw
