#include "jobs/flag_overrides.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "model/rolling_model.hpp"
#include "scene/scene_loader.hpp"

namespace rollspin::jobs {

namespace {

std::string keyOf(const std::string& setting) { return setting.substr(0, setting.find('=')); }

// The last explicit --set of `key`, or "".
std::string explicitSetting(const std::vector<std::string>& overrides, const std::string& key) {
  std::string found;
  for (const std::string& o : overrides)
    if (keyOf(o) == key) found = o;
  return found;
}

}  // namespace

FlagOverride flagOverride(const std::string& flag, const std::string& section, std::string_view key,
                          std::variant<long long, double, bool, std::string> value, bool preset) {
  return {flag, scene::KeySetting{section, key, std::move(value), SourceLoc{flag}}, preset};
}

scene::SceneSpec loadSceneWithFlags(const std::string& file, std::vector<std::string> overrides,
                                    const std::vector<FlagOverride>& flags,
                                    const std::optional<std::string>& sceneText) {
  std::vector<scene::KeySetting> settings;
  for (const FlagOverride& f : flags) {
    // An explicit --set is what the user asked for; a preset is only a default.
    const std::string mine = f.preset ? explicitSetting(overrides, f.setting.dottedKey()) : "";
    if (!mine.empty()) {
      std::fprintf(stderr, "rollspin: note: %s would set %s=%s; keeping --set %s\n", f.flag.c_str(),
                   f.setting.dottedKey().c_str(), f.setting.valueText().c_str(), mine.c_str());
      continue;
    }
    settings.push_back(f.setting);
  }
  // Each key a flag sets remembers the flag (SourceLoc), so its messages name it.
  return sceneText ? scene::loadSceneText(*sceneText, file, overrides, settings)
                   : model::loadScene(file, overrides, settings);
}

}  // namespace rollspin::jobs
