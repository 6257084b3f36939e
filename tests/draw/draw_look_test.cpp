// What the ball view shows, checked on the DrawList (no GL): Brockett's
// glass plate stays in frame wherever it moves, the positions of a strobe
// figure stand apart on screen, a surface whose chart is an angle is meshed
// once round (not twice over, which z-fights), and a wall is lit from above so that the
// ball's shadow falls below the ball instead of straight behind it.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "draw/draw_style.hpp"
#include "draw/scene_drawer.hpp"
#include "loaded_scene.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "support/sweep.hpp"
#include "support/test_files.hpp"

namespace rollspin::draw {
namespace {
using namespace rollspin::model;
using namespace rollspin::motion;

using scene_fixture::load;
using scene_fixture::Loaded;

glm::vec3 ndc(const render::View& v, const glm::vec3& world) {
  const glm::vec4 c = v.camera.clipFromView * v.camera.viewFromWorld * glm::vec4(world, 1.0f);
  return glm::vec3(c) / c.w;
}

// The plate's glass disc is the ball view's only translucent lit mesh.
void expectPlateInFrame(const std::string& scene) {
  const Loaded l = load(scene);
  const SceneDrawer drawer(l.spec, l.model, nullptr);
  const double length = l.model.path->length();
  int discs = 0;
  for (int i = 0; i <= 12; ++i) {
    const double s = length * i / 12.0;
    const render::DrawList list = drawer.draw(solveFrame(l.spec, l.model, s));
    const render::View& v = list.views.at(0);
    for (const render::MeshItem& m : list.meshes) {
      if (m.view != 0 || m.material.opacity >= 1.0f || !m.material.lit) continue;  // not a text backing plate
      ++discs;
      for (int k = 0; k < 32; ++k) {
        const float phi = 2.0f * 3.14159265f * float(k) / 32.0f;
        for (float z : {0.0f, 1.0f}) {  // both faces of the unit cylinder
          const glm::vec3 p = ndc(v, glm::vec3(m.worldFromModel * glm::vec4(std::cos(phi), std::sin(phi), z, 1.0f)));
          EXPECT_LE(std::abs(p.x), 1.0f) << scene << " s = " << s;
          EXPECT_LE(std::abs(p.y), 1.0f) << scene << " s = " << s;
        }
      }
    }
  }
  EXPECT_EQ(discs, 13) << scene;
}

TEST(BallView, BrockettPlateStaysInFrameAllAlongThePath) {
  expectPlateInFrame("scenes/tennis-ball.toml");
  expectPlateInFrame("tests/render/scenes/brockett_plate.toml");
}

TEST(BallView, StrobePositionsStandApartOnScreen) {
  const Loaded l = load("scenes/lollipop.toml", {"render.strobe=8", "render.layout=ball"});
  const SceneDrawer drawer(l.spec, l.model, nullptr);
  const render::DrawList list = drawer.draw(solveFrame(l.spec, l.model, 0.0));
  const render::View& v = list.views.at(0);
  struct Disc {
    glm::vec2 centre;
    float radius;
  };
  std::vector<Disc> balls;
  const glm::vec3 right = glm::transpose(glm::mat3(v.camera.viewFromWorld))[0];
  for (const render::MeshItem& m : list.meshes) {
    if (m.view != 0 || m.material.pattern != render::Pattern::Texture) continue;
    const glm::vec3 c(m.worldFromModel[3]);
    const float radius = glm::length(glm::vec3(m.worldFromModel[0]));
    const glm::vec3 p = ndc(v, c), q = ndc(v, c + radius * right);
    const glm::vec2 scale(0.5f * float(v.width), 0.5f * float(v.height));  // NDC → pixels
    balls.push_back({glm::vec2(p) * scale, glm::length((glm::vec2(q) - glm::vec2(p)) * scale)});
  }
  ASSERT_EQ(balls.size(), 8u);
  // Neighbours may touch, not cover each other: seen from 40° up, as before,
  // the closest pair overlapped by a quarter of their radii.
  for (std::size_t i = 0; i < balls.size(); ++i)
    for (std::size_t j = i + 1; j < balls.size(); ++j)
      EXPECT_GE(glm::length(balls[i].centre - balls[j].centre), 0.95f * (balls[i].radius + balls[j].radius))
          << "balls " << i << " and " << j;
}

// The surface mesh of a cylinder or torus (coordinates that are angles) may
// go once round, but not further: a second sheet on the first z-fights in
// stripes. Its area (flat triangles: a little under the surface's) can then
// not exceed one turn's: 2πa·(height) for a cylinder about z, 4π²Aa for a
// torus.
template <class OneTurnArea>
void expectSurfaceMeshedOnce(const std::string& scene, OneTurnArea oneTurnArea) {
  const Loaded l = load(scene);
  const SceneDrawer drawer(l.spec, l.model, nullptr);
  const render::DrawList list = drawer.draw(solveFrame(l.spec, l.model, 0.5 * l.model.path->length()));
  const render::MeshData* surface = nullptr;
  for (const render::MeshItem& m : list.meshes)
    if (m.view == 0 && !m.dynamic && m.material.lit && m.material.opacity >= 1.0f &&
        (surface == nullptr || m.mesh->vertices.size() > surface->vertices.size()))
      surface = m.mesh.get();
  ASSERT_NE(surface, nullptr) << scene;
  double area = 0.0;
  for (std::size_t t = 0; t + 2 < surface->indices.size(); t += 3) {
    const glm::dvec3 a(surface->vertices[surface->indices[t]].position);
    const glm::dvec3 b(surface->vertices[surface->indices[t + 1]].position);
    const glm::dvec3 c(surface->vertices[surface->indices[t + 2]].position);
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  const double bound = oneTurnArea(*surface);
  EXPECT_LE(area, bound * (1.0 + 1e-6)) << scene << ": the mesh covers " << area / bound << " turns";
  EXPECT_GT(area, 0.3 * bound) << scene;  // the whole path's band, not a sliver
}

TEST(BallView, AnglesAreMeshedOnceRound) {
  expectSurfaceMeshedOnce("scenes/cylinder-helix.toml", [](const render::MeshData& m) {
    float z0 = 1e30f, z1 = -1e30f;
    for (const render::Vertex& v : m.vertices) z0 = std::min(z0, v.position.z), z1 = std::max(z1, v.position.z);
    return 2.0 * std::numbers::pi * 2.0 * double(z1 - z0);  // radius a = 2, axis z
  });
  expectSurfaceMeshedOnce("scenes/torus.toml", [](const render::MeshData&) {
    return 4.0 * std::numbers::pi * std::numbers::pi * 4.0 * 1.5;  // A = 4, a = 1.5
  });
}

// A curved surface meshed in its own chart shows checker cells of about the
// ball's radius all over: within a factor 4.5 of R along both chart
// directions, or, where the chart stretches its cells more than that (the
// steep paraboloid: an x-cell on its wall was R/27 across, fine stripes
// with moiré), world-space cubes of R.
TEST(BallView, ChartCheckerCellsAreAboutTheBallsRadius) {
  int charts = 0, solid = 0;
  // Under ROLLSPIN_TEST_SWEEP=sample a quarter of the scenes, and always the
  // paraboloid (the world-cube case).
  std::vector<std::filesystem::path> scenes = test::sweep(test::bundledSceneFiles());
  const std::filesystem::path paraboloid = test::sourceDir() / "scenes/paraboloid-story.toml";
  if (std::find(scenes.begin(), scenes.end(), paraboloid) == scenes.end()) scenes.push_back(paraboloid);
  for (const std::filesystem::path& file : scenes) {
    const Loaded l = load(std::filesystem::relative(file, test::sourceDir()).string());
    if (!l.model.surface || l.model.surface->look().mesh != geometry::SurfaceLook::Mesh::Chart) continue;
    const SceneDrawer drawer(l.spec, l.model, nullptr);
    const render::DrawList list = drawer.draw(solveFrame(l.spec, l.model, 0.0));
    const double R = l.model.ballRadius;
    const std::string name = file.stem().string();
    const render::MeshItem* surfaceItem = nullptr;
    for (const render::MeshItem& m : list.meshes)
      if (m.material.receivesShadow &&
          (m.material.pattern == render::Pattern::Checker || m.material.pattern == render::Pattern::SolidChecker))
        surfaceItem = &m;
    ASSERT_NE(surfaceItem, nullptr) << name;
    ++charts;
    if (surfaceItem->material.pattern == render::Pattern::SolidChecker) {
      ++solid;
      EXPECT_NEAR(surfaceItem->material.patternScale.x, 1.0 / R, 1e-6 / R) << name;
      continue;
    }
    // Each triangle's cell edges: the chart's Jacobian from its corners
    // (one unit of uv is one cell).
    double shortest = 1e300, longest = 0.0;
    const render::MeshData& mesh = *surfaceItem->mesh;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const render::Vertex& a = mesh.vertices[mesh.indices[t]];
      const render::Vertex& b = mesh.vertices[mesh.indices[t + 1]];
      const render::Vertex& c = mesh.vertices[mesh.indices[t + 2]];
      const glm::dmat2 uvEdges(glm::dvec2(b.uv - a.uv), glm::dvec2(c.uv - a.uv));
      if (std::abs(glm::determinant(uvEdges)) < 1e-12) continue;
      const glm::dmat2 inverse = glm::inverse(uvEdges);
      const glm::dvec3 e1(b.position - a.position), e2(c.position - a.position);
      for (int k = 0; k < 2; ++k) {
        // d position / d uv_k = e1 · inverse[k][0] + e2 · inverse[k][1]
        const double edge =
            glm::length(e1 * inverse[k][0] + e2 * inverse[k][1]) *
            double(k == 0 ? surfaceItem->material.patternScale.x : surfaceItem->material.patternScale.y);
        shortest = std::min(shortest, edge);
        longest = std::max(longest, edge);
      }
    }
    EXPECT_GT(shortest, R / 4.5) << name << ": a checker cell is " << shortest / R << " R across";
    EXPECT_LT(longest, 4.5 * R) << name << ": a checker cell is " << longest / R << " R long";
  }
  EXPECT_GE(charts, test::sweepSampled() ? 2 : 8);
  EXPECT_GE(solid, 1);  // paraboloid-story
}

// A growing line (trail, travelled path) is drawn as a static settled prefix
// and a dynamic rest: together they are the whole line, joined at one shared
// point, and over a clip the static prefix changes only at the few
// checkpoints, so a retained layer is rebuilt a few times, not every frame.
TEST(BallView, GrowingLinesSettleAtAFewCheckpoints) {
  const Loaded l = load("scenes/lollipop.toml");
  const SceneDrawer drawer(l.spec, l.model, nullptr);
  const double length = l.model.path->length();
  const std::vector<glm::vec4> growing{kTravelledColor, kMarkerTrailColor, kBlochTrailColor, kFieldTrailColor};
  std::vector<std::set<std::vector<float>>> prefixes(growing.size());
  constexpr int kFrames = 300;  // a 10 s clip at 30 fps
  for (int f = 0; f < kFrames; ++f) {
    const motion::FrameOrientations frame = solveFrame(l.spec, l.model, length * f / (kFrames - 1));
    const render::DrawList list = drawer.draw(frame);
    for (std::size_t g = 0; g < growing.size(); ++g) {
      std::vector<const render::PolylineItem*> parts;
      for (const render::PolylineItem& p : list.polylines)
        if (p.color == growing[g]) parts.push_back(&p);
      ASSERT_FALSE(parts.empty()) << "line " << g << " frame " << f;
      ASSERT_LE(parts.size(), 2u);
      const render::PolylineItem& last = *parts.back();
      EXPECT_TRUE(last.dynamic || parts.size() == 1) << "line " << g << " frame " << f;
      if (parts.size() == 2) {
        const render::PolylineItem& prefix = *parts.front();
        EXPECT_FALSE(prefix.dynamic);
        EXPECT_EQ(prefix.points.back(), last.points.front()) << "the parts must join";
        std::vector<float> key;
        for (const glm::vec3& p : prefix.points) key.insert(key.end(), {p.x, p.y, p.z});
        prefixes[g].insert(key);
      }
      // The parts are the one line the frame would draw: the trail ends at s.
      if (g == 2) {
        std::size_t points = 0;
        for (const auto* p : parts) points += p->points.size();
        EXPECT_EQ(points, frame.trail.size() + parts.size() - 1) << "frame " << f;
      }
    }
  }
  for (std::size_t g = 0; g < growing.size(); ++g) {
    EXPECT_GE(prefixes[g].size(), 3u) << "line " << g << ": the prefix should grow over the clip";
    EXPECT_LE(prefixes[g].size(), kGrowingLineCheckpoints + 1) << "line " << g;
  }
}

TEST(BallView, OnAWallTheShadowFallsBelowTheBall) {
  const Loaded l = load("scenes/wall.toml");
  const SceneDrawer drawer(l.spec, l.model, nullptr);
  const double R = l.model.ballRadius;
  const double s = 0.3 * l.model.path->length();
  const render::DrawList list = drawer.draw(solveFrame(l.spec, l.model, s));
  const render::Light& light = list.views.at(0).light;
  const glm::vec3 n(0.0f, -1.0f, 0.0f);  // the wall's normal (scenes/wall.toml)
  const glm::vec3 toward = glm::normalize(light.towardLight);
  EXPECT_GT(glm::dot(toward, n), 0.2f) << "the wall must be lit from its front";
  // Where the light ray through the ball's centre meets the wall: the
  // middle of the shadow, which should lie well below the centre.
  const geometry::DarbouxSample f = l.model.path->at(s);
  const glm::vec3 centre(float(f.centre(R).x()), float(f.centre(R).y()), float(f.centre(R).z()));
  const glm::vec3 onWall(float(f.point.x()), float(f.point.y()), float(f.point.z()));
  const float t = glm::dot(centre - onWall, n) / glm::dot(toward, n);
  const glm::vec3 shadowMiddle = centre - t * toward;
  EXPECT_LT(shadowMiddle.z, centre.z - 0.8f * float(R));
}

}  // namespace
}  // namespace rollspin::draw
