// The surface looks (draw/surface_looks.hpp) checked on their meshes: a board
// lies in its plane under the ball's sweep with checker cells of the ball's
// radius, a sphere is whole (cut toward the eye where the ball rolls inside,
// its rim on the sphere and the cut), and a chart lies on its surface with
// the ball's-side normals, holds the path with room to spare and frames
// only stretches of its own edge near the ball.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "draw/camera_framing.hpp"
#include "draw/surface_looks.hpp"
#include "loaded_scene.hpp"
#include "model/rolling_model.hpp"
#include "support/test_files.hpp"

namespace rollspin::draw {
namespace surface_looks_test {

using scene_fixture::load;
using scene_fixture::Loaded;

Vec3 toVec(const glm::vec3& p) { return {double(p.x), double(p.y), double(p.z)}; }

// The mesh's boundary: the edges that only one triangle has.
std::vector<std::pair<Vec3, Vec3>> boundaryEdges(const render::MeshData& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.indices[t + std::size_t(k)], b = mesh.indices[t + std::size_t((k + 1) % 3)];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<Vec3, Vec3>> edges;
  for (const auto& [e, n] : uses)
    if (n == 1) edges.emplace_back(toVec(mesh.vertices[e.first].position), toVec(mesh.vertices[e.second].position));
  return edges;
}

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

double meshArea(const render::MeshData& mesh) {
  double area = 0.0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const Vec3 a = toVec(mesh.vertices[mesh.indices[t]].position);
    const Vec3 b = toVec(mesh.vertices[mesh.indices[t + 1]].position);
    const Vec3 c = toVec(mesh.vertices[mesh.indices[t + 2]].position);
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

bool boxHolds(const SweptBox& box, const Vec3& p, double slack) {
  return (p.array() >= box.lo.array() - slack).all() && (p.array() <= box.hi.array() + slack).all();
}

// Samples of the contact path and of the ball's centre along it.
void samplePath(const model::RollingModel& m, int count, std::vector<Vec3>& points, std::vector<Vec3>& centres) {
  const double length = m.path->length();
  for (int i = 0; i <= count; ++i) {
    const geometry::DarbouxSample f = m.path->at(length * i / count);
    points.push_back(f.point);
    centres.push_back(f.point + m.ballRadius * f.normal);
  }
}

void expectMatteChecker(const render::Material& m) {
  EXPECT_TRUE(m.receivesShadow);
  EXPECT_FALSE(m.castsShadow);
  EXPECT_EQ(m.cull, render::Cull::None);
  EXPECT_TRUE(m.pattern == render::Pattern::Checker || m.pattern == render::Pattern::SolidChecker);
}


TEST(SurfaceLooks, BoardLiesInItsPlaneUnderTheSweepWithCellsOfTheBallsRadius) {
  geometry::SurfaceLook look;
  look.mesh = geometry::SurfaceLook::Mesh::Board;
  look.up = Vec3(1.0, 2.0, 2.0) / 3.0;  // oblique: no axis-aligned shortcut
  SweptBox box;
  box.lo = Vec3(-2.0, -1.0, 0.5);
  box.hi = Vec3(3.0, 2.5, 1.5);
  const double R = 0.7;
  const SurfaceAsDrawn shape = boardSurface(look, box, R);
  ASSERT_NE(shape.mesh, nullptr);
  const render::MeshData& mesh = *shape.mesh;
  ASSERT_GE(mesh.vertices.size(), 3u);
  expectMatteChecker(shape.material);
  EXPECT_EQ(shape.material.pattern, render::Pattern::Checker);

  // In the plane through the origin with normal `up`, whose normal each vertex carries.
  for (const render::Vertex& v : mesh.vertices) {
    EXPECT_NEAR(look.up.dot(toVec(v.position)), 0.0, 1e-5);
    EXPECT_NEAR((toVec(v.normal) - look.up).norm(), 0.0, 1e-6);
  }
  // A square: four boundary edges of one length, at right angles.
  const auto edges = boundaryEdges(mesh);
  ASSERT_EQ(edges.size(), 4u);
  const double side = (edges[0].second - edges[0].first).norm();
  for (const auto& [a, b] : edges) EXPECT_NEAR((b - a).norm(), side, 1e-5 * side);
  EXPECT_NEAR(meshArea(mesh), side * side, 1e-4 * side * side);

  // Under the sweep: every corner of the box, dropped onto the plane, lies
  // inside the board with at least the ball's radius to spare.
  Vec3 middle = Vec3::Zero();
  for (const render::Vertex& v : mesh.vertices) middle += toVec(v.position) / double(mesh.vertices.size());
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c((corner & 1) ? box.hi.x() : box.lo.x(), (corner & 2) ? box.hi.y() : box.lo.y(),
                 (corner & 4) ? box.hi.z() : box.lo.z());
    const Vec3 q = c - look.up * look.up.dot(c);
    for (const auto& [a, b] : edges) {
      // The inward normal of this edge, in the plane.
      Vec3 inward = look.up.cross(b - a).normalized();
      if (inward.dot(middle - a) < 0.0) inward = -inward;
      EXPECT_GE(inward.dot(q - a), R) << "corner " << corner << " lies " << inward.dot(q - a) / R << " R inside";
    }
  }

  // Checker cells of size R: uv (one unit a cell at patternScale 1) is the
  // plane's coordinates over R, so R·|Δuv| = |Δp| for every pair of
  // vertices, and the cells' corners lie on a grid through the origin.
  EXPECT_EQ(shape.material.patternScale, glm::vec2(1.0f));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    for (std::size_t j = i + 1; j < mesh.vertices.size(); ++j) {
      const double dp = (toVec(mesh.vertices[i].position) - toVec(mesh.vertices[j].position)).norm();
      const double duv = double(glm::length(mesh.vertices[i].uv - mesh.vertices[j].uv));
      EXPECT_NEAR(R * duv, dp, 1e-4 * side);
    }
  // The affine map p ↦ uv from three corners, at p = 0 (on the plane).
  const Vec3 p0 = toVec(mesh.vertices[0].position), p1 = toVec(mesh.vertices[1].position),
             p2 = toVec(mesh.vertices[2].position);
  const Vec3 d1 = p1 - p0, d2 = p2 - p0, r = -p0;
  const double g11 = d1.dot(d1), g12 = d1.dot(d2), g22 = d2.dot(d2), det = g11 * g22 - g12 * g12;
  ASSERT_GT(std::abs(det), 1e-9 * g11 * g22);
  const double alpha = (g22 * r.dot(d1) - g12 * r.dot(d2)) / det, beta = (g11 * r.dot(d2) - g12 * r.dot(d1)) / det;
  const glm::dvec2 uvAtOrigin = glm::dvec2(mesh.vertices[0].uv) +
                                alpha * glm::dvec2(mesh.vertices[1].uv - mesh.vertices[0].uv) +
                                beta * glm::dvec2(mesh.vertices[2].uv - mesh.vertices[0].uv);
  EXPECT_NEAR(uvAtOrigin.x, std::round(uvAtOrigin.x), 1e-3);
  EXPECT_NEAR(uvAtOrigin.y, std::round(uvAtOrigin.y), 1e-3);
}

TEST(SurfaceLooks, SphereSeenFromInsideIsWholeAndCutAwayTowardTheEye) {
  const Loaded l = load("scenes/sphere-inside.toml");
  const geometry::SurfaceLook look = l.model.surface->look();
  ASSERT_EQ(look.mesh, geometry::SurfaceLook::Mesh::Sphere);
  ASSERT_TRUE(look.cutAwayTowardEye);
  const double r = look.radius;
  ASSERT_GT(r, 0.0);
  std::vector<Vec3> points, centres;
  samplePath(l.model, 200, points, centres);
  SweptBox box;
  for (const Vec3& c : centres) box.lo = box.lo.cwiseMin(c), box.hi = box.hi.cwiseMax(c);
  const SurfaceAsDrawn shape = sphereSurface(look, box, l.spec, l.model, points);
  ASSERT_NE(shape.mesh, nullptr);
  expectMatteChecker(shape.material);

  // The sphere of radius r about the origin, its normals radial and unit.
  for (const render::Vertex& v : shape.mesh->vertices) {
    const Vec3 p = toVec(v.position), n = toVec(v.normal);
    EXPECT_NEAR(p.norm(), r, 1e-5 * r);
    EXPECT_NEAR(n.norm(), 1.0, 1e-5);
    EXPECT_NEAR(std::abs(n.dot(p)) / r, 1.0, 1e-5);
  }
  // All of it (flat triangles: a little under 4πr²).
  const double area = meshArea(*shape.mesh), whole = 4.0 * std::numbers::pi * r * r;
  EXPECT_LE(area, whole);
  EXPECT_GE(area, 0.99 * whole);

  // The box holds the sweep and the whole sphere.
  for (const Vec3& c : centres) EXPECT_TRUE(boxHolds(shape.box, c, 1e-9));
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(shape.box.lo[k], -r);
    EXPECT_GE(shape.box.hi[k], r);
  }

