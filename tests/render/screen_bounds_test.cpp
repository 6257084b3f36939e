// Screen bounds for the retained layers (render/screen_bounds.hpp), checked
// against brute force: a sphere's bounds hold every projected point of it,
// and little more, for perspective, off-axis and orthographic cameras; a
// tile mask's rectangles cover exactly its tiles; islands are disjoint and
// hold every rectangle. No GL.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "render/screen_bounds.hpp"
#include "support/sweep.hpp"

namespace rollspin::render {
namespace {

View randomView(std::mt19937& rng, int kind) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  View v;
  v.x = 100;
  v.y = 50;
  v.width = 640;
  v.height = 360;
  const glm::vec3 eye(6.0f * u(rng), 6.0f * u(rng), 3.0f + 4.0f * u(rng));
  v.camera.viewFromWorld = glm::lookAt(eye, glm::vec3(0.5f * u(rng), 0.5f * u(rng), 0.0f), glm::vec3(0, 0, 1));
  v.camera.position = eye;
  const float aspect = float(v.width) / float(v.height);
  if (kind == 0) {
    v.camera.clipFromView = glm::perspective(0.4f + 0.5f * (u(rng) + 1.0f), aspect, 0.05f, 100.0f);
  } else if (kind == 1) {  // off-axis: a window of a wider frustum (the layout's narrowed camera)
    const float h = 0.05f * std::tan(0.4f), w = h * aspect, shiftX = 0.6f * w * u(rng), shiftY = 0.6f * h * u(rng);
    v.camera.clipFromView = glm::frustum(-w + shiftX, w + shiftX, -h + shiftY, h + shiftY, 0.05f, 100.0f);
  } else {
    const float half = 3.0f + u(rng);
    v.camera.clipFromView = glm::ortho(-half * aspect, half * aspect, -half, half, 0.05f, 100.0f);
  }
  return v;
}

TEST(ScreenBounds, ASpheresBoundsHoldEveryPointOfItAndLittleMore) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int checked = 0;
  // A sweep over the random trials (the sanitizer pass checks a quarter of
  // them); every trial's numbers are drawn either way.
  const std::vector<bool> visited = test::sweepMask(600);
  for (int trial = 0; trial < 600; ++trial) {
    const int kind = trial % 3;
    const View v = randomView(rng, kind);
    const glm::vec3 centre(1.5f * u(rng), 1.5f * u(rng), 0.5f * u(rng));
    const float radius = 0.1f + 0.4f * (u(rng) + 1.0f);
    if (!visited[std::size_t(trial)]) continue;
    const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
    // Brute force: a fine grid of points on the sphere, projected.
    std::vector<glm::vec3> points;
    for (int i = 0; i <= 180; ++i)
      for (int j = 0; j < 360; ++j) {
        const float th = std::numbers::pi_v<float> * float(i) / 180.0f;
        const float ph = 2.0f * std::numbers::pi_v<float> * float(j) / 360.0f;
        points.push_back(centre +
                         radius * glm::vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
      }
    const glm::vec3 inView(v.camera.viewFromWorld * glm::vec4(centre, 1.0f));
    const auto bounds = sphereBounds(v, centre, radius, 0.0f);
    if (kind != 2 && -inView.z - radius <= 0.06f) {
      EXPECT_FALSE(bounds.has_value()) << "trial " << trial << ": the sphere reaches the eye's plane";
      continue;
    }
    ASSERT_TRUE(bounds.has_value()) << "trial " << trial;
    const PixelRect brute = screenBounds(v, clipFromWorld, points.data(), points.size(), 0.0f);
    if (brute.empty()) continue;  // off screen
    ++checked;
    EXPECT_LE(bounds->x0, brute.x0) << "trial " << trial;
    EXPECT_LE(bounds->y0, brute.y0) << "trial " << trial;
    EXPECT_GE(bounds->x1, brute.x1) << "trial " << trial;
    EXPECT_GE(bounds->y1, brute.y1) << "trial " << trial;
    // A grid 1° apart misses the outline by less than a pixel or two.
    EXPECT_LE((bounds->x1 - bounds->x0) - (brute.x1 - brute.x0), 3) << "trial " << trial;
    EXPECT_LE((bounds->y1 - bounds->y0) - (brute.y1 - brute.y0), 3) << "trial " << trial;
  }
  const int swept = int(std::count(visited.begin(), visited.end(), true));
  EXPECT_GT(2 * checked, swept);  // more than half are on screen and checked
  std::printf("%d of %d trials checked\n", checked, swept);
}

// Every pixel near the sphere's projection lies in a band: the pixels
// within 1.5 px of a projected point of it (the margin is 2); the bands are
// disjoint, inside the box, and leave out most of its corners.
TEST(ScreenBounds, ASpheresBandsHoldEveryPixelNearItAndLeaveOutTheCorners) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int checked = 0, trimmed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int kind = trial % 3;
    const View v = randomView(rng, kind);
    const glm::vec3 centre(1.5f * u(rng), 1.5f * u(rng), 0.5f * u(rng));
    const float radius = 0.1f + 0.4f * (u(rng) + 1.0f);
    const auto box = sphereBounds(v, centre, radius, 2.0f);
    if (!box || box->empty()) continue;
    const int rows = trial % 2 == 0 ? 16 : 8;
    const std::vector<PixelRect> bands = sphereBands(v, *box, centre, radius, 2.0f, rows);
    std::vector<int> inBands(std::size_t(v.x + v.width) * (v.y + v.height), 0);
    long long area = 0;
    for (const PixelRect& b : bands) {
      ASSERT_FALSE(b.empty());
      ASSERT_EQ(intersect(b, *box), b) << "trial " << trial;
      area += static_cast<long long>(b.x1 - b.x0) * (b.y1 - b.y0);
      for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x) ASSERT_EQ(inBands[std::size_t(y) * (v.x + v.width) + x]++, 0) << trial;
    }
    const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
    for (int i = 0; i <= 90; ++i)
      for (int j = 0; j < 180; ++j) {
        const float th = std::numbers::pi_v<float> * float(i) / 90.0f;
        const float ph = 2.0f * std::numbers::pi_v<float> * float(j) / 180.0f;
        const glm::vec4 c =
            clipFromWorld * glm::vec4(centre + radius * glm::vec3(std::sin(th) * std::cos(ph),
                                                                  std::sin(th) * std::sin(ph), std::cos(th)),
                                      1.0f);
        const float px = float(v.x) + (c.x / c.w * 0.5f + 0.5f) * float(v.width);
        const float py = float(v.y) + (0.5f - c.y / c.w * 0.5f) * float(v.height);
        for (const float dx : {-1.5f, 0.0f, 1.5f})
          for (const float dy : {-1.5f, 0.0f, 1.5f}) {
            const int x = int(std::floor(px + dx)), y = int(std::floor(py + dy));
            if (x < box->x0 || x >= box->x1 || y < box->y0 || y >= box->y1) continue;
            ASSERT_EQ(inBands[std::size_t(y) * (v.x + v.width) + x], 1)
                << "trial " << trial << ": pixel " << x << "," << y << " near the sphere is in no band";
          }
      }
    ++checked;
    // A sphere whole in view, over a few bands: its box's corners (a fifth
    // of it) are mostly left out.
    const long long boxArea = static_cast<long long>(box->x1 - box->x0) * (box->y1 - box->y0);
    if (box->x0 > v.x && box->y0 > v.y && box->x1 < v.x + v.width && box->y1 < v.y + v.height &&
        box->y1 - box->y0 >= 8 * rows) {
      ++trimmed;
      EXPECT_LT(double(area), 0.92 * double(boxArea)) << "trial " << trial;
    }
  }
  EXPECT_GT(checked, 150);
  EXPECT_GT(trimmed, 20);
}

