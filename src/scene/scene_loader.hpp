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
#include <variant>

#include "scene/scene_spec.hpp"

namespace rollspin::scene {

// A key a command-line flag sets (--width 641 → render.width): laid over
// the document after the --set overrides and validated the same way, with
// the flag as where the value came from in messages and locations.
struct KeySetting {
  std::string section;   // "render"
  std::string_view key;  // a key constant of the section's table (scene_tables.hpp: key::kWidth)
  std::variant<long long, double, bool, std::string> value;
  SourceLoc from;  // the flag as typed: "--width 641"
  [[nodiscard]] std::string dottedKey() const { return section + "." + std::string(key); }
  [[nodiscard]] std::string valueText() const;  // as --set would write it: "641", "true"
};

// `file` may also name a bundled scene (scene_catalog.hpp: "lollipop").
[[nodiscard]] SceneSpec loadSceneFile(const std::filesystem::path& file, std::span<const std::string> overrides = {},
                                      std::span<const KeySetting> settings = {});

// Same, from text; sourceName is used in messages (e.g. "<inline>").
[[nodiscard]] SceneSpec loadSceneText(std::string_view text, const std::string& sourceName,
                                      std::span<const std::string> overrides = {},
                                      std::span<const KeySetting> settings = {});

}  // namespace rollspin::scene
