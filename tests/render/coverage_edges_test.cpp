// Where a mesh can cover a pixel in part (render/coverage_edges.hpp),
// checked against brute force: a CPU rasterizer with 16 samples a pixel and
// a depth test, clipped as GL clips (near and far planes, a cut-away plane),
// finds every pixel whose samples do not all see one patch of surface (some
// miss the mesh, or two of them see triangles that share no vertex). Every
// such pixel must lie in a marked tile, for closed meshes, open patches,
// meshes with creases, views with the mesh behind the eye, and cut-away
// meshes; and not every tile may be marked. No GL.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "render/coverage_edges.hpp"
#include "render/mesh_builders.hpp"
#include "support/sweep.hpp"

namespace rollspin::render {
namespace {

constexpr int kImageWidth = 400, kImageHeight = 260;
constexpr int kGrid = 4;  // samples a pixel along each axis

View viewFrom(const glm::vec3& eye, const glm::vec3& target, float fovy, float near) {
  View v;
  v.x = 24;
  v.y = 10;
  v.width = 352;
  v.height = 240;
  v.camera.viewFromWorld = glm::lookAt(eye, target, glm::vec3(0, 0, 1));
  v.camera.position = eye;
  v.camera.clipFromView = glm::perspective(fovy, float(v.width) / float(v.height), near, 60.0f);
  return v;
}

// A vertex after the model and camera: clip coordinates and the cut's distance.
struct ClipVertex {
  glm::vec4 clip;
  float cut;
};

// The sample buffer: per sample the nearest depth and its triangle.
struct Samples {
  int width, height;
  std::vector<float> depth;
  std::vector<int> triangle;
  Samples(int w, int h)
      : width(w),
        height(h),
        depth(std::size_t(w) * h * kGrid * kGrid, 2.0f),
        triangle(std::size_t(w) * h * kGrid * kGrid, -1) {}
};

// Lexicographic order of points, so that a shared edge is computed the same
// way from either of its triangles.
template <typename V>
bool before(const V& a, const V& b) {
  for (int i = 0; i < V::length(); ++i)
    if (a[i] != b[i]) return a[i] < b[i];
  return false;
}

// Sutherland–Hodgman against z + w ≥ 0, w − z ≥ 0 and the cut ≥ 0 (GL's
// near and far planes and gl_ClipDistance), then each fan triangle
// rasterized at every sample it covers, the nearest kept. Watertight: an
// edge's function is evaluated from its ends in one order whichever
// triangle asks, and a sample on it goes to one side (as GL's fill rule
// gives it to one triangle), so no sample falls through a shared edge.
void rasterize(const std::vector<ClipVertex>& triangle, int id, const View& v, Samples& out) {
  std::vector<ClipVertex> poly = triangle, next;
  for (int plane = 0; plane < 3; ++plane) {
    auto dist = [&](const ClipVertex& p) {
      return plane == 0 ? p.clip.z + p.clip.w : plane == 1 ? p.clip.w - p.clip.z : p.cut;
    };
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const ClipVertex& a = poly[i];
      const ClipVertex& b = poly[(i + 1) % poly.size()];
      const float da = dist(a), db = dist(b);
      if (da >= 0.0f) next.push_back(a);
      if ((da >= 0.0f) != (db >= 0.0f)) {
        const bool aFirst = before(a.clip, b.clip);
        const ClipVertex& lo = aFirst ? a : b;
        const ClipVertex& hi = aFirst ? b : a;
        const float dlo = dist(lo), dhi = dist(hi);
        const float t = dlo / (dlo - dhi);
        next.push_back({lo.clip + t * (hi.clip - lo.clip), lo.cut + t * (hi.cut - lo.cut)});
      }
    }
    std::swap(poly, next);
  }
  if (poly.size() < 3) return;
  std::vector<glm::vec3> screen;  // pixels (view-relative, y down) and NDC depth
  for (const ClipVertex& p : poly)
    screen.emplace_back((p.clip.x / p.clip.w * 0.5f + 0.5f) * float(v.width),
                        (0.5f - p.clip.y / p.clip.w * 0.5f) * float(v.height), p.clip.z / p.clip.w);
  // The edge p–q's function at (x, y), from its ends in one order.
  auto edge = [](glm::vec2 p, glm::vec2 q, float x, float y) {
    if (before(q, p)) std::swap(p, q);
    return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
  };
  for (std::size_t k = 1; k + 1 < screen.size(); ++k) {
    const glm::vec3 corner[3] = {screen[0], screen[k], screen[k + 1]};
    const glm::vec3 a = corner[0], b = corner[1], c = corner[2];
    const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area == 0.0f) continue;
    float side[3];  // the sign of each edge's function inside the triangle
    for (int e = 0; e < 3; ++e) {
      const glm::vec3 p = corner[e], q = corner[(e + 1) % 3], o = corner[(e + 2) % 3];
      side[e] = edge(glm::vec2(p), glm::vec2(q), o.x, o.y) > 0.0f ? 1.0f : -1.0f;
    }
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x})))),
              x1 = std::min(v.width - 1, int(std::floor(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y})))),
              y1 = std::min(v.height - 1, int(std::floor(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        for (int s = 0; s < kGrid * kGrid; ++s) {
          const float px = float(x) + (float(s % kGrid) + 0.5f) / kGrid;
          const float py = float(y) + (float(s / kGrid) + 0.5f) / kGrid;
          bool inside = true;
          for (int e = 0; e < 3 && inside; ++e) {
            const float f = edge(glm::vec2(corner[e]), glm::vec2(corner[(e + 1) % 3]), px, py) * side[e];
            inside = f > 0.0f || (f == 0.0f && side[e] > 0.0f);
          }
          if (!inside) continue;
          const float wa = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
          const float wb = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
          const float z = wa * a.z + wb * b.z + (1.0f - wa - wb) * c.z;
          const std::size_t at = (std::size_t(y) * v.width + x) * kGrid * kGrid + s;
          if (z < out.depth[at]) {
            out.depth[at] = z;
            out.triangle[at] = id;
          }
        }
  }
}

struct Result {
  int partial = 0;      // pixels covered in part (brute force)
  int missed = 0;       // of those, outside every marked tile
  int markedTiles = 0;  // of the view's tiles
  int viewTiles = 0;
};

Result check(const MeshData& mesh, const glm::mat4& worldFromModel, const glm::vec4& cutPlane, const View& v) {
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  std::vector<ClipVertex> placed;
  for (const Vertex& vertex : mesh.vertices) {
    const glm::vec4 world = worldFromModel * glm::vec4(vertex.position, 1.0f);
    placed.push_back({clipFromWorld * world, glm::dot(cutPlane, world)});
  }
  Samples samples(v.width, v.height);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    rasterize({placed[mesh.indices[t]], placed[mesh.indices[t + 1]], placed[mesh.indices[t + 2]]}, int(t / 3), v,
              samples);
  auto shareAVertex = [&](int a, int b) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (mesh.indices[std::size_t(a) * 3 + i] == mesh.indices[std::size_t(b) * 3 + j]) return true;
    return false;
  };
  TileGrid grid(kImageWidth, kImageHeight);
  addOutlineTiles(mesh, meshEdgesOf(mesh), worldFromModel, cutPlane, v, 2.0f, grid);
  Result r;
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) {
      const int* ids = &samples.triangle[(std::size_t(y) * v.width + x) * kGrid * kGrid];
      bool partial = false;
      for (int s = 0; s < kGrid * kGrid && !partial; ++s)
        for (int t = 0; t < s && !partial; ++t)
          partial = (ids[s] < 0) != (ids[t] < 0) || (ids[s] >= 0 && ids[t] >= 0 && !shareAVertex(ids[s], ids[t]));
      if (!partial) continue;
      ++r.partial;
      const int ix = v.x + x, iy = v.y + y;
      if (!grid.dirty[std::size_t(iy / TileGrid::kTile) * grid.cols + ix / TileGrid::kTile]) ++r.missed;
    }
  for (int ty = v.y / TileGrid::kTile; ty <= (v.y + v.height - 1) / TileGrid::kTile; ++ty)
    for (int tx = v.x / TileGrid::kTile; tx <= (v.x + v.width - 1) / TileGrid::kTile; ++tx) {
      ++r.viewTiles;
      r.markedTiles += grid.dirty[std::size_t(ty) * grid.cols + tx];
    }
  return r;
}

