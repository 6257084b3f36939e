// `extends`: a scene laid over its base scene, recursively, each key keeping
// the file:line:col of the file that set it.
#include <fstream>
#include <sstream>

#include "scene/scene_catalog.hpp"
#include "scene/scene_sources.hpp"

namespace rollspin::scene {

toml::table parseText(std::string_view text, const std::string& sourceName) {
  try {
    return toml::parse(text, sourceName);
  } catch (const toml::parse_error& e) {
    throw badInput(
        SourceLoc{sourceName, static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column)},
        "TOML syntax error: {}", e.description());
  }
}

std::string readSceneFile(const std::filesystem::path& file, const SourceLoc& askedBy, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec)) {
    if (askedBy.empty()) throw badInput(SourceLoc{file.string()}, "cannot read the scene file");
    throw badInput(askedBy, "{}: cannot read the scene file '{}'", what, file.string());
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

namespace {

// Tables merge key by key, anything else in `derived` replaces `base`'s.
void mergeInto(toml::table& base, const toml::table& derived) {
  for (auto&& [key, node] : derived) {
    toml::node* existing = base.get(key.str());
    if (existing != nullptr && existing->is_table() && node.is_table()) {
      mergeInto(*existing->as_table(), *node.as_table());
    } else {
      base.insert_or_assign(key, node);
    }
  }
}

// Records where every key of a parsed file is (toml++ does not carry source
// positions through node copies, and merging copies).
void collectLocations(const toml::table& t, const std::string& prefix, const std::string& file,
                      std::map<std::string, SourceLoc>& out) {
  for (auto&& [key, node] : t) {
    const std::string path = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    const auto& src = node.source();
    out[path] = src.begin.line == 0
                    ? SourceLoc{file}
                    : SourceLoc{file, static_cast<int>(src.begin.line), static_cast<int>(src.begin.column)};
    if (const toml::table* sub = node.as_table()) collectLocations(*sub, path, file, out);
    // [[segment]] entries: segment[1], segment[2], … (counted from 1).
    if (const toml::array* entries = node.as_array()) {
      for (std::size_t i = 0; i < entries->size(); ++i) {
        const toml::node& entry = *entries->get(i);
        const std::string item = path + "[" + std::to_string(i + 1) + "]";
        const auto& at = entry.source();
        if (at.begin.line != 0)
          out[item] = SourceLoc{file, static_cast<int>(at.begin.line), static_cast<int>(at.begin.column)};
        if (const toml::table* sub = entry.as_table()) collectLocations(*sub, item, file, out);
      }
    }
  }
}

}  // namespace

// `extends = "other.toml"` (relative to the extending file): the other scene
// is loaded first, recursively, and this file's keys are laid over it; each
// key keeps the location of the file that set it.
toml::table resolveExtends(toml::table root, const std::filesystem::path& file,
                           std::vector<std::filesystem::path>& chain, std::map<std::string, SourceLoc>& locations) {
  const toml::node* extends = root.get("extends");
  if (extends == nullptr) {
    collectLocations(root, "", file.string(), locations);
    return root;
  }
  const auto& src = extends->source();
  const SourceLoc loc{file.string(), static_cast<int>(src.begin.line), static_cast<int>(src.begin.column)};
  if (!extends->is_string()) throw badInput(loc, "extends: expected the path of a scene file (a string)");
  const std::string& named = extends->as_string()->get();
  const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  std::filesystem::path base = (folder / named).lexically_normal();
  std::error_code ec;
  // Beside the extending file first; a bare name may be a bundled scene
  // ("storyboard"), found as `rollspin render storyboard` finds it.
  if (!std::filesystem::exists(base, ec)) {
    const auto bundled = findBundledScene(named);
    if (!bundled)
      throw noSuchScene(loc, fmt::format("extends: cannot read the scene file '{}'", named), named,
                        "the folder of " + file.filename().string() + " (" +
                            std::filesystem::weakly_canonical(folder, ec).string() + ")");
    base = *bundled;
  }
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(base, ec);
  for (const auto& seen : chain) {
    if (seen == canonical) {
      std::string cycle;
      for (const auto& c : chain) cycle += c.filename().string() + " -> ";
      throw badInput(loc, "extends: cycle: {}{}", cycle, canonical.filename().string());
    }
  }
  if (chain.size() >= 32) throw badInput(loc, "extends: more than 32 levels");
  chain.push_back(canonical);
  toml::table merged =
      resolveExtends(parseText(readSceneFile(base, loc, "extends"), base.string()), base, chain, locations);
  chain.pop_back();
  root.erase("extends");
  collectLocations(root, "", file.string(), locations);
  // A storyboard replaces the scene's motion as a whole: a child's
  // [[segment]] array replaces the parent's (arrays are not merged) and any
  // [path] it had, and a child's [path] replaces the parent's segments.
  if (root.contains("segment")) merged.erase("path");
  if (root.contains("path")) merged.erase("segment");
  mergeInto(merged, root);
  return merged;
}


}  // namespace rollspin::scene
