// Thinning a patch's grid for export (src/export/grid_thinning.hpp): a flat
// patch keeps its corners only, a curved one keeps every dropped line within
// the tolerance of its chord and its texture coordinates, and anything that
// is not such a grid comes back unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "export/grid_thinning.hpp"
#include "render/mesh_builders.hpp"

namespace rollspin::gltf {
namespace {

std::shared_ptr<render::MeshData> cylinderPatch(int na, int nb, double radius) {
  return render::parametricPatch(
      [&](float a, float b, glm::vec3& p, glm::vec3& n) {
        const double phi = std::numbers::pi * double(a);  // half a turn round, straight along b
        n = glm::vec3(float(std::cos(phi)), float(std::sin(phi)), 0.0f);
        p = float(radius) * n + glm::vec3(0.0f, 0.0f, 4.0f * b);
      },
      na, nb, glm::vec2(6.0f, 3.0f));
}

TEST(GridThinning, AFlatPatchKeepsItsCornersAndTheirCells) {
  const auto flat = render::parametricPatch(
      [](float a, float b, glm::vec3& p, glm::vec3& n) {
        p = glm::vec3(3.0f * a, 2.0f * b, 0.0f);
        n = glm::vec3(0.0f, 0.0f, 1.0f);
      },
      32, 24, glm::vec2(8.0f, 5.0f));
  EXPECT_EQ(gridSizeOf(*flat).na, 32);
  EXPECT_EQ(gridSizeOf(*flat).nb, 24);
  const render::MeshData thin = thinGrid(*flat, 1e-4, 1e-4);
  ASSERT_EQ(thin.vertices.size(), 4u);
  EXPECT_EQ(thin.indices.size(), 6u);
  EXPECT_EQ(thin.vertices[3].uv, glm::vec2(8.0f, 5.0f));
  EXPECT_EQ(thin.vertices[3].position, glm::vec3(3.0f, 2.0f, 0.0f));
}

// A tolerance per vertex: tight on the first half of the columns, loose on
// the rest; the columns thin only where they may, and a scalar tolerance is
// the same as that value at every vertex.
TEST(GridThinning, EachVertexKeepsWithinItsOwnTolerance) {
  const double radius = 2.0, tight = 0.001, loose = 0.02;
  const auto fine = cylinderPatch(256, 16, radius);
  std::vector<double> tolerances(fine->vertices.size());
  for (std::size_t v = 0; v < tolerances.size(); ++v) tolerances[v] = v % 257 < 128 ? tight : loose;
  const render::MeshData thin = thinGrid(*fine, tolerances);
  int tightColumns = 0, looseColumns = 0;
  for (int k = 0; k <= gridSizeOf(thin).na; ++k) {
    const glm::vec3 p = thin.vertices[std::size_t(k)].position;
    for (int i = 0; i <= 256; ++i)
      if (fine->vertices[std::size_t(i)].position == p) (i < 128 ? tightColumns : looseColumns) += 1;
  }
  EXPECT_GT(tightColumns, 3 * looseColumns);
  EXPECT_EQ(gridSizeOf(thinGrid(*fine, std::vector<double>(fine->vertices.size(), loose))).na,
            gridSizeOf(thinGrid(*fine, loose, loose)).na);
  EXPECT_EQ(thinGrid(*fine, std::vector<double>(3, loose)).vertices.size(), fine->vertices.size())
      << "a tolerance for each vertex, or none thinned";
}

// z = x y is straight along every row and column: thinned by its lines
// alone it would keep only the corners, and the two triangles would miss
// its middle by a quarter of the corners' spread. Every fine vertex stays
// within the two tolerances of the triangle of its kept quad.
TEST(GridThinning, ATwistedPatchKeepsItsMiddle) {
  const double tolerance = 0.01;
  const auto fine = render::parametricPatch(
      [](float a, float b, glm::vec3& p, glm::vec3& n) {
        p = glm::vec3(2.0f * a - 1.0f, 2.0f * b - 1.0f, (2.0f * a - 1.0f) * (2.0f * b - 1.0f));
        n = glm::normalize(glm::vec3(-p.y, -p.x, 1.0f));
      },
      64, 64);
  const render::MeshData thin = thinGrid(*fine, tolerance, tolerance);
  EXPECT_GT(thin.vertices.size(), 4u);
  EXPECT_LT(thin.vertices.size(), fine->vertices.size());
  double worst = 0.0;
  for (const render::Vertex& v : fine->vertices) {
    // The thinned mesh's height at (x, y): the triangle that holds it.
    double z = 1e300;
    for (std::size_t t = 0; t + 2 < thin.indices.size() && z == 1e300; t += 3) {
      const glm::vec3 a = thin.vertices[thin.indices[t]].position, b = thin.vertices[thin.indices[t + 1]].position,
                      c = thin.vertices[thin.indices[t + 2]].position;
      const float d = (b.y - c.y) * (a.x - c.x) + (c.x - b.x) * (a.y - c.y);
      const float l1 = ((b.y - c.y) * (v.position.x - c.x) + (c.x - b.x) * (v.position.y - c.y)) / d;
      const float l2 = ((c.y - a.y) * (v.position.x - c.x) + (a.x - c.x) * (v.position.y - c.y)) / d;
      if (std::min({l1, l2, 1.0f - l1 - l2}) >= -1e-5f) z = l1 * a.z + l2 * b.z + (1.0f - l1 - l2) * c.z;
    }
    ASSERT_NE(z, 1e300) << "a fine vertex outside the thinned patch";
    worst = std::max(worst, std::abs(z - double(v.position.z)));
  }
  EXPECT_LE(worst, 2.0 * tolerance + 1e-6);
}

TEST(GridThinning, ACurvedPatchKeepsEveryDroppedColumnWithinItsChord) {
  const double radius = 2.0, tolerance = 0.01;
  const auto fine = cylinderPatch(256, 16, radius);
  const render::MeshData thin = thinGrid(*fine, tolerance, tolerance);
  const GridSize grid = gridSizeOf(thin);
  // Round: a chord of angle θ sags r (1 − cos(θ/2)), so about π / (2 acos(1 − tol/r)) columns; straight: one row.
  const double columns = std::numbers::pi / (2.0 * std::acos(1.0 - tolerance / radius));
  EXPECT_GE(grid.na, int(std::floor(columns)));
  EXPECT_LE(grid.na, int(std::ceil(columns)) + 1);
  EXPECT_EQ(grid.nb, 1);
  // Every fine vertex of the bottom row lies within the tolerance of the thinned polygon.
  for (int i = 0; i <= 256; ++i) {
    const glm::vec3& p = fine->vertices[std::size_t(i)].position;
    double nearest = 1e300;
    for (int k = 0; k < grid.na; ++k) {
      const glm::vec3 a = thin.vertices[std::size_t(k)].position, b = thin.vertices[std::size_t(k + 1)].position;
      const float x = glm::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
      nearest = std::min(nearest, double(glm::length(p - glm::mix(a, b, x))));
    }
    EXPECT_LE(nearest, tolerance + 1e-6) << "column " << i;
  }
  // The kept vertices are the fine grid's, with their texture coordinates.
  EXPECT_EQ(thin.vertices.front().uv, fine->vertices.front().uv);
  EXPECT_EQ(thin.vertices.back().uv, fine->vertices.back().uv);
}

TEST(GridThinning, RowToleranceZeroKeepsARoundSection) {
  const auto fine = cylinderPatch(12, 40, 1.0);  // round along a: with 0 there nothing goes
  const render::MeshData thin = thinGrid(*fine, 0.0, 0.1);
  EXPECT_EQ(gridSizeOf(thin).na, 12);
  EXPECT_EQ(gridSizeOf(thin).nb, 1);
}

TEST(GridThinning, AMeshThatIsNotAGridComesBackUnchanged) {
  render::MeshData mesh = *cylinderPatch(8, 8, 1.0);
  std::swap(mesh.indices[7], mesh.indices[8]);
  EXPECT_EQ(gridSizeOf(mesh).na, 0);
  const render::MeshData same = thinGrid(mesh, 1.0, 1.0);
  EXPECT_EQ(same.indices, mesh.indices);
  EXPECT_EQ(same.vertices.size(), mesh.vertices.size());
}

}  // namespace
}  // namespace rollspin::gltf
