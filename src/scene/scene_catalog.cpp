#include "scene/scene_catalog.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
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

// The folders a host set with setProgramSceneFolders (none: the executable's).
struct ProgramFolders {
  std::mutex mutex;
  std::vector<fs::path> folders;
};
ProgramFolders& programFolders() {
  static ProgramFolders* set = new ProgramFolders;  // never destroyed: read by loaders until exit
  return *set;
}

// The executable's own: <prefix>/share/rollspin/scenes, and for the build
// tree's binary (build/rollspin) the source's scenes/.
std::vector<fs::path> executableFolders() {
  const fs::path exe = executablePath();
  if (exe.empty()) return {};
  std::vector<fs::path> out{(exe.parent_path() / ".." / "share" / "rollspin" / "scenes").lexically_normal()};
  std::error_code ec;
  if (fs::equivalent(exe.parent_path(), build_tree::kBinaryDir, ec)) out.emplace_back(build_tree::kSourceScenes);
  return out;
}

// Every folder that may hold bundled scenes, in search order, whether or not it exists.
std::vector<fs::path> candidateFolders() {
  std::vector<fs::path> out;
  if (const char* env = std::getenv("ROLLSPIN_SCENE_PATH"); env != nullptr) {
    std::stringstream list(env);
    for (std::string item; std::getline(list, item, ':');)
      if (!item.empty()) out.emplace_back(item);
  }
  ProgramFolders& set = programFolders();
  const std::lock_guard lock(set.mutex);
  const std::vector<fs::path> program = set.folders.empty() ? executableFolders() : set.folders;
  out.insert(out.end(), program.begin(), program.end());
  return out;
}

}  // namespace

void setProgramSceneFolders(std::vector<fs::path> folders) {
  ProgramFolders& set = programFolders();
  const std::lock_guard lock(set.mutex);
  set.folders = std::move(folders);
}

std::vector<fs::path> sceneFolders() {
  std::vector<fs::path> out;
  for (const fs::path& folder : candidateFolders())
    if (isFolder(folder) && std::find(out.begin(), out.end(), folder) == out.end()) out.push_back(folder);
  return out;
}

std::optional<fs::path> findBundledScene(const std::string& name) {
  if (name.empty() || fs::path(name).has_parent_path()) return std::nullopt;
  for (const fs::path& folder : sceneFolders())
    for (const fs::path& candidate : {folder / name, folder / (name + ".toml")})
      if (isFile(candidate)) return candidate;
  return std::nullopt;
}

std::string sceneSearchText() {
  // A folder both in $ROLLSPIN_SCENE_PATH and among the program's is
  // searched once, and said once.
  std::vector<fs::path> said;
  std::string out;
  for (const fs::path& folder : candidateFolders()) {
    if (std::find(said.begin(), said.end(), folder) != said.end()) continue;
    said.push_back(folder);
    out += (out.empty() ? "" : ", ") + folder.string();
  }
  return out;
}

Error noSuchScene(const SourceLoc& where, const std::string& what, const std::string& given,
                  const std::string& firstPlace) {
  const fs::path asGiven(given);
  std::string looked = firstPlace;
  if (!asGiven.has_parent_path())
    if (const std::string folders = sceneSearchText(); !folders.empty()) looked += ", " + folders;
  std::vector<std::string> names;
  for (const BundledScene& s : bundledScenes()) names.push_back(s.name);
  std::string known;
  for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
  const std::string guess = nearestName(asGiven.stem().string(), names);
  return badInput(where, "{}: there is none; looked in {}{}{}", what, looked,
                  guess.empty() ? std::string() : fmt::format("; did you mean '{}'?", guess),
                  known.empty() ? std::string() : "; the bundled scenes (`rollspin scenes`): " + known);
}

fs::path resolveScene(const std::string& given) {
  std::error_code ec;
  if (fs::exists(given, ec)) return given;  // a file, or a folder the reader refuses
  // A bare name (no folder in it) may be a bundled scene, with or without .toml.
  if (const auto bundled = findBundledScene(given)) return *bundled;
  throw noSuchScene(SourceLoc{given}, "cannot read the scene file", given,
                    "the working directory (" + fs::current_path().string() + ")");
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
  // abbreviation ("sec. IV", "e.g. a"), in any case ("Cf. Berry").
  static const std::vector<std::string> abbreviations{"sec", "e.g", "i.e", "cf", "eq", "fig", "vs", "etc"};
  for (std::size_t i = joined.find('.'); i != std::string::npos; i = joined.find('.', i + 1)) {
    if (i + 1 < joined.size() && joined[i + 1] != ' ') continue;
    const std::size_t wordStart = joined.find_last_of(" (", i);
    std::string word = joined.substr(wordStart == std::string::npos ? 0 : wordStart + 1,
                                     i - (wordStart == std::string::npos ? 0 : wordStart + 1));
    for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (std::find(abbreviations.begin(), abbreviations.end(), word) != abbreviations.end()) continue;
    return joined.substr(0, i + 1);
  }
  return joined;
}

}  // namespace rollspin::scene
