// [surface] → its geometry::Surface, through the kind's row of geometry's
// table (geometry/surface_kinds.hpp), whose factory reads the kind's own keys;
// nothing here names a kind. Also the scene's expressions, compiled with their
// parse errors at the scene's file:line:col.
#pragma once

#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/expression.hpp"
#include "geometry/surface.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::model {

// A scene's angle (degrees) in the geometry's radians; a scene's [x, y, z] as
// the geometry's vector.
[[nodiscard]] inline constexpr double radians(double degrees) { return degrees * (std::numbers::pi / 180.0); }
[[nodiscard]] inline geometry::Vec3 toVec(const scene::Vec3& v) { return {v[0], v[1], v[2]}; }

// [surface] → its geometry; throws BadInput (surface.z that does not parse).
[[nodiscard]] std::shared_ptr<const geometry::Surface> buildSurface(const scene::SceneSpec& spec);

// "surface.z": the key of the surface kind's formula, or "" for a kind
// without one (its geometry is defined everywhere on its domain).
[[nodiscard]] std::string surfaceFormulaKey(const scene::SceneSpec& spec);

// Parses an expression of `variables`; a parse error is BadInput at `key`,
// pointing into the TOML string itself (column of the opening quote + 1 +
// position) when the key came from a file.
[[nodiscard]] std::shared_ptr<const geometry::Expression> compileExpression(const scene::SceneSpec& spec,
                                                                            const std::string& key,
                                                                            const std::string& text,
                                                                            std::vector<std::string> variables);

}  // namespace rollspin::model
