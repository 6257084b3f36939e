#include "draw/surface_looks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "draw/camera_framing.hpp"
#include "draw/draw_style.hpp"
#include "render/mesh_builders.hpp"

namespace rollspin::draw {

namespace {

// A chart whose cells differ in size by more than this over the meshed box
// is shown with the world-space checker (see chartSurface).
constexpr double kChartStretchForSolidChecker = 4.0;

// The parameter box [u0, u1] × [v0, v1] of a chart that is meshed, and its
// checker cells along u and v.
struct ChartBox {
  double u0, u1, v0, v1;
  float cellsU, cellsV;
};

// The parameter box the path visits, padded by about 3R on the surface,
// with checker cells of about R; none where no path point has parameters.
std::optional<ChartBox> chartBoxOfPath(const geometry::Surface& surface, const std::vector<Vec3>& pathPoints,
                                       double R) {
  const geometry::ParameterDomain domain = surface.domain();
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300, speedU = 0.0, speedV = 0.0;
  int found = 0;
  for (std::size_t i = 0; i < pathPoints.size(); i += std::max<std::size_t>(1, pathPoints.size() / 200)) {
    const auto uv = surface.parametersOf(pathPoints[i]);
    if (!uv) continue;
    u0 = std::min(u0, uv->x());
    u1 = std::max(u1, uv->x());
    v0 = std::min(v0, uv->y());
    v1 = std::max(v1, uv->y());
    const geometry::SurfaceJet j = surface.jet(*uv);
    speedU += j.xu.norm();
    speedV += j.xv.norm();
    ++found;
  }
  if (found == 0) return std::nullopt;
  speedU = std::max(speedU / found, 1e-9);
  speedV = std::max(speedV / found, 1e-9);
  const double eps = 1e-6;
  u0 = std::max(u0 - 3.0 * R / speedU, domain.uMin + eps);
  u1 = std::min(u1 + 3.0 * R / speedU, domain.uMax - eps);
  v0 = std::max(v0 - 3.0 * R / speedV, domain.vMin + eps);
  v1 = std::min(v1 + 3.0 * R / speedV, domain.vMax - eps);
  auto cellsU = float((u1 - u0) * speedU / R), cellsV = float((v1 - v0) * speedV / R);
  // An angle padded past one turn would mesh the surface twice over (two
  // coincident sheets z-fight): keep one turn about the box's middle, with
  // a whole even number of checker cells so the pattern closes across the
  // seam.
  auto oneTurn = [](double period, double& lo, double& hi, float& cells) {
    if (period <= 0.0 || hi - lo < period) return;
    const double mid = 0.5 * (lo + hi);
    cells = std::max(2.0f, 2.0f * std::round(0.5f * cells * float(period / (hi - lo))));
    lo = mid - 0.5 * period;
    hi = mid + 0.5 * period;
  };
  oneTurn(domain.uPeriod, u0, u1, cellsU);
  oneTurn(domain.vPeriod, v0, v1, cellsV);
  return ChartBox{u0, u1, v0, v1, cellsU, cellsV};
}

// Whether the chart's cells differ in size a lot over the box: they are
// about R where the path runs, but a steep height field's x-cell on the
// paraboloid's wall is R/27 across and long down the slope, fine stripes
// that beat with the pixels.
bool chartCellsVary(const geometry::Surface& surface, const ChartBox& b) {
  double shortest = 1e300, longest = 0.0;
  for (int i = 0; i <= 8; ++i)
    for (int k = 0; k <= 8; ++k) {
      const geometry::SurfaceJet j =
          surface.jet(geometry::Vec2(b.u0 + (b.u1 - b.u0) * i / 8.0, b.v0 + (b.v1 - b.v0) * k / 8.0));
      for (const double edge : {j.xu.norm() * (b.u1 - b.u0) / b.cellsU, j.xv.norm() * (b.v1 - b.v0) / b.cellsV}) {
        shortest = std::min(shortest, edge);
        longest = std::max(longest, edge);
      }
    }
  return longest > kChartStretchForSolidChecker * shortest;
}

// The meshed patch's edge within 4.5 R of the ball's centres (a cylinder's
// top and bottom rims), framed so that the frame does not cut the surface
// just past the ball; far corners (a paraboloid's rising rim) are not.
// Text keeps off these framed stretches of edge too (markImportant).
void frameChartEdgesNearPath(const geometry::Surface& surface, const ChartBox& b, const std::vector<Vec3>& centres,
                             double R, SurfaceAsDrawn& shape) {
  std::vector<Vec3> runs[4];
  auto endRun = [&](std::vector<Vec3>& run) {
    if (run.size() > 1) shape.framedEdges.push_back(run);
    run.clear();
  };
  for (int k = 0; k <= 32; ++k) {
    const double t = k / 32.0;
    const geometry::Vec2 edges[4] = {
        geometry::Vec2(b.u0 + (b.u1 - b.u0) * t, b.v0), geometry::Vec2(b.u0 + (b.u1 - b.u0) * t, b.v1),
        geometry::Vec2(b.u0, b.v0 + (b.v1 - b.v0) * t), geometry::Vec2(b.u1, b.v0 + (b.v1 - b.v0) * t)};
    for (int e = 0; e < 4; ++e) {
      const Vec3 p = surface.position(edges[e]);
      double nearest = 1e300;
      for (const Vec3& c : centres) nearest = std::min(nearest, (c - p).norm());
      if (nearest <= 4.5 * R) {
        shape.framedPoints.push_back(p);
        runs[e].push_back(p);
      } else {
        endRun(runs[e]);
      }
    }
  }
  for (std::vector<Vec3>& run : runs) endRun(run);
}

}  // namespace

// Surfaces receive the ball's shadow but cast none: a surface shadowing
// itself only adds acne, and where the ball's shadow would pass through a
// surface to its far side, that side faces away from the light anyway.
render::Material matteCheckerMaterial() {
  render::Material material;
  material.castsShadow = false;
  material.receivesShadow = true;
  material.specular = 0.0f;  // matte: cheaper, and no glare on the board
  material.shininess = 16.0f;
  material.pattern = render::Pattern::Checker;
  material.cull = render::Cull::None;
  return material;
}

// A square board under the path; checker cells of size R so that the
// distance rolled can be counted.
SurfaceAsDrawn boardSurface(const geometry::SurfaceLook& look, const SweptBox& box, double R) {
  SurfaceAsDrawn shape{nullptr, matteCheckerMaterial(), box, {}, {}, {}, {}};
  const Vec3 n = look.up;
  const Vec3 mid = 0.5 * (box.lo + box.hi);
  const Vec3 centre = mid - n * n.dot(mid);
  const double half = 0.5 * (box.hi - box.lo).norm() + 3.0 * R;
  const Vec3 e1 = geometry::defaultTangentFor(n), e2 = n.cross(e1);
  shape.mesh = render::parametricPatch(
      [&](float a, float b, glm::vec3& p, glm::vec3& nn) {
        p = toGlm(centre + (2.0 * a - 1.0) * half * e1 + (2.0 * b - 1.0) * half * e2);
        nn = toGlm(n);
      },
      1, 1);  // flat: two triangles (large ones let llvmpipe shade whole tiles)
  for (auto& v : shape.mesh->vertices) {
    const Vec3 p(v.position.x, v.position.y, v.position.z);
    v.uv = glm::vec2(float(p.dot(e1) / R), float(p.dot(e2) / R));  // cells of size R, a corner at the origin
  }
  shape.material.color = {0.80f, 0.78f, 0.74f};
  shape.material.color2 = {0.55f, 0.56f, 0.58f};
  shape.material.patternScale = glm::vec2(1.0f);
  return shape;
}

// A whole sphere of radius look.radius about the origin. Seen from inside,
// the cap that faces the camera is cut away, so the ball inside is seen
// wherever it rolls (a rim line marks the cut), and the whole sphere frames
// the picture; outside, the ball and its path do (a small circle on a big
// sphere would otherwise be lost), and the half of the sphere the path lies
// on, where a slightly wider framing holds it: its rim is the sphere's
// widest outline seen from the path's side, which a view's edge would
// otherwise cut in the middle of the frame.
SurfaceAsDrawn sphereSurface(const geometry::SurfaceLook& look, const SweptBox& box, const scene::SceneSpec& spec,
                             const model::RollingModel& model, const std::vector<Vec3>& pathPoints) {
  SurfaceAsDrawn shape{nullptr, matteCheckerMaterial(), box, {}, {}, {}, {}};
  const double r = look.radius;
  const double c0 = 0.0, c1 = std::numbers::pi;
  if (look.cutAwayTowardEye) {
    const Vec3 toEye = towardEye(orbitAngles(spec, model));
    const double offset = 0.25 * r;
    shape.material.cutPlane = glm::vec4(-toGlm(toEye), float(offset));
    const Vec3 e1 = Vec3::UnitZ().cross(toEye).normalized(), e2 = toEye.cross(e1);
    const double rimRadius = std::sqrt(r * r - offset * offset);
    for (int k = 0; k <= 180; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / 180;
      shape.cutRim.push_back(offset * toEye + rimRadius * (std::cos(phi) * e1 + std::sin(phi) * e2));
    }
  }
  shape.mesh = render::parametricPatch(
      [&](float a, float b, glm::vec3& p, glm::vec3& nn) {
        const double phi = 2.0 * std::numbers::pi * a, th = c0 + (c1 - c0) * b;
        const Vec3 d(std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi), std::cos(th));
        p = toGlm(r * d);
        nn = toGlm(-d);  // the patch winds inward; lighting flips by facing anyway
      },
      128, std::max(8, int(64 * (c1 - c0) / std::numbers::pi)),
      glm::vec2(24.0f, float(12.0 * (c1 - c0) / std::numbers::pi)));
  shape.material.color = {0.72f, 0.74f, 0.78f};
  shape.material.color2 = {0.52f, 0.56f, 0.62f};
  for (int i = 0; i <= 8 && look.cutAwayTowardEye; ++i)
    for (int k = 0; k < 16; ++k) {
      const double th = c0 + (c1 - c0) * i / 8, phi = 2.0 * std::numbers::pi * k / 16;
      shape.framedPoints.push_back(r * Vec3(std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi), std::cos(th)));
    }
  Vec3 pathSide = Vec3::Zero();
  for (const Vec3& p : pathPoints) pathSide += p;
  if (pathSide.norm() > 1e-9 * r * double(pathPoints.size()) && !look.cutAwayTowardEye) {
    pathSide.normalize();
    for (int i = 0; i <= 12; ++i)
      for (int k = 0; k < 24; ++k) {
        const double th = std::numbers::pi * i / 12, phi = 2.0 * std::numbers::pi * k / 24;
        const Vec3 d(std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi), std::cos(th));
        if (d.dot(pathSide) >= -0.05) shape.outline.push_back(r * d);
      }
  }
  for (int k = 0; k < 3; ++k) {
    shape.box.lo[k] = std::min(shape.box.lo[k], -r);
    shape.box.hi[k] = std::max(shape.box.hi[k], r);
  }
  return shape;
}

