#include "render/mesh_builders.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rollspin::render {

namespace {
constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

void addGridIndices(MeshData& m, std::uint32_t base, int na, int nb) {
  for (int j = 0; j < nb; ++j)
    for (int i = 0; i < na; ++i) {
      const std::uint32_t a = base + j * (na + 1) + i, b = a + 1, c = a + (na + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
}

// A flat disc cap at height z facing ±z.
void addCap(MeshData& m, int segments, float z, float sign) {
  const auto centre = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.push_back({{0, 0, z}, {0, 0, sign}, {0.5f, 0.5f}});
  for (int i = 0; i <= segments; ++i) {
    const float phi = kTwoPi * i / segments;
    m.vertices.push_back(
        {{std::cos(phi), std::sin(phi), z}, {0, 0, sign}, {0.5f + 0.5f * std::cos(phi), 0.5f + 0.5f * std::sin(phi)}});
  }
  for (int i = 0; i < segments; ++i) {
    const std::uint32_t a = centre + 1 + i, b = a + 1;
    if (sign > 0) m.indices.insert(m.indices.end(), {centre, a, b});
    else m.indices.insert(m.indices.end(), {centre, b, a});
  }
}
}  // namespace

std::shared_ptr<MeshData> uvSphere(int longitudeSegments, int latitudeRings) {
  auto m = std::make_shared<MeshData>();
  // The seam column is duplicated so u runs 0 → 1 without wrapping.
  for (int j = 0; j <= latitudeRings; ++j) {
    const float v = float(j) / latitudeRings, theta = std::numbers::pi_v<float> * v;
    for (int i = 0; i <= longitudeSegments; ++i) {
      const float u = float(i) / longitudeSegments, phi = kTwoPi * u - std::numbers::pi_v<float>;
      const glm::vec3 p{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      m->vertices.push_back({p, p, {u, v}});
    }
  }
  // Rows run from +z (v = 0) downward; wind counter-clockwise seen from outside.
  for (int j = 0; j < latitudeRings; ++j)
    for (int i = 0; i < longitudeSegments; ++i) {
      const std::uint32_t a = j * (longitudeSegments + 1) + i, b = a + 1, c = a + (longitudeSegments + 1), d = c + 1;
      m->indices.insert(m->indices.end(), {a, c, d, a, d, b});
    }
  return m;
}

std::shared_ptr<MeshData> parametricPatch(const PatchFunction& f, int na, int nb, glm::vec2 uvScale) {
  auto m = std::make_shared<MeshData>();
  for (int j = 0; j <= nb; ++j)
    for (int i = 0; i <= na; ++i) {
      const float a = float(i) / na, b = float(j) / nb;
      Vertex v;
      f(a, b, v.position, v.normal);
      v.uv = glm::vec2(a, b) * uvScale;
      m->vertices.push_back(v);
    }
  addGridIndices(*m, 0, na, nb);
  return m;
}

std::shared_ptr<MeshData> unitCylinder(int segments) {
  auto m = std::make_shared<MeshData>();
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= segments; ++i) {
      const float phi = kTwoPi * i / segments;
      const glm::vec3 n{std::cos(phi), std::sin(phi), 0.0f};
      m->vertices.push_back({n + glm::vec3(0, 0, float(j)), n, {float(i) / segments, float(j)}});
    }
  addGridIndices(*m, 0, segments, 1);
  addCap(*m, segments, 0.0f, -1.0f);
  addCap(*m, segments, 1.0f, 1.0f);
  return m;
}

std::shared_ptr<MeshData> unitCone(int segments) {
  auto m = std::make_shared<MeshData>();
  // Side normals tilt up by 45° for a cone of height 1 and radius 1.
  for (int i = 0; i <= segments; ++i) {
    const float phi = kTwoPi * i / segments;
    const glm::vec3 n = glm::normalize(glm::vec3(std::cos(phi), std::sin(phi), 1.0f));
    m->vertices.push_back({{std::cos(phi), std::sin(phi), 0.0f}, n, {float(i) / segments, 0.0f}});
    m->vertices.push_back({{0.0f, 0.0f, 1.0f}, n, {float(i) / segments, 1.0f}});
  }
  for (int i = 0; i < segments; ++i) {
    const std::uint32_t a = 2 * i, apex = a + 1, b = a + 2;
    m->indices.insert(m->indices.end(), {a, b, apex});
  }
  addCap(*m, segments, 0.0f, -1.0f);
  return m;
}

glm::mat4 alongSegment(const glm::vec3& a, const glm::vec3& b, float radius) {
  const glm::vec3 d = b - a;
  const float len = glm::length(d);
  const glm::vec3 z = len > 0.0f ? d / len : glm::vec3(0, 0, 1);
  const glm::vec3 helper = std::abs(z.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
  const glm::vec3 x = glm::normalize(glm::cross(helper, z));
  const glm::vec3 y = glm::cross(z, x);
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(x * radius, 0.0f);
  m[1] = glm::vec4(y * radius, 0.0f);
  m[2] = glm::vec4(d, 0.0f);
  m[3] = glm::vec4(a, 1.0f);
  return m;
}

ArrowParts arrowParts(const glm::vec3& origin, const glm::vec3& tip, float shaftRadius) {
  const float len = glm::length(tip - origin);
  const float headLength = std::min(len * 0.35f, shaftRadius * 6.0f);
  const glm::vec3 neck = tip - (tip - origin) / len * headLength;
  return {alongSegment(origin, neck, shaftRadius), alongSegment(neck, tip, shaftRadius * 2.6f)};
}

}  // namespace rollspin::render
