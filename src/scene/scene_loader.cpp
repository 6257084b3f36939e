#include "scene/scene_loader.hpp"

#include "scene/scene_catalog.hpp"
#include "scene/schema_reader.hpp"
#include "scene/scene_sources.hpp"

namespace rollspin::scene {

SceneSpec loadSceneText(std::string_view text, const std::string& sourceName, std::span<const std::string> overrides) {
  std::error_code ec;
  std::vector<std::filesystem::path> chain{std::filesystem::weakly_canonical(sourceName, ec)};
  std::map<std::string, SourceLoc> locations;  // file:line:col per key; --set arguments win
  toml::table root = resolveExtends(parseText(text, sourceName), sourceName, chain, locations);
  for (const auto& arg : overrides) applyOverride(root, arg, locations);
  SceneSpec spec = schema::Reader(root, sourceName, std::move(locations)).read();
  return spec;
}

SceneSpec loadSceneFile(const std::filesystem::path& given, std::span<const std::string> overrides) {
  // A bare name ("lollipop") is a bundled scene when no such file is here.
  const std::filesystem::path file = resolveScene(given.string());
  SceneSpec spec = loadSceneText(readSceneFile(file, {}, ""), file.string(), overrides);
  spec.name = file.stem().string();
  return spec;
}


}  // namespace rollspin::scene
