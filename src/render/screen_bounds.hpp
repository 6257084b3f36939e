// Screen-space bounds for redrawing part of a frame (render/retained_layers.cpp's
// retained layers): pixel rectangles, the pixels world points or a sphere
// can reach in a view, and a tile mask as few rectangles. Plain data: no GL.
// A sphere (centre c, radius r, depth d = −c_z in view space) projects
// inside the tangents x/d = (c_x d ± r √(c_x² + d² − r²)) / (d² − r²).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "render/draw_list.hpp"

namespace rollspin::render {

// A rectangle of image pixels, top-left origin, half-open: [x0, x1) × [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  [[nodiscard]] bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool operator==(const PixelRect&) const = default;
};

[[nodiscard]] PixelRect intersect(const PixelRect& a, const PixelRect& b);
[[nodiscard]] PixelRect unite(const PixelRect& a, const PixelRect& b);
[[nodiscard]] bool overlaps(const PixelRect& a, const PixelRect& b);
// True when `bounds` overlaps one of `rects`.
[[nodiscard]] bool reachesAny(const std::vector<PixelRect>& rects, const PixelRect& bounds);

// The parts of a draw (runs of triangles, of line segments) kept for the
// dirty rectangles, merged into as few runs as possible: a part that begins
// where the run before ends extends it. Parts are given in drawing order,
// so drawing the runs in order draws the kept parts in their order.
class RunsOfParts {
 public:
  struct Run {
    std::size_t begin = 0, end = 0;
    bool operator==(const Run&) const = default;
  };
  void clear() { runs_.clear(); }
  void add(std::size_t begin, std::size_t end) {
    if (!runs_.empty() && runs_.back().end == begin) runs_.back().end = end;
    else runs_.push_back({begin, end});
  }
  [[nodiscard]] const std::vector<Run>& runs() const { return runs_; }

 private:
  std::vector<Run> runs_;
};

// The pixels (image coordinates) a set of world points can reach in view
// v, widened by `marginPx`; the whole view when one lies behind the eye.
[[nodiscard]] PixelRect screenBounds(const View& v, const glm::mat4& clipFromWorld, const glm::vec3* points,
                                     std::size_t count, float marginPx);

// The pixels a world-space sphere can cover in view v, widened by
// `marginPx`; none when the camera is not a plain perspective or
// orthographic one, or the sphere reaches the eye's plane.
[[nodiscard]] std::optional<PixelRect> sphereBounds(const View& v, const glm::vec3& centre, float radius,
                                                    float marginPx);

// The pixels of `box` (sphereBounds of the sphere, widened by marginPx)
// that the sphere can cover, widened by marginPx: horizontal bands of
// `bandRows` rows (aligned to multiples of it), each as wide as the
// silhouette over its rows, in columns rounded out to multiples of 4
// (llvmpipe's pixel blocks). Disjoint, top to bottom. The silhouette is
// held by a polygon whose edges touch the sphere's outline circle (a
// projection keeps lines tangent, so the projected polygon holds the
// projected outline); where a corner would lie behind the eye, `box` whole.
[[nodiscard]] std::vector<PixelRect> sphereBands(const View& v, const PixelRect& box, const glm::vec3& centre,
                                                 float radius, float marginPx, int bandRows);

// The set tiles of a cols × rows mask of `tile`-pixel tiles over a width ×
// height image, as disjoint rectangles: runs along each tile row, a run
// continuing the rectangle above it when it spans the same columns.
[[nodiscard]] std::vector<PixelRect> rectsOfTiles(const std::vector<std::uint8_t>& dirty, int cols, int rows, int tile,
                                                  int width, int height);

// Disjoint rectangles inside `area` gathered into islands: boxes that hold
// every rectangle touching another, widened by one pixel (a scissor needs
// it beyond what is read back: see drawOverLayer), merged until no two boxes
// meet, so that the boxes are disjoint and each pixel is drawn once.
[[nodiscard]] std::vector<PixelRect> separatedIslands(const std::vector<PixelRect>& rects, const PixelRect& area);

}  // namespace rollspin::render