std::shared_ptr<MeshData> torus() {
  return parametricPatch(
      [](float a, float b, glm::vec3& p, glm::vec3& n) {
        const float u = 2.0f * std::numbers::pi_v<float> * a, w = 2.0f * std::numbers::pi_v<float> * b;
        n = glm::vec3(std::cos(u) * std::cos(w), std::sin(u) * std::cos(w), std::sin(w));
        p = glm::vec3(2.0f * std::cos(u), 2.0f * std::sin(u), 0.0f) + 0.7f * n;
      },
      24, 12);
}

std::shared_ptr<MeshData> board() {
  return parametricPatch(
      [](float a, float b, glm::vec3& p, glm::vec3& n) {
        p = glm::vec3(16.0f * a - 8.0f, 16.0f * b - 8.0f, 0.0f);
        n = glm::vec3(0, 0, 1);
      },
      6, 6);
}

const glm::vec4 kNoCut(0.0f, 0.0f, 0.0f, 1.0f);

TEST(CoverageEdges, EdgesHaveTwoTrianglesInsideAClosedMeshAndOneOnABorder) {
  const auto sphere = uvSphere(12, 6);
  const MeshEdges sphereEdges = meshEdgesOf(*sphere);
  const auto boundary = std::count_if(sphereEdges.triangles.begin(), sphereEdges.triangles.end(),
                                      [](const auto& t) { return t[1] == MeshEdges::kBorder; });
  // The uv sphere splits its vertices along the seam u = 0 ≡ 1 (one border
  // edge per ring on each side of it) and at the poles (a vertex per
  // segment: the edges between them belong to one triangle each, of no area).
  EXPECT_EQ(boundary, 2 * 6 + 2 * 12);
  const auto plane = board();
  const MeshEdges planeEdges = meshEdgesOf(*plane);
  const auto planeBorder = std::count_if(planeEdges.triangles.begin(), planeEdges.triangles.end(),
                                         [](const auto& t) { return t[1] == MeshEdges::kBorder; });
  EXPECT_EQ(planeBorder, 4 * 6);
  EXPECT_EQ(planeEdges.vertices.size(), std::size_t(6 * 7 * 2 + 6 * 6));
}

