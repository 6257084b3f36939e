#include "render/screen_bounds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace rollspin::render {

PixelRect intersect(const PixelRect& a, const PixelRect& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

PixelRect unite(const PixelRect& a, const PixelRect& b) {
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

bool overlaps(const PixelRect& a, const PixelRect& b) { return !intersect(a, b).empty(); }

bool reachesAny(const std::vector<PixelRect>& rects, const PixelRect& bounds) {
  return std::any_of(rects.begin(), rects.end(), [&](const PixelRect& r) { return overlaps(r, bounds); });
}

PixelRect screenBounds(const View& v, const glm::mat4& clipFromWorld, const glm::vec3* points, std::size_t count,
                       float marginPx) {
  const PixelRect whole{v.x, v.y, v.x + v.width, v.y + v.height};
  float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec4 c = clipFromWorld * glm::vec4(points[i], 1.0f);
    if (c.w <= 1e-6f) return whole;
    const float x = (c.x / c.w * 0.5f + 0.5f) * float(v.width);
    const float y = (0.5f - c.y / c.w * 0.5f) * float(v.height);
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  if (count == 0) return {};
  auto toInt = [](float f) { return static_cast<int>(std::clamp(f, -1e7f, 1e7f)); };
  return intersect(PixelRect{v.x + toInt(std::floor(x0 - marginPx)), v.y + toInt(std::floor(y0 - marginPx)),
                             v.x + toInt(std::ceil(x1 + marginPx)) + 1, v.y + toInt(std::ceil(y1 + marginPx)) + 1},
                   whole);
}

// Perspective: in each of the planes (x, z) and (y, z) of view space the
// tangents from the eye to the sphere's circle have slopes x/d = (c d ± r
// √(c² + d² − r²)) / (d² − r²), d = −z the depth (Mara & McGuire, "2D
// polyhedral bounds of a clipped, perspective-projected 3D sphere", 2013).
std::optional<PixelRect> sphereBounds(const View& v, const glm::vec3& centre, float radius, float marginPx) {
  const glm::mat4& P = v.camera.clipFromView;
  // No skew, no x or y in w (frustum or ortho): x_ndc = P00 x/w + P20 z/w + P30/w.
  if (P[1][0] != 0.0f || P[0][1] != 0.0f || P[0][3] != 0.0f || P[1][3] != 0.0f) return std::nullopt;
  const glm::vec3 c(v.camera.viewFromWorld * glm::vec4(centre, 1.0f));
  float ndc[2][2];  // [axis][min, max]
  const bool perspective = P[2][3] == -1.0f && P[3][3] == 0.0f;
  const bool orthographic = P[2][3] == 0.0f && P[3][3] == 1.0f;
  if (!perspective && !orthographic) return std::nullopt;
  for (int axis = 0; axis < 2; ++axis) {
    const float ca = c[axis];
    if (orthographic) {
      const float mid = P[axis][axis] * ca + P[2][axis] * c.z + P[3][axis];
      const float half = std::abs(P[axis][axis]) * radius;
      ndc[axis][0] = mid - half;
      ndc[axis][1] = mid + half;
      continue;
    }
    const float d = -c.z;
    if (d - radius <= 1e-4f * std::max(1.0f, d)) return std::nullopt;
    const float t = std::sqrt(std::max(0.0f, ca * ca + d * d - radius * radius));
    const float denominator = d * d - radius * radius;
    const float lo = (ca * d - radius * t) / denominator, hi = (ca * d + radius * t) / denominator;
    // x_ndc = P00 (x/d) − P20 (the off-axis shift), P00 > 0.
    const float a = P[axis][axis] * lo - P[2][axis], b = P[axis][axis] * hi - P[2][axis];
    ndc[axis][0] = std::min(a, b);
    ndc[axis][1] = std::max(a, b);
  }
  const PixelRect whole{v.x, v.y, v.x + v.width, v.y + v.height};
  auto toInt = [](float f) { return static_cast<int>(std::clamp(f, -1e7f, 1e7f)); };
  const float x0 = (ndc[0][0] * 0.5f + 0.5f) * float(v.width), x1 = (ndc[0][1] * 0.5f + 0.5f) * float(v.width);
  const float y0 = (0.5f - ndc[1][1] * 0.5f) * float(v.height), y1 = (0.5f - ndc[1][0] * 0.5f) * float(v.height);
  return intersect(PixelRect{v.x + toInt(std::floor(x0 - marginPx)), v.y + toInt(std::floor(y0 - marginPx)),
                             v.x + toInt(std::ceil(x1 + marginPx)) + 1, v.y + toInt(std::ceil(y1 + marginPx)) + 1},
                   whole);
}

// The outline circle: where the rays from the eye touch the sphere. In
// perspective its plane is normal to the centre's direction, at c (1 − r²/D²)
// with radius r √(D² − r²) / D (D = |c|, view space); orthographic: the
// sphere's great circle facing the camera.
std::vector<PixelRect> sphereBands(const View& v, const PixelRect& box, const glm::vec3& centre, float radius,
                                   float marginPx, int bandRows) {
  const glm::mat4& P = v.camera.clipFromView;
  const glm::vec3 c(v.camera.viewFromWorld * glm::vec4(centre, 1.0f));
  const bool orthographic = P[2][3] == 0.0f && P[3][3] == 1.0f;
  glm::vec3 axis(0.0f, 0.0f, 1.0f), circleCentre = c;
  float circleRadius = radius;
  if (!orthographic) {
    const float distance = glm::length(c);
    if (distance <= radius) return {box};
    axis = c / distance;
    circleCentre = c * (1.0f - radius * radius / (distance * distance));
    circleRadius = radius * std::sqrt(distance * distance - radius * radius) / distance;
  }
  const glm::vec3 side =
      glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  const glm::vec3 up = glm::cross(axis, side);
  // A regular polygon around the circle (its edges touch it), projected.
  constexpr int kCorners = 32;
  const float toCorner = circleRadius / std::cos(std::numbers::pi_v<float> / kCorners);
  std::array<glm::vec2, kCorners> polygon;
  for (int k = 0; k < kCorners; ++k) {
    const float angle = 2.0f * std::numbers::pi_v<float> * float(k) / kCorners;
    const glm::vec4 clip =
        P * glm::vec4(circleCentre + toCorner * (std::cos(angle) * side + std::sin(angle) * up), 1.0f);
    if (clip.w <= 1e-6f) return {box};
    polygon[k] = glm::vec2(float(v.x) + (clip.x / clip.w * 0.5f + 0.5f) * float(v.width),
                           float(v.y) + (0.5f - clip.y / clip.w * 0.5f) * float(v.height));
  }
  std::vector<PixelRect> bands;
  auto floorTo = [](float f, int step) {
    return step * static_cast<int>(std::floor(std::clamp(f, -1e7f, 1e7f) / float(step)));
  };
  for (int y0 = floorTo(float(box.y0), bandRows); y0 < box.y1; y0 += bandRows) {
    // The polygon's extent across the band's rows, widened by the margin.
    const float lo = float(y0) - marginPx, hi = float(y0 + bandRows) + marginPx;
    float x0 = 1e30f, x1 = -1e30f;
    for (int k = 0; k < kCorners; ++k) {
      const glm::vec2 p = polygon[k], q = polygon[(k + 1) % kCorners];
      if (p.y >= lo && p.y <= hi) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      for (const float edge : {lo, hi})
        if ((p.y - edge) * (q.y - edge) < 0.0f) {
          const float x = p.x + (q.x - p.x) * (edge - p.y) / (q.y - p.y);
          x0 = std::min(x0, x), x1 = std::max(x1, x);
        }
    }
    if (x0 > x1) continue;
    const PixelRect band =
        intersect(PixelRect{floorTo(x0 - marginPx, 4), y0, floorTo(x1 + marginPx, 4) + 4, y0 + bandRows}, box);
    if (!band.empty()) bands.push_back(band);
  }
  return bands;
}

std::vector<PixelRect> rectsOfTiles(const std::vector<std::uint8_t>& dirty, int cols, int rows, int tile, int width,
                                    int height) {
  std::vector<PixelRect> rects;
  std::vector<std::size_t> open;  // rectangles that end at the current row
  for (int ty = 0; ty < rows; ++ty) {
    std::vector<std::size_t> nowOpen;
    for (int tx = 0; tx < cols;) {
      if (!dirty[static_cast<std::size_t>(ty) * cols + tx]) {
        ++tx;
        continue;
      }
      int end = tx;
      while (end < cols && dirty[static_cast<std::size_t>(ty) * cols + end]) ++end;
      const int x0 = tx * tile, x1 = std::min(width, end * tile);
      const int y0 = ty * tile, y1 = std::min(height, (ty + 1) * tile);
      auto same =
          std::find_if(open.begin(), open.end(), [&](std::size_t r) { return rects[r].x0 == x0 && rects[r].x1 == x1; });
      if (same != open.end()) {
        rects[*same].y1 = y1;
        nowOpen.push_back(*same);
      } else {
        rects.push_back({x0, y0, x1, y1});
        nowOpen.push_back(rects.size() - 1);
      }
      tx = end;
    }
    open = std::move(nowOpen);
  }
  return rects;
}

std::vector<PixelRect> separatedIslands(const std::vector<PixelRect>& rects, const PixelRect& area) {
  // The boxes kept are pairwise disjoint: a new one absorbs every kept box
  // it meets (growing, it may meet more) before it is kept. Each absorption
  // removes a box, so hundreds of rectangles (a 4K trail) stay cheap.
  std::vector<PixelRect> boxes;
  for (const PixelRect& r : rects) {
    const PixelRect c = intersect(r, area);
    if (c.empty()) continue;
    PixelRect box = intersect(PixelRect{c.x0 - 1, c.y0 - 1, c.x1 + 1, c.y1 + 1}, area);
    for (std::size_t k = 0; k < boxes.size();) {
      if (overlaps(boxes[k], box)) {
        box = unite(box, boxes[k]);
        boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(k));
        k = 0;
      } else {
        ++k;
      }
    }
    boxes.push_back(box);
  }
  return boxes;
}

}  // namespace rollspin::render
