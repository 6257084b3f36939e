// Sight lines through a drawn mesh: a BVH answer equals a brute-force test
// of every triangle, a cut plane opens the mesh, the end gap lets a point
// touching the surface be seen, and the disc share is what is in front.
#include <gtest/gtest.h>

#include <random>

#include "draw/sight_lines.hpp"
#include "render/mesh_builders.hpp"

namespace rollspin::draw {
namespace {
using Vec3 = SightLines::Vec3;

const Eigen::Vector4d kNoCut(0.0, 0.0, 0.0, 1.0);

// Every triangle, no tree (Möller–Trumbore), as the reference.
bool bruteForceBlocked(const render::MeshData& mesh, const Vec3& from, const Vec3& to) {
  auto at = [&](std::uint32_t i) {
    const auto& p = mesh.vertices[i].position;
    return Vec3(p.x, p.y, p.z);
  };
  const Vec3 d = to - from;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const Vec3 a = at(mesh.indices[i]), ab = at(mesh.indices[i + 1]) - a, ac = at(mesh.indices[i + 2]) - a;
    const Vec3 p = d.cross(ac);
    const double det = ab.dot(p);
    if (std::abs(det) < 1e-300) continue;
    const Vec3 s = from - a;
    const double u = s.dot(p) / det, v = d.dot(s.cross(ab)) / det, t = ac.dot(s.cross(ab)) / det;
    if (u >= 0 && v >= 0 && u + v <= 1 && t > 0 && t < 1) return true;
  }
  return false;
}

TEST(SightLines, TheTreeAgreesWithEveryTriangleTestedInTurn) {
  const auto sphere = render::uvSphere(32, 16);  // unit sphere
  const SightLines lines(*sphere, kNoCut);
  EXPECT_GT(lines.triangleCount(), 800u);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  int blocked = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 a(coordinate(random), coordinate(random), coordinate(random));
    const Vec3 b(coordinate(random), coordinate(random), coordinate(random));
    const bool expected = bruteForceBlocked(*sphere, a, b);
    EXPECT_EQ(lines.blocked(a, b, 0.0), expected) << a.transpose() << " → " << b.transpose();
    blocked += expected;
  }
  EXPECT_GT(blocked, 400);  // both answers were exercised
  EXPECT_LT(blocked, 1600);
}

TEST(SightLines, ACutPlaneOpensTheMeshAndTheEndGapSparesATouchingPoint) {
  const auto sphere = render::uvSphere(48, 24);
  // Through the sphere along x: blocked; with the +x cap cut away (keep
  // x ≤ 0.25), a point inside is seen from +x.
  EXPECT_TRUE(SightLines(*sphere, kNoCut).blocked(Vec3(3, 0, 0), Vec3(0, 0, 0)));
  const SightLines open(*sphere, Eigen::Vector4d(-1.0, 0.0, 0.0, 0.25));
  EXPECT_FALSE(open.blocked(Vec3(3, 0.1, 0.05), Vec3(0, 0.1, 0.05)));
  EXPECT_TRUE(open.blocked(Vec3(-3, 0.1, 0.05), Vec3(0, 0.1, 0.05)));  // the far side still stands
  // A point on the surface seen from outside: not hidden by itself with a gap.
  const SightLines closed(*sphere, kNoCut);
  EXPECT_FALSE(closed.blocked(Vec3(3, 0.02, 0.01), Vec3(0.98, 0.02, 0.01), 0.05));
}

TEST(SightLines, TheShareOfABallSeenIsWhatStandsInFrontOfIt) {
  const auto sphere = render::uvSphere(48, 24);
  const SightLines unitSphere(*sphere, kNoCut);
  const double R = 0.3;
  // A ball beside the sphere, seen from the side it is on: all of it.
  EXPECT_DOUBLE_EQ(unitSphere.visibleShare(Vec3(0, -6, 0), Vec3(0, -1.3, 0), R), 1.0);
  // Straight behind the sphere: none of it.
  EXPECT_DOUBLE_EQ(unitSphere.visibleShare(Vec3(0, 6, 0), Vec3(0, -1.3, 0), R), 0.0);
  // Half behind the rim (its centre on the silhouette's tangent line): about half.
  const double share = unitSphere.visibleShare(Vec3(0, 20, 0), Vec3(1.0, -1.3, 0), R, 400);
  EXPECT_GT(share, 0.35);
  EXPECT_LT(share, 0.65);
}

}  // namespace
}  // namespace rollspin::draw
