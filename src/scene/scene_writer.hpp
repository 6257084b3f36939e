// The fully resolved scene as TOML: every key that applies to the scene's
// kinds, with its value or default (extends and --set already applied).
// Loading the text gives back the same scene. `notes` adds a comment after a
// key (e.g. "solver.steps" → "automatic: 10054 steps"); keys whose default is
// computed (steps, samples) are written as such comments when not set.
#pragma once

#include <map>
#include <string>

#include "scene/scene_spec.hpp"

namespace rollspin::scene {

[[nodiscard]] std::string writeScene(const SceneSpec& spec, const std::map<std::string, std::string>& notes = {});

}  // namespace rollspin::scene