// Any other surface (cylinder, torus, height field, ...): its own chart
// x(u, v) meshed over the parameter box the path visits; where the chart's
// cells vary a lot, world cubes of R show cells of about R everywhere.
SurfaceAsDrawn chartSurface(const geometry::Surface& surface, const SweptBox& box, double R,
                            const std::vector<Vec3>& pathPoints, const std::vector<Vec3>& centres) {
  SurfaceAsDrawn shape{nullptr, matteCheckerMaterial(), box, {}, {}, {}, {}};
  const std::optional<ChartBox> chart = chartBoxOfPath(surface, pathPoints, R);
  if (!chart) return shape;
  const ChartBox& b = *chart;
  shape.mesh = render::parametricPatch(
      [&](float a, float c, glm::vec3& p, glm::vec3& nn) {
        const geometry::Vec2 uv(b.u0 + (b.u1 - b.u0) * a, b.v0 + (b.v1 - b.v0) * c);
        p = toGlm(surface.position(uv));
        nn = toGlm(surface.normal(uv));
      },
      std::clamp(int(b.cellsU * 4), 16, 256), std::clamp(int(b.cellsV * 4), 16, 256), glm::vec2(b.cellsU, b.cellsV));
  shape.material.color = {0.78f, 0.77f, 0.74f};
  shape.material.color2 = {0.55f, 0.57f, 0.60f};
  if (chartCellsVary(surface, b)) {
    shape.material.pattern = render::Pattern::SolidChecker;
    shape.material.patternScale = glm::vec2(float(1.0 / R));
  }
  for (const auto& v : shape.mesh->vertices) {
    const Vec3 p(v.position.x, v.position.y, v.position.z);
    shape.box.lo = shape.box.lo.cwiseMin(p);
    shape.box.hi = shape.box.hi.cwiseMax(p);
  }
  frameChartEdgesNearPath(surface, b, centres, R, shape);
  return shape;
}


}  // namespace rollspin::draw
