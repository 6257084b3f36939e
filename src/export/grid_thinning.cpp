#include "export/grid_thinning.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace rollspin::gltf {

namespace {

// The kept lines of one direction: from 0, each next kept line is the
// farthest whose dropped lines between all lie within their vertices'
// tolerances of their chords. `at(line, across)` is the vertex on `line`
// at position `across` of the other direction (0 … acrossCount), and
// `tolerance(line, across)` that vertex's tolerance.
template <typename At, typename Tolerance>
std::vector<int> keptLines(int lines, int acrossCount, const At& at, const Tolerance& tolerance) {
  const auto fits = [&](int from, int to) {
    for (int k = 0; k <= acrossCount; ++k)
      for (int i = from + 1; i < to; ++i) {
        const float x = float(i - from) / float(to - from);
        const glm::vec3 chord = glm::mix(at(from, k), at(to, k), x);
        if (double(glm::length(at(i, k) - chord)) > tolerance(i, k)) return false;
      }
    return true;
  };
  std::vector<int> kept{0};
  while (kept.back() < lines) {
    int next = kept.back() + 1;
    // Grow while the next line still fits (a sag grows with the span, so
    // the first failure ends the span).
    while (next < lines && fits(kept.back(), next + 1)) ++next;
    kept.push_back(next);
  }
  return kept;
}

// Rows and columns are each thinned along their own lines, which misses a
// surface's twist (z = xy is straight along every row and column, yet a
// quad's two triangles cut its middle off by a quarter of its corners'
// spread): each dropped vertex is checked against the triangle of the kept
// quad it falls in (at its own place in the quad's index square: a, b, d
// or a, d, c as keptGrid splits it), and a quad that misses one gets back
// the column or row through its worst vertex (across its longer side),
// until none misses.
template <typename At, typename Tolerance>
void keepTheTwist(const At& at, const Tolerance& tolerance, std::vector<int>& columns, std::vector<int>& rows) {
  for (;;) {
    std::vector<int> addColumns, addRows;
    for (std::size_t q = 0; q + 1 < rows.size(); ++q)
      for (std::size_t p = 0; p + 1 < columns.size(); ++p) {
        const int i0 = columns[p], i1 = columns[p + 1], j0 = rows[q], j1 = rows[q + 1];
        if (i1 - i0 < 2 && j1 - j0 < 2) continue;
        const glm::vec3 a = at(i0, j0), b = at(i1, j0), c = at(i0, j1), d = at(i1, j1);
        double worst = 0.0;
        int worstI = -1, worstJ = -1;
        for (int j = j0; j <= j1; ++j)
          for (int i = i0; i <= i1; ++i) {
            const float x = float(i - i0) / float(i1 - i0), y = float(j - j0) / float(j1 - j0);
            const glm::vec3 onMesh = x >= y ? a + x * (b - a) + y * (d - b) : a + y * (c - a) + x * (d - c);
            const double excess = double(glm::length(at(i, j) - onMesh)) - tolerance(i, j);
            if (excess > worst) worst = excess, worstI = i, worstJ = j;
          }
        if (worstI < 0) continue;
        const bool splitColumns = (i1 - i0 >= j1 - j0 && worstI != i0 && worstI != i1) || worstJ == j0 || worstJ == j1;
        if (splitColumns) addColumns.push_back(worstI);
        else addRows.push_back(worstJ);
      }
    if (addColumns.empty() && addRows.empty()) return;
    for (auto [kept, added] : {std::pair{&columns, &addColumns}, std::pair{&rows, &addRows}}) {
      kept->insert(kept->end(), added->begin(), added->end());
      std::sort(kept->begin(), kept->end());
      kept->erase(std::unique(kept->begin(), kept->end()), kept->end());
    }
  }
}

// The grid of the kept columns and rows.
render::MeshData keptGrid(const render::MeshData& mesh, const GridSize& grid, const std::vector<int>& columns,
                          const std::vector<int>& rows) {
  render::MeshData out;
  for (const int j : rows)
    for (const int i : columns) out.vertices.push_back(mesh.vertices[std::size_t(j * (grid.na + 1) + i)]);
  const auto na = std::uint32_t(columns.size() - 1);
  for (std::uint32_t j = 0; j + 1 < rows.size(); ++j)
    for (std::uint32_t i = 0; i < na; ++i) {
      const std::uint32_t a = j * (na + 1) + i, b = a + 1, c = a + na + 1, d = c + 1;
      out.indices.insert(out.indices.end(), {a, b, d, a, d, c});
    }
  return out;
}

}  // namespace

GridSize gridSizeOf(const render::MeshData& mesh) {
  if (mesh.indices.size() < 6 || mesh.indices[0] != 0 || mesh.indices[1] != 1) return {};
  const int na = int(mesh.indices[2]) - 2;  // the first quad's far corner is (na + 1) + 1
  if (na < 1 || mesh.vertices.size() % std::size_t(na + 1) != 0) return {};
  const int nb = int(mesh.vertices.size() / std::size_t(na + 1)) - 1;
  if (nb < 1 || mesh.indices.size() != std::size_t(6 * na * nb)) return {};
  std::size_t t = 0;
  for (int j = 0; j < nb; ++j)
    for (int i = 0; i < na; ++i) {
      const auto a = std::uint32_t(j * (na + 1) + i), b = a + 1, c = a + std::uint32_t(na + 1), d = c + 1;
      for (const std::uint32_t v : {a, b, d, a, d, c})
        if (mesh.indices[t++] != v) return {};
    }
  return {na, nb};
}

render::MeshData thinGrid(const render::MeshData& mesh, double columnTolerance, double rowTolerance) {
  const GridSize grid = gridSizeOf(mesh);
  if (grid.na == 0) return mesh;
  const auto vertex = [&](int i, int j) -> const glm::vec3& {
    return mesh.vertices[std::size_t(j * (grid.na + 1) + i)].position;
  };
  std::vector<int> columns = keptLines(
      grid.na, grid.nb, [&](int i, int j) { return vertex(i, j); }, [&](int, int) { return columnTolerance; });
  std::vector<int> rows = keptLines(
      grid.nb, grid.na, [&](int j, int i) { return vertex(i, j); }, [&](int, int) { return rowTolerance; });
  keepTheTwist(
      vertex, [&](int, int) { return columnTolerance + rowTolerance; }, columns, rows);
  return keptGrid(mesh, grid, columns, rows);
}

render::MeshData thinGrid(const render::MeshData& mesh, const std::vector<double>& tolerances) {
  const GridSize grid = gridSizeOf(mesh);
  if (grid.na == 0 || tolerances.size() != mesh.vertices.size()) return mesh;
  const auto index = [&](int i, int j) { return std::size_t(j * (grid.na + 1) + i); };
  const auto vertex = [&](int i, int j) -> const glm::vec3& { return mesh.vertices[index(i, j)].position; };
  std::vector<int> columns = keptLines(grid.na, grid.nb, vertex, [&](int i, int j) { return tolerances[index(i, j)]; });
  std::vector<int> rows = keptLines(
      grid.nb, grid.na, [&](int j, int i) { return vertex(i, j); },
      [&](int j, int i) { return tolerances[index(i, j)]; });
  keepTheTwist(
      vertex, [&](int i, int j) { return 2.0 * tolerances[index(i, j)]; }, columns, rows);
  return keptGrid(mesh, grid, columns, rows);
}

}  // namespace rollspin::gltf
