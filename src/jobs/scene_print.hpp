// `rollspin scene --print` and Python's Scene.toml(): the resolved scene as
// TOML (every default filled in, extends and --set applied), with what the
// engine derives (automatic steps, sample counts, a storyboard's timing)
// noted beside the keys.
#pragma once

#include <string>

#include "scene/scene_spec.hpp"

namespace rollspin::jobs {

// sourceName: what the header line calls the scene (its path as given).
[[nodiscard]] std::string resolvedSceneText(const std::string& sourceName, const scene::SceneSpec& spec);

}  // namespace rollspin::jobs
