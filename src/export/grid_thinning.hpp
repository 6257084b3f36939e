// Thinning a regular grid mesh for export: of the (na + 1) × (nb + 1)
// vertices of a parametric patch (render::parametricPatch's layout, row j,
// column i at j (na + 1) + i), keep whole columns and rows, greedily as far
// apart as the dropped ones allow: a dropped column i between kept i0 < i1
// must lie within `tolerance` of the chord of every row,
//   |P(i, j) − lerp(P(i0, j), P(i1, j), (i − i0) / (i1 − i0))| ≤ tolerance
// (a tolerance of its own per vertex: tolerance(i, j)),
// and rows likewise. Then every dropped vertex is checked against the
// triangle of its kept quad that holds it (a twisting surface, z = xy, is
// straight along rows and columns but not across a quad), and quads off by
// more than the two tolerances get lines back until none is. Texture
// coordinates are linear in (i, j) on such a patch, so the kept vertices
// carry the same checker cells; the surface moves by at most twice the
// tolerance (a column's and a row's sag, or the quad check's bound).
#pragma once

#include <vector>

#include "render/draw_list.hpp"

namespace rollspin::gltf {

// The grid's columns and rows (na, nb) when `mesh` is exactly a patch's
// grid (vertex count and every index as parametricPatch writes them), else
// {0, 0}.
struct GridSize {
  int na = 0, nb = 0;
};
[[nodiscard]] GridSize gridSizeOf(const render::MeshData& mesh);

// The thinned grid (as a patch of its own), or `mesh` unchanged when it is
// not a grid. Columns (along a) keep within `columnTolerance`, rows (along
// b) within `rowTolerance` (0: only rows in line with their neighbours go).
[[nodiscard]] render::MeshData thinGrid(const render::MeshData& mesh, double columnTolerance, double rowTolerance);

// The same with a tolerance of each vertex's own (`tolerances[v]` for
// mesh.vertices[v], both directions): a dropped vertex keeps within its own.
[[nodiscard]] render::MeshData thinGrid(const render::MeshData& mesh, const std::vector<double>& tolerances);

}  // namespace rollspin::gltf
