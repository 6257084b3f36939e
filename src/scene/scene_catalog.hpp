// Where a scene named on the command line is found: a file path as given
// (relative to the working directory), else a bundled scene by name
// ("lollipop" or "lollipop.toml") in, in turn, each folder of
// $ROLLSPIN_SCENE_PATH (':'-separated), the installed
// <prefix>/share/rollspin/scenes (found from the executable's own path,
// ../share/rollspin/scenes) and, for a binary in the build tree, the
// source's scenes/. `rollspin scenes` lists the bundled ones.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rollspin::scene {

// The folders searched for a bare scene name, in order (existing ones only).
[[nodiscard]] std::vector<std::filesystem::path> sceneFolders();

// `given` itself when it names a file; else the bundled scene of that name.
// Throws BadInput (exit 2) saying where it looked when there is none.
[[nodiscard]] std::filesystem::path resolveScene(const std::string& given);

struct BundledScene {
  std::string name;                // the file's stem: what `rollspin render NAME` takes
  std::filesystem::path file;
  std::string description;         // the first sentence of the file's leading comment
};
// Every scene of sceneFolders(), sorted by name; a name in an earlier folder hides a later one's.
[[nodiscard]] std::vector<BundledScene> bundledScenes();

// The first sentence of a scene file's leading '#' comment block ("" if none).
[[nodiscard]] std::string sceneDescription(const std::string& text);

}  // namespace rollspin::scene
