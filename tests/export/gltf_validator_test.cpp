// The Khronos glTF validator (npm gltf-validator, run by node through
// tests/export/validate_gltf.mjs) finds 0 errors and 0 warnings in the
// export of every bundled scene (scenes/*.toml), all exported in this one
// process, and in a .gltf with its .bin. Skips, saying why, where node or
// web/node_modules is missing (scripts/install-deps.sh installs both).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "export/gltf_export.hpp"
#include "support/test_files.hpp"

namespace rollspin::gltf {
namespace {

// Runs `command`, returning its exit status and (in `output`) what it printed.
int run(const std::string& command, std::string& output) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return -1;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(GltfValidator, EveryBundledSceneHasNoErrorOrWarning) {
  const std::filesystem::path validator = test::sourceDir() / "web/node_modules/gltf-validator";
  std::string version;
  if (run("node --version", version) != 0) GTEST_SKIP() << "node is not installed (scripts/install-deps.sh)";
  if (!std::filesystem::exists(validator))
    GTEST_SKIP() << validator << " is missing (scripts/install-deps.sh runs npm ci in web/)";
  const std::filesystem::path dir = test::freshTempDir("gltf_validator");
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(test::sourceDir() / "scenes"))
    if (entry.path().extension() == ".toml") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  ASSERT_GE(scenes.size(), 10u);
  std::string files;
  for (const std::filesystem::path& file : scenes) {
    const scene::SceneSpec spec = model::loadScene(file.string(), {});
    const model::RollingModel model = model::buildSceneModel(spec);
    const ExportRequest request{&spec, &model, nullptr, "test", test::readFile(file), true};
    const std::filesystem::path out = dir / (spec.name + (file == scenes.front() ? ".gltf" : ".glb"));
    writeGltf(request, out);
    files += " '" + out.string() + "'";
  }
  std::string report;
  const int status =
      run("node '" + (test::sourceDir() / "tests/export/validate_gltf.mjs").string() + "'" + files, report);
  EXPECT_EQ(status, 0) << report;
  std::printf("%s", report.c_str());
}

}  // namespace
}  // namespace rollspin::gltf