TEST(ScreenBounds, SkewedCamerasGetNoSphereBounds) {
  std::mt19937 rng(1);
  View v = randomView(rng, 0);
  v.camera.clipFromView[1][0] = 0.1f;
  EXPECT_FALSE(sphereBounds(v, glm::vec3(0.0f), 0.5f, 0.0f).has_value());
}

TEST(ScreenBounds, TileRectanglesCoverExactlyTheSetTiles) {
  std::mt19937 rng(3);
  constexpr int kTile = 32, width = 13 * kTile - 7, height = 9 * kTile - 20, cols = 13, rows = 9;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::uint8_t> dirty(cols * rows);
    const int density = trial % 5;  // sparse to full
    for (auto& d : dirty) d = std::uniform_int_distribution<int>(0, 4)(rng) < density + 1 ? 1 : 0;
    const std::vector<PixelRect> rects = rectsOfTiles(dirty, cols, rows, kTile, width, height);
    std::vector<int> covered(std::size_t(width) * height, 0);
    for (const PixelRect& r : rects) {
      ASSERT_FALSE(r.empty());
      ASSERT_TRUE(r.x0 >= 0 && r.y0 >= 0 && r.x1 <= width && r.y1 <= height);
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) ++covered[std::size_t(y) * width + x];
    }
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const int want = dirty[std::size_t(y / kTile) * cols + std::size_t(x / kTile)];
        ASSERT_EQ(covered[std::size_t(y) * width + x], want) << "trial " << trial << " pixel " << x << "," << y;
      }
  }
}

