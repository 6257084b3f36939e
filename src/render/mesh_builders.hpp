// Mesh generators for the DrawList: plain vertex/index data, no GL.
// All meshes are in model coordinates; place them with MeshItem::worldFromModel.
#pragma once

#include <functional>
#include <memory>

#include "render/draw_list.hpp"

namespace rollspin::render {

// Unit sphere, z the polar axis. uv = (longitude / 2π + ½, colatitude / π),
// i.e. equirectangular: u = atan2(y, x)/2π + ½, v = acos(z)/π (v = 0 at +z).
[[nodiscard]] std::shared_ptr<MeshData> uvSphere(int longitudeSegments, int latitudeRings);

// A parametric surface patch: (a, b) ∈ [0, 1]² → position, normal; uv = (a, b)
// scaled by uvScale. Triangulated on an na × nb grid.
using PatchFunction = std::function<void(float a, float b, glm::vec3& position, glm::vec3& normal)>;
[[nodiscard]] std::shared_ptr<MeshData> parametricPatch(const PatchFunction& f, int na, int nb,
                                                        glm::vec2 uvScale = glm::vec2(1.0f));

// Closed cylinder of radius 1 from z = 0 to z = 1 (with caps).
[[nodiscard]] std::shared_ptr<MeshData> unitCylinder(int segments);
// Cone of base radius 1 at z = 0, apex at z = 1 (with base cap).
[[nodiscard]] std::shared_ptr<MeshData> unitCone(int segments);

// worldFromModel for a unit z-aligned primitive (unitCylinder, unitCone)
// stretched from a to b with the given radius.
[[nodiscard]] glm::mat4 alongSegment(const glm::vec3& a, const glm::vec3& b, float radius);

// An ArrowItem as drawn: a unitCylinder shaft and a unitCone head 2.6 shaft
// radii wide and min(0.35 length, 6 radii) long, lit with the arrows'
// specular and shininess.
struct ArrowParts {
  glm::mat4 shaft{1.0f}, head{1.0f};
};
[[nodiscard]] ArrowParts arrowParts(const glm::vec3& origin, const glm::vec3& tip, float shaftRadius);
inline constexpr float kArrowSpecular = 0.35f, kArrowShininess = 64.0f;

}  // namespace rollspin::render
