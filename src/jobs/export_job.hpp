// The glTF export job (`rollspin export`, Python's Scene.export): the scene
// as glTF 2.0 (export/gltf_export.hpp): meshes, the animation "roll" in the
// clip's seconds, and the resolved scene in the ball's extras. Solves, draws
// no pixel: no GL context, no encoder.
#pragma once

#include <filesystem>
#include <string>

#include "scene/scene_spec.hpp"

namespace rollspin::jobs {

struct ExportJob {
  const scene::SceneSpec* spec = nullptr;
  std::string sceneSource;       // the scene's path or name, for the remembered scene text
  std::filesystem::path output;  // "" → output/<scene>.glb
  bool metadata = true;          // false: leave the resolved scene text out
};

// Checks an output name before any work is done (extension, folder).
void checkExportOutput(const std::filesystem::path& output);
// Writes the file (to a temporary name, then renamed) and returns its path.
std::filesystem::path exportGltf(const ExportJob& job);

}  // namespace rollspin::jobs
