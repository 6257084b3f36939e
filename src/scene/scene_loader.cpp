#include "scene/scene_loader.hpp"

#include <fmt/format.h>

#include <type_traits>

#include "scene/scene_catalog.hpp"
#include "scene/scene_sources.hpp"
#include "scene/schema_reader.hpp"

namespace rollspin::scene {

std::string KeySetting::valueText() const {
  return std::visit(
      [](const auto& v) -> std::string {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, bool>) return v ? "true" : "false";
        else if constexpr (std::is_same_v<V, std::string>) return v;
        else return fmt::format("{}", v);
      },
      value);
}

SceneSpec loadSceneText(std::string_view text, const std::string& sourceName, std::span<const std::string> overrides,
                        std::span<const KeySetting> settings) {
  std::error_code ec;
  std::vector<std::filesystem::path> chain{std::filesystem::weakly_canonical(sourceName, ec)};
  std::map<std::string, SourceLoc> locations;  // file:line:col per key; --set arguments win, then flags
  toml::table root = resolveExtends(parseText(text, sourceName), sourceName, chain, locations);
  for (const auto& arg : overrides) applyOverride(root, arg, locations);
  for (const KeySetting& setting : settings) applySetting(root, setting, locations);
  SceneSpec spec = schema::Reader(root, sourceName, std::move(locations)).read();
  return spec;
}

namespace {

// Only blank lines and comments: TOML's lines that hold no key or table.
bool holdsNoKeys(std::string_view text) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first != std::string_view::npos && line[first] != '#') return false;
    start = end + 1;
  }
  return true;
}

}  // namespace

SceneSpec loadSceneFile(const std::filesystem::path& given, std::span<const std::string> overrides,
                        std::span<const KeySetting> settings) {
  // A bare name ("lollipop") is a bundled scene when no such file is here.
  const std::filesystem::path file = resolveScene(given.string());
  const std::string text = readSceneFile(file, {}, "");
  // An empty file is a mistake (a truncated copy, the wrong file), not a
  // request for the default circle; --set keys alone still make a scene.
  if (overrides.empty() && settings.empty() && holdsNoKeys(text))
    throw badInput(SourceLoc{file.string()},
                   "empty scene: the file has no keys (only blank lines or comments); print a full one with "
                   "`rollspin scene lollipop --print > {}` and edit it, or start it with `extends = \"lollipop\"`",
                   file.filename().string());
  SceneSpec spec = loadSceneText(text, file.string(), overrides, settings);
  spec.name = file.stem().string();
  return spec;
}


}  // namespace rollspin::scene
