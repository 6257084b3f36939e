#include "scene/scene_catalog.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "core/text.hpp"

namespace rollspin::scene {

namespace build_tree {
// This build tree's rollspin folder and the source's scenes/ (generated into
// build_tree.cpp by src/scene/CMakeLists.txt).
extern const char* const kBinaryDir;
extern const char* const kSourceScenes;
}  // namespace build_tree

namespace {

namespace fs = std::filesystem;

fs::path executablePath() {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path{} : self;
}

bool isFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

bool isFolder(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

// Every folder that may hold bundled scenes, in search order, whether or not it exists.
std::vector<fs::path> candidateFolders() {
  std::vector<fs::path> out;
  if (const char* env = std::getenv("ROLLSPIN_SCENE_PATH"); env != nullptr) {
    std::stringstream list(env);
    for (std::string item; std::getline(list, item, ':');)
      if (!item.empty()) out.emplace_back(item);
  }
  const fs::path exe = executablePath();
  if (!exe.empty()) {
    out.push_back((exe.parent_path() / ".." / "share" / "rollspin" / "scenes").lexically_normal());
    // The build tree's binary (build/rollspin) reads the source's scenes/.
    std::error_code ec;
    if (fs::equivalent(exe.parent_path(), build_tree::kBinaryDir, ec)) out.emplace_back(build_tree::kSourceScenes);
  }
  return out;
}

}  // namespace

std::vector<fs::path> sceneFolders() {
  std::vector<fs::path> out;
  for (const fs::path& folder : candidateFolders())
    if (isFolder(folder) && std::find(out.begin(), out.end(), folder) == out.end()) out.push_back(folder);
  return out;
}

fs::path resolveScene(const std::string& given) {
  std::error_code ec;
  if (fs::exists(given, ec)) return given;  // a file, or a folder the reader refuses
  // A bare name (no folder in it) may be a bundled scene, with or without .toml.
  const fs::path asGiven(given);
  if (!given.empty() && !asGiven.has_parent_path()) {
    for (const fs::path& folder : sceneFolders()) {
      for (const fs::path& candidate : {folder / given, folder / (given + ".toml")})
        if (isFile(candidate)) return candidate;
    }
  }
  std::string looked = "the working directory (" + fs::current_path().string() + ")";
  if (!asGiven.has_parent_path())
    for (const fs::path& folder : candidateFolders()) looked += ", " + folder.string();
  std::vector<std::string> names;
  for (const BundledScene& s : bundledScenes()) names.push_back(s.name);
  std::string known;
  for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
  const std::string guess = nearestName(asGiven.stem().string(), names);
  throw badInput(SourceLoc{given}, "cannot read the scene file: there is none; looked in {}{}{}", looked,
                 guess.empty() ? std::string() : fmt::format("; did you mean '{}'?", guess),
                 known.empty() ? std::string() : "; the bundled scenes (`rollspin scenes`): " + known);
}

std::vector<BundledScene> bundledScenes() {
  std::map<std::string, BundledScene> byName;
  for (const fs::path& folder : sceneFolders()) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
      if (entry.path().extension() != ".toml" || !isFile(entry.path())) continue;
      const std::string name = entry.path().stem().string();
      if (byName.contains(name)) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream text;
      text << in.rdbuf();
      byName.emplace(name, BundledScene{name, entry.path(), sceneDescription(text.str())});
    }
  }
  std::vector<BundledScene> out;
  for (auto& [name, scene] : byName) out.push_back(std::move(scene));
  return out;
}

std::string sceneDescription(const std::string& text) {
  // The leading comment block, its lines joined.
  std::string joined;
  std::stringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] != '#') break;
    std::string body = line.substr(1);
    body.erase(0, body.find_first_not_of(" \t"));
    while (!body.empty() && std::isspace(static_cast<unsigned char>(body.back()))) body.pop_back();
    if (body.empty()) break;
    joined += (joined.empty() ? "" : " ") + body;
  }
  // Its first sentence: a '.' before a space or the end, unless it closes an
  // abbreviation ("sec. IV", "e.g. a").
  static const std::vector<std::string> abbreviations{"sec", "e.g", "i.e", "cf", "eq", "fig", "vs", "etc", "Eq", "Fig"};
  for (std::size_t i = joined.find('.'); i != std::string::npos; i = joined.find('.', i + 1)) {
    if (i + 1 < joined.size() && joined[i + 1] != ' ') continue;
    const std::size_t wordStart = joined.find_last_of(" (", i);
    const std::string word = joined.substr(wordStart == std::string::npos ? 0 : wordStart + 1,
                                           i - (wordStart == std::string::npos ? 0 : wordStart + 1));
    if (std::find(abbreviations.begin(), abbreviations.end(), word) != abbreviations.end()) continue;
    return joined.substr(0, i + 1);
  }
  return joined;
}

}  // namespace rollspin::scene