TEST(CoverageEdges, EveryPixelCoveredInPartLiesInAMarkedTile) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const auto sphere = uvSphere(16, 8);
  const auto ring = torus();
  const auto cylinder = unitCylinder(12);
  const auto cone = unitCone(12);
  const auto plane = board();
  int partial = 0, trials = 0;
  // A sweep over the random views (the sanitizer pass checks a quarter of
  // them, every mesh in each); every view's numbers are drawn either way.
  const std::vector<bool> visited = test::sweepMask(12);
  const int views = int(std::count(visited.begin(), visited.end(), true));
  for (int trial = 0; trial < 12; ++trial) {
    const glm::vec3 eye(7.0f * u(rng), 7.0f * u(rng), 2.0f + 4.0f * u(rng));
    const View v = viewFrom(eye, glm::vec3(0.6f * u(rng), 0.6f * u(rng), 0.0f), 0.6f + 0.3f * u(rng), 0.3f);
    const glm::mat4 spin = glm::rotate(glm::mat4(1.0f), 3.0f * u(rng), glm::normalize(glm::vec3(u(rng), u(rng), 1.0f)));
    struct Case {
      const MeshData* mesh;
      glm::mat4 worldFromModel;
      glm::vec4 cut;
      const char* name;
    };
    const glm::vec4 cut(glm::normalize(glm::vec3(u(rng), u(rng), u(rng))), 0.3f * u(rng));
    const Case cases[] = {
        {sphere.get(), glm::scale(spin, glm::vec3(2.0f)), kNoCut, "sphere"},
        {sphere.get(), glm::scale(spin, glm::vec3(2.0f)), cut, "sphere cut away"},
        {ring.get(), spin, kNoCut, "torus"},
        {cylinder.get(), glm::scale(spin, glm::vec3(1.0f, 1.0f, 2.5f)), kNoCut, "cylinder"},
        {cone.get(), glm::scale(spin, glm::vec3(1.5f)), kNoCut, "cone"},
        {plane.get(), glm::mat4(1.0f), kNoCut, "board"},
    };
    if (!visited[std::size_t(trial)]) continue;
    for (const Case& c : cases) {
      const Result r = check(*c.mesh, c.worldFromModel, c.cut, v);
      ++trials;
      partial += r.partial;
      EXPECT_EQ(r.missed, 0) << c.name << ", trial " << trial << ": " << r.missed << " of " << r.partial
                             << " pixels covered in part lie in no marked tile";
    }
  }
  EXPECT_GT(partial, 250 * views);  // the brute force found edges to check
  EXPECT_EQ(trials, 6 * views);
  std::printf("%d views, %d pixels covered in part\n", views, partial);
}

TEST(CoverageEdges, APlaneThroughTheNearPlaneIsMarkedWhereItIsCut) {
  // The eye just above a large board, looking along it: the board reaches
  // behind the eye, and the near plane cuts it inside the view.
  const auto plane = board();
  for (const float pitch : {-0.05f, -0.6f}) {
    const glm::vec3 eye(0.0f, 0.0f, 0.25f);
    const View v = viewFrom(eye, eye + glm::vec3(0.0f, std::cos(pitch), std::sin(pitch)), 1.4f, 0.4f);
    const Result r = check(*plane, glm::mat4(1.0f), kNoCut, v);
    EXPECT_GT(r.partial, 0) << "pitch " << pitch;
    EXPECT_EQ(r.missed, 0) << "pitch " << pitch;
  }
}

TEST(CoverageEdges, TheInsideOfAPlaneOrASphereIsNotMarked) {
  // Samples only near edges: a board seen from above marks its border's
  // tiles, not its middle.
  const auto plane = board();
  const View above = viewFrom(glm::vec3(0.0f, -3.0f, 9.0f), glm::vec3(0.0f), 0.9f, 0.3f);
  const Result r = check(*plane, glm::mat4(1.0f), kNoCut, above);
  EXPECT_EQ(r.missed, 0);
  EXPECT_LT(r.markedTiles, r.viewTiles / 2) << r.markedTiles << " of " << r.viewTiles;
  const auto sphere = uvSphere(48, 24);
  const View near = viewFrom(glm::vec3(0.0f, -6.0f, 0.0f), glm::vec3(0.0f), 0.8f, 0.3f);
  const Result s = check(*sphere, glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)), kNoCut, near);
  EXPECT_EQ(s.missed, 0);
  EXPECT_LT(s.markedTiles, s.viewTiles * 3 / 4) << s.markedTiles << " of " << s.viewTiles;
}

}  // namespace
}  // namespace rollspin::render
