// The layout's occupancy grid marks exactly the cells a disc reaches: a cell
// whose nearest point lies within the radius of the centre (checked against
// that definition, cell by cell, for discs of every size and place).
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "draw/clip_layout.hpp"

namespace rollspin::draw {
namespace {

// The definition, one cell at a time (what Occupancy::disc did before it
// marked runs of cells): among the cells of the disc's bounding box, those
// whose nearest point lies within r of the centre.
bool reaches(glm::vec2 c, float r, float cell, int x, int y) {
  if (x < int(std::floor((c.x - r) / cell)) || x > int(std::floor((c.x + r) / cell)) ||
      y < int(std::floor((c.y - r) / cell)) || y > int(std::floor((c.y + r) / cell)))
    return false;
  const float nx = std::clamp(c.x, float(x) * cell, float(x + 1) * cell);
  const float ny = std::clamp(c.y, float(y) * cell, float(y + 1) * cell);
  return (nx - c.x) * (nx - c.x) + (ny - c.y) * (ny - c.y) <= r * r;
}

TEST(Occupancy, ADiscMarksExactlyTheCellsItReaches) {
  std::mt19937 random(7);
  int compared = 0, marked = 0;
  for (const auto& [width, height] :
       {std::pair{192, 108}, std::pair{640, 360}, std::pair{1920, 1080}, std::pair{85, 301}}) {
    // The grid's cell, as the constructor sets it (about 160 across the height).
    const float cell = std::max(1.0f, float(height) / 160.0f);
    std::uniform_real_distribution<float> x(-0.2f * float(width), 1.2f * float(width));
    std::uniform_real_distribution<float> y(-0.2f * float(height), 1.2f * float(height));
    std::uniform_real_distribution<float> logRadius(std::log(0.05f), std::log(0.6f * float(height)));
    for (int trial = 0; trial < 300; ++trial) {
      Occupancy grid(width, height);
      // Whole and half cells, cell corners and arbitrary places.
      glm::vec2 c(x(random), y(random));
      if (trial % 3 == 1) c = glm::round(c / cell) * cell;
      if (trial % 3 == 2) c = (glm::floor(c / cell) + 0.5f) * cell;
      const float r = trial % 10 == 0 ? 0.0f : std::exp(logRadius(random));
      grid.disc(c, r);
      const int cellsX = int(std::ceil(float(width) / cell)), cellsY = int(std::ceil(float(height) / cell));
      for (int cy = 0; cy < cellsY; ++cy)
        for (int cx = 0; cx < cellsX; ++cx) {
          // anyIn over one cell's interior asks for that cell alone.
          const glm::vec2 middle = (glm::vec2(float(cx), float(cy)) + 0.5f) * cell;
          const bool isMarked = grid.anyIn(middle, middle);
          ASSERT_EQ(isMarked, reaches(c, r, cell, cx, cy))
              << width << "x" << height << ": disc at (" << c.x << ", " << c.y << ") radius " << r << ", cell (" << cx
              << ", " << cy << ")";
          ++compared;
          marked += isMarked ? 1 : 0;
        }
    }
  }
  EXPECT_GT(marked, 10000);  // the discs reached the grid, often
  EXPECT_GT(compared, marked);
}

}  // namespace
}  // namespace rollspin::draw
