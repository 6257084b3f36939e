// Scene files: TOML → validated SceneSpec. Overrides "key.sub=value" (from
// --set) are merged into the document before validation and validated the
// same way; an error names where the offending value came from
// (file:line:col, or the --set argument), the key and what was expected, and
// is thrown as rollspin::Error (BadInput → exit code 2).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "scene/scene_spec.hpp"

namespace rollspin::scene {

// `file` may also name a bundled scene (scene_catalog.hpp: "lollipop").
[[nodiscard]] SceneSpec loadSceneFile(const std::filesystem::path& file, std::span<const std::string> overrides = {});

// Same, from text; sourceName is used in messages (e.g. "<inline>").
[[nodiscard]] SceneSpec loadSceneText(std::string_view text, const std::string& sourceName,
                                      std::span<const std::string> overrides = {});

}  // namespace rollspin::scene
