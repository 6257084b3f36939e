// Where a mesh drawn at one sample could differ from the same mesh drawn in
// samples and resolved (render/view_pass.cpp draws the static opaque meshes
// at one sample and in samples only near these edges): the pixels a
// triangle covers in part. That is near an edge of the mesh's screen
// outline: an edge whose two triangles face opposite ways (a silhouette),
// an edge of one triangle (the mesh's border, or a crease whose vertices
// are split), or a cut (the near and far planes, a material's cut-away
// plane). Everywhere else every sample of a pixel shows the triangle its
// centre shows.
// Facing of triangle (a, b, c) in clip space: sign det[a_xyw; b_xyw; c_xyw]
// (Olano & Greer, "Triangle scan conversion using 2D homogeneous
// coordinates", 1997), valid for vertices behind the eye too.
// Plain data: no GL.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/draw_list.hpp"
#include "render/layer_key.hpp"

namespace rollspin::render {

// A mesh's edges by vertex index (a crease or seam with split vertices is
// two border edges), each with its triangles: the second is kBorder for an
// edge of one triangle, kShared for one of three or more.
struct MeshEdges {
  static constexpr std::int32_t kBorder = -1, kShared = -2;
  std::vector<std::array<std::uint32_t, 2>> vertices;
  std::vector<std::array<std::int32_t, 2>> triangles;
};
[[nodiscard]] MeshEdges meshEdgesOf(const MeshData& mesh);

// The tiles of `grid` within `marginPx` of the mesh's outline edges and
// cuts in view v (image pixels), the mesh placed by worldFromModel and cut
// away where dot(cutPlane, world) < 0.
void addOutlineTiles(const MeshData& mesh, const MeshEdges& edges, const glm::mat4& worldFromModel,
                     const glm::vec4& cutPlane, const View& v, float marginPx, TileGrid& grid);

// The tiles of `grid` within `marginPx` of the segment a–b, given in clip
// space (w > 0 at both ends), in view v.
void addSegmentTiles(const glm::vec4& a, const glm::vec4& b, const View& v, float marginPx, TileGrid& grid);

}  // namespace rollspin::render
