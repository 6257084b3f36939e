// Files for the tests, with no rollspin code behind them: the source tree
// (shipped scenes, the renderer's test scenes), a fresh temporary directory
// under the build tree, and a file's bytes.
#pragma once

#include <filesystem>
#include <string>

namespace rollspin::test {

// A fresh empty directory under the build tree for one test.
std::filesystem::path freshTempDir(const std::string& name);

// This build's paths (generated into build_paths.cpp by tests/CMakeLists.txt):
// the source tree, the build tree, the tests' temporary root, and cmake.
std::filesystem::path sourceDir();
std::filesystem::path buildDir();
std::filesystem::path testTmpRoot();
std::string cmakeCommand();
// A scene shipped in scenes/ by name ("lollipop"), as a path string for a command line.
std::string shippedScenePath(const std::string& name);
// A scene of the renderer's tests (tests/render/scenes) by name ("twin_only").
std::string renderTestScenePath(const std::string& name);
// A file's bytes ("" when it cannot be read).
std::string readFile(const std::filesystem::path& p);

}  // namespace rollspin::test
