// Command-line flags that stand for scene keys (--width → render.width,
// --quality → size and frame rate): they are applied as overrides after
// --set and validated by the scene loader like the file, but an error — or a
// later check such as the frame-memory estimate — names the flag the user
// typed (`--width 641`), not a `--set` they never wrote.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene_loader.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::jobs {

struct FlagOverride {
  std::string flag;           // as typed: "--width 641", "--quality medium"
  scene::KeySetting setting;  // the key (a row's constant) and its value
  bool preset = false;        // a preset's key (--quality): only a default
};
// A flag's override of `section`.`key`.
[[nodiscard]] FlagOverride flagOverride(const std::string& flag, const std::string& section, std::string_view key,
                                        std::variant<long long, double, bool, std::string> value, bool preset = false);

// loadScene(file, overrides) with each flag's key laid over them, the flag
// the source of the key. A preset's key does not override a key the user
// set with --set; it says so in one line on stderr instead.
// sceneText: the scene itself (the Python binding's loads()); `file` then
// only names it in messages.
[[nodiscard]] scene::SceneSpec loadSceneWithFlags(const std::string& file, std::vector<std::string> overrides,
                                                  const std::vector<FlagOverride>& flags,
                                                  const std::optional<std::string>& sceneText = std::nullopt);

}  // namespace rollspin::jobs
