#include "render/coverage_edges.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "render/screen_bounds.hpp"

namespace rollspin::render {

MeshEdges meshEdgesOf(const MeshData& mesh) {
  // Every triangle's three edges keyed by their sorted vertex pair, sorted:
  // an edge's triangles are then neighbours.
  std::vector<std::pair<std::uint64_t, std::int32_t>> keyed;
  keyed.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.indices[t + k], b = mesh.indices[t + (k + 1) % 3];
      if (a == b) continue;
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      keyed.emplace_back(key, static_cast<std::int32_t>(t / 3));
    }
  std::sort(keyed.begin(), keyed.end());
  MeshEdges edges;
  for (std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i + 1;
    while (j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
    const std::int32_t second = j - i == 1 ? MeshEdges::kBorder : j - i == 2 ? keyed[i + 1].second : MeshEdges::kShared;
    edges.vertices.push_back({std::uint32_t(keyed[i].first >> 32), std::uint32_t(keyed[i].first)});
    edges.triangles.push_back({keyed[i].second, second});
    i = j;
  }
  return edges;
}

void addSegmentTiles(const glm::vec4& a, const glm::vec4& b, const View& v, float marginPx, TileGrid& grid) {
  if (a.w <= 1e-9f || b.w <= 1e-9f) return;
  const float w = float(v.width), h = float(v.height);
  glm::vec2 p((a.x / a.w * 0.5f + 0.5f) * w, (0.5f - a.y / a.w * 0.5f) * h);
  glm::vec2 q((b.x / b.w * 0.5f + 0.5f) * w, (0.5f - b.y / b.w * 0.5f) * h);
  // Only the part inside the view (widened by the margin) reaches a tile.
  float t0 = 0.0f, t1 = 1.0f;
  const glm::vec2 d = q - p;
  const float lo[2] = {-marginPx, -marginPx}, hi[2] = {w + marginPx, h + marginPx};
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(d[axis]) < 1e-12f) {
      if (p[axis] < lo[axis] || p[axis] > hi[axis]) return;
      continue;
    }
    float ta = (lo[axis] - p[axis]) / d[axis], tb = (hi[axis] - p[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 > t1) return;
  const glm::vec2 from = p + t0 * d, to = p + t1 * d;
  // In pieces of at most 16 pixels: a long diagonal edge marks a band of
  // tiles along itself, not the box it spans.
  const int pieces = std::max(1, int(std::ceil(glm::length(to - from) / 16.0f)));
  const PixelRect area{v.x, v.y, v.x + v.width, v.y + v.height};
  for (int k = 0; k < pieces; ++k) {
    const glm::vec2 s = from + (to - from) * (float(k) / float(pieces));
    const glm::vec2 e = from + (to - from) * (float(k + 1) / float(pieces));
    const glm::vec2 mn = glm::min(s, e), mx = glm::max(s, e);
    grid.add(intersect(PixelRect{v.x + int(std::floor(mn.x - marginPx)), v.y + int(std::floor(mn.y - marginPx)),
                                 v.x + int(std::ceil(mx.x + marginPx)) + 1, v.y + int(std::ceil(mx.y + marginPx)) + 1},
                       area));
  }
}

namespace {

// A vertex in clip space with the signed distances of the three cuts that
// can end a triangle inside the view: the near plane (z + w), the far plane
// (w − z) and the cut-away plane. GL draws where all are ≥ 0.
struct Placed {
  glm::vec4 clip;
  float cuts[3];
};

Placed mixOf(const Placed& a, const Placed& b, float t) {
  Placed p;
  p.clip = a.clip + t * (b.clip - a.clip);
  for (int c = 0; c < 3; ++c) p.cuts[c] = a.cuts[c] + t * (b.cuts[c] - a.cuts[c]);
  return p;
}

// The part of a–b where every cut but `skip` is ≥ 0, as tiles.
void addClipped(const Placed& a, const Placed& b, int skip, const View& v, float marginPx, TileGrid& grid) {
  float t0 = 0.0f, t1 = 1.0f;
  for (int c = 0; c < 3; ++c) {
    if (c == skip) continue;
    const float fa = a.cuts[c], fb = b.cuts[c];
    if (fa < 0.0f && fb < 0.0f) return;
    if (fa < 0.0f) t0 = std::max(t0, fa / (fa - fb));
    if (fb < 0.0f) t1 = std::min(t1, fa / (fa - fb));
  }
  if (t0 > t1) return;
  addSegmentTiles(mixOf(a, b, t0).clip, mixOf(a, b, t1).clip, v, marginPx, grid);
}

}  // namespace

void addOutlineTiles(const MeshData& mesh, const MeshEdges& edges, const glm::mat4& worldFromModel,
                     const glm::vec4& cutPlane, const View& v, float marginPx, TileGrid& grid) {
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  const bool cutAway = cutPlane != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  std::vector<Placed> placed(mesh.vertices.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const glm::vec4 world = worldFromModel * glm::vec4(mesh.vertices[i].position, 1.0f);
    Placed& p = placed[i];
    p.clip = clipFromWorld * world;
    p.cuts[0] = p.clip.z + p.clip.w;
    p.cuts[1] = p.clip.w - p.clip.z;
    p.cuts[2] = cutAway ? glm::dot(cutPlane, world) : 1.0f;
  }
  // Facing: +1, −1, or 0 for a triangle seen edge-on (its edges count).
  const std::size_t triangles = mesh.indices.size() / 3;
  std::vector<std::int8_t> facing(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    auto xyw = [&](std::size_t k) {
      const glm::vec4& p = placed[mesh.indices[3 * t + k]].clip;
      return glm::dvec3(p.x, p.y, p.w);
    };
    const glm::dvec3 a = xyw(0), b = xyw(1), c = xyw(2);
    const double det = glm::dot(a, glm::cross(b, c));
    facing[t] = det > 0.0 ? 1 : det < 0.0 ? -1 : 0;
  }
  for (std::size_t e = 0; e < edges.vertices.size(); ++e) {
    const auto [t0, t1] = edges.triangles[e];
    const bool outline = t1 < 0 || facing[std::size_t(t0)] != facing[std::size_t(t1)] || facing[std::size_t(t0)] == 0;
    if (outline) addClipped(placed[edges.vertices[e][0]], placed[edges.vertices[e][1]], -1, v, marginPx, grid);
  }
  // Where a cut crosses a triangle, the segment on which it is zero.
  for (std::size_t t = 0; t < triangles; ++t) {
    const Placed* corner[3] = {&placed[mesh.indices[3 * t]], &placed[mesh.indices[3 * t + 1]],
                               &placed[mesh.indices[3 * t + 2]]};
    for (int c = 0; c < 3; ++c) {
      const bool neg[3] = {corner[0]->cuts[c] < 0.0f, corner[1]->cuts[c] < 0.0f, corner[2]->cuts[c] < 0.0f};
      if (neg[0] == neg[1] && neg[1] == neg[2]) continue;
      Placed ends[2];
      int found = 0;
      for (int k = 0; k < 3 && found < 2; ++k) {
        const Placed& a = *corner[k];
        const Placed& b = *corner[(k + 1) % 3];
        if (neg[k] == neg[(k + 1) % 3]) continue;
        ends[found++] = mixOf(a, b, a.cuts[c] / (a.cuts[c] - b.cuts[c]));
      }
      if (found == 2) addClipped(ends[0], ends[1], c, v, marginPx, grid);
    }
  }
}

}  // namespace rollspin::render
