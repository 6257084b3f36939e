// A surface as the ball view draws it, one function per look
// (geometry::SurfaceLook): a board under the path, a sphere (cut away toward
// the eye where the ball rolls inside), a chart of the surface's (u, v)
// patch near the path. Each returns its mesh, material and what of it the
// framing holds. Internal to draw/ (ball_view.cpp).
#pragma once

#include <memory>
#include <vector>

#include "geometry/surface.hpp"
#include "model/rolling_model.hpp"
#include "render/draw_list.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::draw {

using geometry::Vec3;

// The box the framing holds: the ball's sweep, grown by what else the
// picture shows.
struct SweptBox {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
};

// A surface as its look shows it (geometry::SurfaceLook): its mesh and
// material, and what of it the framing holds: the box grown by it, points
// on it (FrameExtent::points, as surface points), the outline it adds
// (FrameExtent::outline), the stretches of its edge that text keeps off,
// and the rim of a cap cut away toward the eye.
struct SurfaceAsDrawn {
  std::shared_ptr<render::MeshData> mesh;
  render::Material material;
  SweptBox box;
  std::vector<Vec3> framedPoints;
  std::vector<Vec3> outline;
  std::vector<std::vector<Vec3>> framedEdges;
  std::vector<Vec3> cutRim;
};

// The surfaces' material: a matte checker that receives the ball's shadow.
[[nodiscard]] render::Material matteCheckerMaterial();

// A square board under the path; checker cells of size R.
[[nodiscard]] SurfaceAsDrawn boardSurface(const geometry::SurfaceLook& look, const SweptBox& box, double R);
// The sphere (inside or outside), cut away toward the eye where the look says.
[[nodiscard]] SurfaceAsDrawn sphereSurface(const geometry::SurfaceLook& look, const SweptBox& box,
                                           const scene::SceneSpec& spec, const model::RollingModel& model,
                                           const std::vector<Vec3>& pathPoints);
// The surface's chart around the path, framed by its edges near the ball's centres.
[[nodiscard]] SurfaceAsDrawn chartSurface(const geometry::Surface& surface, const SweptBox& box, double R,
                                          const std::vector<Vec3>& pathPoints, const std::vector<Vec3>& centres);

}  // namespace rollspin::draw
