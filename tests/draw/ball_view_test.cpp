// The ball view (draw/ball_view.hpp) checked on its DrawList: the ball's
// unit sphere is placed at C(s) = P(s) + R n(s) (n from the surface's closed
// form, not the path) and turned by worldFromBody R(U(s)), computed here as
// R_ij = ½ tr(σ_i U σ_j U†) from the spinor's 2×2 matrix; the travelled part
// of the path runs from P(0) to the contact point P(s); the marker's trail
// ends on the ball's surface at the marker; a strobe draws a ball at each of
// its samples.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "draw/ball_view.hpp"
#include "draw/draw_style.hpp"
#include "loaded_scene.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "render/mesh_builders.hpp"
#include "support/test_files.hpp"

namespace rollspin::draw {
namespace ball_view_test {

using geometry::Vec3;
using Complex = std::complex<double>;
using Pauli = std::array<std::array<Complex, 2>, 2>;

using scene_fixture::load;
using scene_fixture::Loaded;

Vec3 toVec(const glm::vec3& p) { return {double(p.x), double(p.y), double(p.z)}; }

Pauli product(const Pauli& a, const Pauli& b) {
  Pauli c{};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) c[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j];
  return c;
}

// R(U)_ij = ½ tr(σ_i U σ_j U†), U = w − i(x σx + y σy + z σz).
Eigen::Matrix3d rotationOfSpinor(const spin::Su2& q) {
  const Complex i(0.0, 1.0);
  const Pauli sigma[3] = {{{{0.0, 1.0}, {1.0, 0.0}}}, {{{0.0, -i}, {i, 0.0}}}, {{{1.0, 0.0}, {0.0, -1.0}}}};
  const Pauli u = {{{q.w - i * q.z, -i * q.x - q.y}, {-i * q.x + q.y, q.w + i * q.z}}};
  Pauli uDagger{};
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) uDagger[r][c] = std::conj(u[c][r]);
  Eigen::Matrix3d m;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const Pauli p = product(sigma[a], product(u, product(sigma[b], uDagger)));
      m(a, b) = 0.5 * (p[0][0] + p[1][1]).real();
    }
  return m;
}

struct Drawn {
  render::DrawList list;
  motion::FrameOrientations frame;
};

Drawn drawBall(const Loaded& l, const Vec3& marker, double s) {
  const BallView ball(l.spec, l.model, nullptr, nullptr, marker, render::uvSphere(12, 6), FigureText{});
  Drawn d;
  d.list.width = 800;
  d.list.height = 600;
  render::View v;
  v.width = 800;
  v.height = 600;
  d.list.views.push_back(v);
  d.frame = motion::solveFrame(l.spec, l.model, s);
  ball.add(d.list, d.frame, 0);
  return d;
}

std::vector<const render::MeshItem*> balls(const render::DrawList& list) {
  std::vector<const render::MeshItem*> found;
  for (const render::MeshItem& m : list.meshes)
    if (m.material.pattern == render::Pattern::Texture && m.sphere) found.push_back(&m);
  return found;
}

// A polyline of one colour, its growing pieces joined.
std::vector<Vec3> lineOf(const render::DrawList& list, const glm::vec4& color) {
  std::vector<Vec3> points;
  for (const render::PolylineItem& p : list.polylines) {
    if (p.color != color || p.points.empty()) continue;
    for (std::size_t k = points.empty() ? 0 : 1; k < p.points.size(); ++k) points.push_back(toVec(p.points[k]));
  }
  return points;
}

// The ball item is T(C) R(U) S(R): its origin at C, its columns R times R(U)'s.
void expectBallAt(const render::MeshItem& ball, const Vec3& centre, const Eigen::Matrix3d& rotation, double R,
                  const std::string& where) {
  EXPECT_NEAR((toVec(glm::vec3(ball.worldFromModel[3])) - centre).norm(), 0.0, 1e-5 * (1.0 + centre.norm())) << where;
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR((toVec(glm::vec3(ball.worldFromModel[c])) - R * rotation.col(c)).norm(), 0.0, 1e-5 * R)
        << where << " column " << c;
}