TEST(ScreenBounds, IslandsAreDisjointAndHoldEveryRectangle) {
  std::mt19937 rng(5);
  constexpr int kTile = 32, cols = 20, rows = 12, width = cols * kTile, height = rows * kTile;
  const PixelRect area{0, 0, width, height};
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::uint8_t> dirty(cols * rows);
    for (auto& d : dirty) d = std::uniform_int_distribution<int>(0, 9)(rng) < 2 ? 1 : 0;
    const std::vector<PixelRect> rects = rectsOfTiles(dirty, cols, rows, kTile, width, height);
    const std::vector<PixelRect> islands = separatedIslands(rects, area);
    for (std::size_t i = 0; i < islands.size(); ++i) {
      EXPECT_EQ(intersect(islands[i], area), islands[i]);
      for (std::size_t j = i + 1; j < islands.size(); ++j)
        EXPECT_FALSE(overlaps(islands[i], islands[j])) << "trial " << trial;
    }
    for (const PixelRect& r : rects) {
      int holders = 0;
      for (const PixelRect& island : islands) holders += intersect(island, r) == r ? 1 : 0;
      EXPECT_EQ(holders, 1) << "trial " << trial;
      // A scissor reaches a pixel beyond the rectangle, inside the area.
      const PixelRect widened = intersect({r.x0 - 1, r.y0 - 1, r.x1 + 1, r.y1 + 1}, area);
      int wideHolders = 0;
      for (const PixelRect& island : islands) wideHolders += intersect(island, widened) == widened ? 1 : 0;
      EXPECT_EQ(wideHolders, 1) << "trial " << trial;
    }
  }
}

TEST(ScreenBounds, ABoxReachesTheRectanglesItOverlaps) {
  const std::vector<PixelRect> rects{{0, 0, 10, 10}, {20, 0, 30, 10}};
  EXPECT_TRUE(reachesAny(rects, {5, 5, 8, 8}));
  EXPECT_TRUE(reachesAny(rects, {29, 9, 40, 40}));
  EXPECT_FALSE(reachesAny(rects, {10, 0, 20, 10}));  // half-open: touching edges do not overlap
  EXPECT_FALSE(reachesAny({}, {0, 0, 100, 100}));
}

// Kept parts that follow on from each other make one run; a part left out
// between them splits the run, in drawing order.
TEST(ScreenBounds, KeptPartsMergeIntoRunsWhereOneEndsAndTheNextBegins) {
  RunsOfParts parts;
  parts.add(0, 96);
  parts.add(96, 192);
  parts.add(288, 384);  // [192, 288) left out
  parts.add(384, 400);
  using Run = RunsOfParts::Run;
  EXPECT_EQ(parts.runs(), (std::vector<Run>{{0, 192}, {288, 400}}));
  // A polyline's parts share their end points: [0, 32], [32, 64], then [96, 128].
  parts.clear();
  parts.add(0, 32);
  parts.add(32, 64);
  parts.add(96, 128);
  EXPECT_EQ(parts.runs(), (std::vector<Run>{{0, 64}, {96, 128}}));
  parts.clear();
  EXPECT_TRUE(parts.runs().empty());
}

}  // namespace
}  // namespace rollspin::render
