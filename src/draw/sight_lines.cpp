#include "draw/sight_lines.hpp"

#include <algorithm>
#include <cmath>

namespace rollspin::draw {

namespace {

using Vec3 = SightLines::Vec3;

double side(const Eigen::Vector4d& plane, const Vec3& p) { return plane.head<3>().dot(p) + plane.w(); }

// Whether the segment p + t d, t in [t0, t1], meets the box [lo, hi] (slabs).
bool meetsBox(const Vec3& p, const Vec3& inverseD, const Eigen::Array3d& lo, const Eigen::Array3d& hi, double t1) {
  double t0 = 0.0;
  for (int k = 0; k < 3; ++k) {
    double a = (lo[k] - p[k]) * inverseD[k], b = (hi[k] - p[k]) * inverseD[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

SightLines::SightLines(const render::MeshData& mesh, const Eigen::Vector4d& cutPlane) : cut_(cutPlane) {
  auto at = [&](std::uint32_t i) {
    const auto& p = mesh.vertices[i].position;
    return Vec3(p.x, p.y, p.z);
  };
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const Vec3 a = at(mesh.indices[i]), b = at(mesh.indices[i + 1]), c = at(mesh.indices[i + 2]);
    if (side(cut_, a) < 0.0 && side(cut_, b) < 0.0 && side(cut_, c) < 0.0) continue;
    if ((b - a).cross(c - a).squaredNorm() == 0.0) continue;  // degenerate (a pole's fan)
    triangles_.push_back({a, b - a, c - a});
  }
  nodes_.reserve(triangles_.size() / 2 + 1);
  nodes_.emplace_back();
  if (!triangles_.empty()) build(0, 0, int(triangles_.size()));
}

// Median split along the longest axis of the centroids' box, down to leaves
// of at most 4 triangles. Node 0 is the root; children are allocated in pairs.
void SightLines::build(int node, int first, int count) {
  auto centroid = [](const Triangle& t) { return Vec3(t.a + (t.ab + t.ac) / 3.0); };
  Eigen::Array3d lo = Eigen::Array3d::Constant(1e300), hi = Eigen::Array3d::Constant(-1e300);
  Eigen::Array3d centresLo = lo, centresHi = hi;
  for (int i = first; i < first + count; ++i) {
    const Triangle& t = triangles_[std::size_t(i)];
    for (const Vec3& p : {t.a, Vec3(t.a + t.ab), Vec3(t.a + t.ac)}) {
      lo = lo.min(p.array());
      hi = hi.max(p.array());
    }
    centresLo = centresLo.min(centroid(t).array());
    centresHi = centresHi.max(centroid(t).array());
  }
  nodes_[std::size_t(node)] = {lo, hi, first, count};
  if (count <= 4) return;
  int axis = 0;
  (centresHi - centresLo).maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(triangles_.begin() + first, triangles_.begin() + first + half, triangles_.begin() + first + count,
                   [&](const Triangle& x, const Triangle& y) { return centroid(x)[axis] < centroid(y)[axis]; });
  const int left = int(nodes_.size());
  nodes_.resize(nodes_.size() + 2);
  nodes_[std::size_t(node)].first = left;
  nodes_[std::size_t(node)].count = 0;
  build(left, first, half);
  build(left + 1, first + half, count - half);
}

bool SightLines::blocked(const Vec3& from, const Vec3& to, double endGap) const {
  if (triangles_.empty()) return false;
  const Vec3 d = to - from;
  const double length = d.norm();
  if (length <= endGap) return false;
  const double tMax = 1.0 - endGap / length;
  const Vec3 inverseD(1.0 / d.x(), 1.0 / d.y(), 1.0 / d.z());
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[std::size_t(stack[--top])];
    if (!meetsBox(from, inverseD, node.lo, node.hi, tMax)) continue;
    if (node.count == 0) {
      if (top + 2 > 128) return false;  // deeper than any tree of this many triangles
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
      continue;
    }
    for (int i = node.first; i < node.first + node.count; ++i) {
      const Triangle& t = triangles_[std::size_t(i)];
      const Vec3 p = d.cross(t.ac);
      const double det = t.ab.dot(p);
      if (std::abs(det) < 1e-300) continue;
      const Vec3 s = from - t.a;
      const double u = s.dot(p) / det;
      if (u < 0.0 || u > 1.0) continue;
      const Vec3 q = s.cross(t.ab);
      const double v = d.dot(q) / det;
      if (v < 0.0 || u + v > 1.0) continue;
      const double hit = t.ac.dot(q) / det;
      if (hit <= 0.0 || hit >= tMax) continue;
      if (side(cut_, from + hit * d) < 0.0) continue;  // that part is cut away
      return true;
    }
  }
  return false;
}

double SightLines::visibleShare(const Vec3& eye, const Vec3& centre, double radius, int rays) const {
  const Vec3 view = (centre - eye).normalized();
  const Vec3 u = view.cross(std::abs(view.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX()).normalized();
  const Vec3 v = view.cross(u);
  int seen = 0;
  for (int k = 0; k < rays; ++k) {
    // Sunflower spread: equal areas of the disc per ray.
    const double rho = std::sqrt((k + 0.5) / rays), phi = 2.399963229728653 * k;
    const Vec3 p =
        centre + radius * (rho * (std::cos(phi) * u + std::sin(phi) * v) - std::sqrt(1.0 - rho * rho) * view);
    if (!blocked(eye, p, 1e-6 * radius)) ++seen;
  }
  return double(seen) / rays;
}

}  // namespace rollspin::draw
