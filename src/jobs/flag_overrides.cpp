#include "jobs/flag_overrides.hpp"

#include <cstdio>

#include "model/rolling_model.hpp"
#include "core/error.hpp"
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

scene::SceneSpec loadSceneWithFlags(const std::string& file, std::vector<std::string> overrides,
                                    const std::vector<FlagOverride>& flags,
                                    const std::optional<std::string>& sceneText) {
  const std::vector<std::string> explicitOnes = overrides;
  std::vector<const FlagOverride*> applied;
  for (const FlagOverride& f : flags) {
    // An explicit --set is what the user asked for; a preset is only a default.
    const std::string mine = f.flag.rfind("--quality", 0) == 0 ? explicitSetting(explicitOnes, keyOf(f.setting)) : "";
    if (!mine.empty()) {
      std::fprintf(stderr, "rollspin: note: %s would set %s; keeping --set %s\n", f.flag.c_str(), f.setting.c_str(),
                   mine.c_str());
      continue;
    }
    overrides.push_back(f.setting);
    applied.push_back(&f);
  }
  // Which flag gave a setting: the last one applied wins, like the loader.
  auto flagFor = [&](const std::string& setLabel) -> const FlagOverride* {
    const FlagOverride* found = nullptr;
    for (const FlagOverride* f : applied)
      if ("--set " + f->setting == setLabel) found = f;
    return found;
  };
  scene::SceneSpec spec;
  try {
    spec = sceneText ? scene::loadSceneText(*sceneText, file, overrides) : model::loadScene(file, overrides);
  } catch (const Error& e) {
    if (const FlagOverride* f = flagFor(e.where().file)) throw Error(e.kind(), SourceLoc{f->flag}, e.message());
    throw;
  }
  for (auto& [key, where] : spec.locations)
    if (const FlagOverride* f = flagFor(where.file)) where = SourceLoc{f->flag};
  return spec;
}

}  // namespace rollspin::jobs
