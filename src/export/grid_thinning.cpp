#include "export/grid_thinning.hpp"

#include <cstdint>
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
  const std::vector<int> columns = keptLines(
      grid.na, grid.nb, [&](int i, int j) { return vertex(i, j); }, [&](int, int) { return columnTolerance; });
  const std::vector<int> rows = keptLines(
      grid.nb, grid.na, [&](int j, int i) { return vertex(i, j); }, [&](int, int) { return rowTolerance; });
  return keptGrid(mesh, grid, columns, rows);
}

render::MeshData thinGrid(const render::MeshData& mesh, const std::vector<double>& tolerances) {
  const GridSize grid = gridSizeOf(mesh);
  if (grid.na == 0 || tolerances.size() != mesh.vertices.size()) return mesh;
  const auto index = [&](int i, int j) { return std::size_t(j * (grid.na + 1) + i); };
  const std::vector<int> columns = keptLines(
      grid.na, grid.nb, [&](int i, int j) { return mesh.vertices[index(i, j)].position; },
      [&](int i, int j) { return tolerances[index(i, j)]; });
  const std::vector<int> rows = keptLines(
      grid.nb, grid.na, [&](int j, int i) { return mesh.vertices[index(i, j)].position; },
      [&](int j, int i) { return tolerances[index(i, j)]; });
  return keptGrid(mesh, grid, columns, rows);
}

}  // namespace rollspin::gltf
