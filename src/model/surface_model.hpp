// Curved-surface scenes (issue 3): builds the Surface and the contact path for
// every [surface] × [path] combination that is not one of the foundation's
// closed-form paths (line / circle on a plane, parallel on a sphere), then
// checks along the whole path that the ball touches at one point. Geometry
// errors (expressions that do not parse, curves leaving the domain, corners,
// a ball that does not fit) become BadInput at the scene key responsible.
#pragma once

#include "model/rolling_model.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::model {

// True when the foundation's analytic paths handle this scene.
[[nodiscard]] bool isAnalyticScene(const scene::SceneSpec& spec);

// Surface, path and validity check for the other scenes.
[[nodiscard]] RollingModel buildSurfaceModel(const scene::SceneSpec& spec);

}  // namespace rollspin::model