  // The cap toward the eye is cut away, the centre (where the ball is seen) kept.
  const Vec3 toEye = towardEye(orbitAngles(l.spec, l.model));
  const glm::vec4 cut = shape.material.cutPlane;
  auto kept = [&](const Vec3& p) { return double(glm::dot(cut, glm::vec4(glm::vec3(p.x(), p.y(), p.z()), 1.0f))); };
  EXPECT_LT(kept(r * toEye), 0.0);
  EXPECT_GT(kept(-r * toEye), 0.0);
  EXPECT_GT(kept(Vec3::Zero()), 0.0);
  // Its rim: a closed circle on the sphere and on the cut.
  ASSERT_GE(shape.cutRim.size(), 16u);
  EXPECT_NEAR((shape.cutRim.front() - shape.cutRim.back()).norm(), 0.0, 1e-9 * r);
  for (const Vec3& p : shape.cutRim) {
    EXPECT_NEAR(p.norm(), r, 1e-9 * r);
    EXPECT_NEAR(kept(p), 0.0, 1e-5 * r);
  }
  // The whole sphere frames the picture: framed points on it, every way round.
  ASSERT_FALSE(shape.framedPoints.empty());
  for (const Vec3& p : shape.framedPoints) EXPECT_NEAR(p.norm(), r, 1e-9 * r);
  for (int k = 0; k < 3; ++k)
    for (const double sign : {-1.0, 1.0}) {
      double reach = -1e300;
      for (const Vec3& p : shape.framedPoints) reach = std::max(reach, sign * p[k]);
      EXPECT_GE(reach, 0.9 * r) << "axis " << k << " sign " << sign;
    }
}

TEST(SurfaceLooks, SphereSeenFromOutsideIsWholeAndOutlinedOnThePathsSide) {
  const Loaded l = load("scenes/berry.toml");
  const geometry::SurfaceLook look = l.model.surface->look();
  ASSERT_EQ(look.mesh, geometry::SurfaceLook::Mesh::Sphere);
  ASSERT_FALSE(look.cutAwayTowardEye);
  const double r = look.radius;
  std::vector<Vec3> points, centres;
  samplePath(l.model, 200, points, centres);
  SweptBox box;
  for (const Vec3& c : centres) box.lo = box.lo.cwiseMin(c), box.hi = box.hi.cwiseMax(c);
  const SurfaceAsDrawn shape = sphereSurface(look, box, l.spec, l.model, points);
  ASSERT_NE(shape.mesh, nullptr);
  for (const render::Vertex& v : shape.mesh->vertices) EXPECT_NEAR(toVec(v.position).norm(), r, 1e-5 * r);
  EXPECT_GE(meshArea(*shape.mesh), 0.99 * 4.0 * std::numbers::pi * r * r);
  // Nothing cut: the default plane keeps every point.
  EXPECT_EQ(shape.material.cutPlane, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_TRUE(shape.cutRim.empty());
  // The outline is the half of the sphere the path lies on (the path here
  // is a parallel at colatitude 50°: the northern side), out to its rim.
  Vec3 side = Vec3::Zero();
  for (const Vec3& p : points) side += p;
  side.normalize();
  ASSERT_GT(side.z(), 0.5);
  ASSERT_FALSE(shape.outline.empty());
  double highest = -1e300, lowest = 1e300;
  for (const Vec3& p : shape.outline) {
    EXPECT_NEAR(p.norm(), r, 1e-9 * r);
    highest = std::max(highest, p.dot(side) / r);
    lowest = std::min(lowest, p.dot(side) / r);
  }
  EXPECT_GE(highest, 0.95);
  EXPECT_LE(lowest, 0.1);    // out to the rim
  EXPECT_GE(lowest, -0.15);  // not the far half
}

TEST(SurfaceLooks, ChartLiesOnTheSurfaceAndHoldsThePathWithRoom) {
  const Loaded l = load("scenes/height-bumps.toml");
  const geometry::Surface& surface = *l.model.surface;
  ASSERT_EQ(surface.look().mesh, geometry::SurfaceLook::Mesh::Chart);
  const double R = l.model.ballRadius;
  std::vector<Vec3> points, centres;
  samplePath(l.model, 400, points, centres);
  SweptBox box;
  for (const Vec3& c : centres) box.lo = box.lo.cwiseMin(c), box.hi = box.hi.cwiseMax(c);
  const SurfaceAsDrawn shape = chartSurface(surface, box, R, points, centres);
  ASSERT_NE(shape.mesh, nullptr);
  const render::MeshData& mesh = *shape.mesh;
  expectMatteChecker(shape.material);

  // On the surface, each vertex with the unit normal on the ball's side;
  // the box holds the sweep and every vertex.
  for (const render::Vertex& v : mesh.vertices) {
    const Vec3 p = toVec(v.position);
    EXPECT_NEAR(surface.distance(p), 0.0, 1e-5);
    EXPECT_NEAR((toVec(v.normal) - surface.normalAt(p)).norm(), 0.0, 1e-5);
    EXPECT_TRUE(boxHolds(shape.box, p, 1e-9));
  }
  for (const Vec3& c : centres) EXPECT_TRUE(boxHolds(shape.box, c, 1e-9));

  // The path runs inside the patch, its edge at least 2R off (the patch is
  // padded by about 3R).
  const auto edges = boundaryEdges(mesh);
  ASSERT_FALSE(edges.empty());
  double closest = 1e300;
  for (const Vec3& p : points)
    for (const auto& [a, b] : edges) closest = std::min(closest, distanceToSegment(p, a, b));
  EXPECT_GE(closest, 2.0 * R) << "the patch's edge comes within " << closest / R << " R of the path";

  // Checker cells of about R where the path runs: each triangle within R of
  // the path, one uv unit (a cell) along u and v spans R/2 … 2R.
  ASSERT_EQ(shape.material.pattern, render::Pattern::Checker);
  int near = 0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const render::Vertex& a = mesh.vertices[mesh.indices[t]];
    const render::Vertex& b = mesh.vertices[mesh.indices[t + 1]];
    const render::Vertex& c = mesh.vertices[mesh.indices[t + 2]];
    const Vec3 middle = (toVec(a.position) + toVec(b.position) + toVec(c.position)) / 3.0;
    double d = 1e300;
    for (const Vec3& p : points) d = std::min(d, (p - middle).norm());
    if (d > R) continue;
    const glm::dmat2 uvEdges(glm::dvec2(b.uv - a.uv), glm::dvec2(c.uv - a.uv));
    if (std::abs(glm::determinant(uvEdges)) < 1e-12) continue;
    const glm::dmat2 inverse = glm::inverse(uvEdges);
    const glm::dvec3 e1(b.position - a.position), e2(c.position - a.position);
    for (int k = 0; k < 2; ++k) {
      const double cell = glm::length(e1 * inverse[k][0] + e2 * inverse[k][1]) /
                          double(k == 0 ? shape.material.patternScale.x : shape.material.patternScale.y);
      EXPECT_GT(cell, 0.5 * R);
      EXPECT_LT(cell, 2.0 * R);
    }
    ++near;
  }
  EXPECT_GT(near, 20);

  // The framed stretches of edge lie on the patch's edge, near the ball.
  ASSERT_FALSE(shape.framedEdges.empty());
  for (const std::vector<Vec3>& run : shape.framedEdges) {
    EXPECT_GE(run.size(), 2u);
    for (const Vec3& p : run) {
      EXPECT_NEAR(surface.distance(p), 0.0, 1e-6);
      double onEdge = 1e300, toBall = 1e300;
      for (const auto& [a, b] : edges) onEdge = std::min(onEdge, distanceToSegment(p, a, b));
      for (const Vec3& c : centres) toBall = std::min(toBall, (c - p).norm());
      EXPECT_LT(onEdge, 0.02 * R);
      EXPECT_LE(toBall, 4.5 * R + 1e-9);
    }
  }
}

}  // namespace surface_looks_test
}  // namespace rollspin::draw