TEST(BallViewPlacement, BallSitsAtContactPlusRNormalTurnedByWorldFromBody) {
  // Outside a sphere about the origin the ball's side is n = P/|P|.
  const Loaded l = load("scenes/berry.toml");
  const double R = l.model.ballRadius, length = l.model.path->length();
  const Vec3 marker = Vec3(0.2, 0.9, -0.4).normalized();
  for (const double share : {0.0, 0.3, 0.7}) {
    const double s = share * length;
    const Drawn d = drawBall(l, marker, s);
    const auto found = balls(d.list);
    ASSERT_EQ(found.size(), 1u);
    const Vec3 P = l.model.path->at(s).point;
    const Vec3 centre = P + R * P.normalized();
    const Eigen::Matrix3d rotation = rotationOfSpinor(d.frame.current.q);
    EXPECT_NEAR((rotation * rotation.transpose() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-9);
    expectBallAt(*found[0], centre, rotation, R, "s = " + std::to_string(share) + " L");

    // The marker's trail ends at the marker on the ball's surface, C + R·R(U) m.
    const std::vector<Vec3> trail = lineOf(d.list, kMarkerTrailColor);
    if (share > 0.0) {
      ASSERT_GE(trail.size(), 2u);
      EXPECT_NEAR((trail.back() - (centre + R * rotation * marker)).norm(), 0.0, 1e-5);
    }
  }
}

TEST(BallViewPlacement, TravelledPathRunsFromTheStartToTheContactPoint) {
  const Loaded l = load("scenes/lollipop.toml");  // a circle on the floor z = 0, n = +z
  const double R = l.model.ballRadius, length = l.model.path->length();
  const Vec3 P0 = l.model.path->at(0.0).point;
  for (const double share : {0.2537, 0.6113}) {  // off any sampling grid
    const double s = share * length;
    const Drawn d = drawBall(l, Vec3::UnitZ(), s);
    const Vec3 P = l.model.path->at(s).point;
    const auto found = balls(d.list);
    ASSERT_EQ(found.size(), 1u);
    expectBallAt(*found[0], P + R * Vec3::UnitZ(), rotationOfSpinor(d.frame.current.q), R, "lollipop");

    const std::vector<Vec3> travelled = lineOf(d.list, kTravelledColor);
    ASSERT_GE(travelled.size(), 3u);
    EXPECT_NEAR((travelled.front() - P0).norm(), 0.0, 0.01 * R);
    // It ends at the contact point itself (lifted off the floor by a hair),
    // not at the last sample of the path before it.
    EXPECT_NEAR(travelled.back().x(), P.x(), 1e-5 * R);
    EXPECT_NEAR(travelled.back().y(), P.y(), 1e-5 * R);
    // On the floor, and as long as the arc travelled (chords: a little under).
    double arc = 0.0;
    for (std::size_t i = 0; i < travelled.size(); ++i) {
      EXPECT_NEAR(travelled[i].z(), 0.0, 0.01 * R);
      if (i > 0) arc += (travelled[i] - travelled[i - 1]).norm();
    }
    EXPECT_LE(arc, s * (1.0 + 1e-6));
    EXPECT_GE(arc, s * 0.99);
    // The whole path is drawn as well, on the floor, longer than the part travelled.
    const std::vector<Vec3> full = lineOf(d.list, kPathLineColor);
    ASSERT_GT(full.size(), travelled.size());
    for (const Vec3& p : full) EXPECT_NEAR(p.z(), 0.0, 0.01 * R);
  }
}

TEST(BallViewPlacement, AStrobeDrawsABallAtEachOfItsSamples) {
  const Loaded l = load("scenes/lollipop.toml", {"render.strobe=6", "render.layout=ball"});
  const double R = l.model.ballRadius;
  const Drawn d = drawBall(l, Vec3::UnitZ(), 0.0);
  ASSERT_EQ(d.frame.strobe.size(), 6u);
  const auto found = balls(d.list);
  ASSERT_EQ(found.size(), 6u);
  for (std::size_t k = 0; k < found.size(); ++k) {
    const motion::OrientedSample& pose = d.frame.strobe[k];
    expectBallAt(*found[k], l.model.path->at(pose.s).point + R * Vec3::UnitZ(), rotationOfSpinor(pose.q), R,
                 "strobe " + std::to_string(k));
  }
}

}  // namespace ball_view_test
}  // namespace rollspin::draw
