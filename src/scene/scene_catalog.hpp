// Where a scene named on the command line is found: a file path as given
// (relative to the working directory), else a bundled scene by name
// ("lollipop" or "lollipop.toml") in, in turn, each folder of
// $ROLLSPIN_SCENE_PATH (':'-separated), the installed
// <prefix>/share/rollspin/scenes (found from the executable's own path,
// ../share/rollspin/scenes) and, for a binary in the build tree, the
// source's scenes/. A host that is not the rollspin program (the Python
// module, where the executable is python3) names its own data folders
// instead. `rollspin scenes` lists the bundled ones.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace rollspin::scene {

// The folders searched for a bare scene name, in order (existing ones only).
[[nodiscard]] std::vector<std::filesystem::path> sceneFolders();

// The program's own bundled-scene folders, searched after $ROLLSPIN_SCENE_PATH
// in place of those found from the executable's path (empty: back to those).
void setProgramSceneFolders(std::vector<std::filesystem::path> folders);

// The bundled scene named `name` ("lollipop" or "lollipop.toml", no folder
// in it), if a scene folder holds one.
[[nodiscard]] std::optional<std::filesystem::path> findBundledScene(const std::string& name);

// "FOLDER, FOLDER, …": every folder a bare name is looked for in, existing or not.
[[nodiscard]] std::string sceneSearchText();

// BadInput at `where`: "WHAT: there is none; looked in FIRST-PLACE, then the
// bundled folders (for a bare name)", the nearest bundled name and the list.
[[nodiscard]] Error noSuchScene(const SourceLoc& where, const std::string& what, const std::string& given,
                                const std::string& firstPlace);

// `given` itself when it names a file; else the bundled scene of that name.
// Throws BadInput (exit 2) saying where it looked when there is none.
[[nodiscard]] std::filesystem::path resolveScene(const std::string& given);

struct BundledScene {
  std::string name;  // the file's stem: what `rollspin render NAME` takes
  std::filesystem::path file;
  std::string description;  // the first sentence of the file's leading comment
};
// Every scene of sceneFolders(), sorted by name; a name in an earlier folder hides a later one's.
[[nodiscard]] std::vector<BundledScene> bundledScenes();

// The first sentence of a scene file's leading '#' comment block ("" if none).
[[nodiscard]] std::string sceneDescription(const std::string& text);

}  // namespace rollspin::scene
