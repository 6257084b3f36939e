// `rollspin export SCENE [-o NAME.glb | NAME.gltf]`: the scene as glTF 2.0
// (export/gltf_export.hpp): meshes, the animation "roll" in the clip's
// seconds, and the resolved scene in the ball's extras. Solves, draws no
// pixel: no GL context, no encoder.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/render_jobs.hpp"
#include "app/scene_print.hpp"
#include "core/stage_log.hpp"
#include "export/gltf_export.hpp"
#include "model/rolling_model.hpp"

namespace rollspin::app {

namespace {

struct ExportOptions {
  std::string scenePath;
  std::vector<std::string> overrides;
  std::string output;
  bool noMetadata = false;
};

int runExport(const ExportOptions& o) {
  if (!o.output.empty()) gltf::checkGltfOutput(o.output);  // before the solve, not after
  const scene::SceneSpec spec = model::loadScene(o.scenePath, o.overrides);
  const model::RollingModel model = model::buildSceneModel(spec);
  std::filesystem::path out = o.output;
  if (out.empty()) {
    std::filesystem::create_directories("output");
    out = std::filesystem::path("output") / (spec.name + ".glb");
  }
  gltf::ExportRequest request;
  request.spec = &spec;
  request.model = &model;
  request.ballTexture = loadBallTexture(spec);
  request.version = ROLLSPIN_VERSION;
  request.metadata = !o.noMetadata;
  if (request.metadata) request.sceneText = resolvedSceneText(o.scenePath, spec);
  gltf::writeGltf(request, out);
  std::fprintf(stderr, "rollspin: wrote %s\n", out.string().c_str());
  return 0;
}

}  // namespace

void registerExportCommand(CLI::App& cli, CommandHandler& handler) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* command = cli.add_subcommand("export", "Write the scene as glTF 2.0 (.glb, or .gltf with its .bin)");
  command->add_option("scene", options->scenePath, "Scene file (TOML), or a bundled scene's name (rollspin scenes)")
      ->required();
  command->add_option("--set", options->overrides, "Override a scene key: --set key.sub=value (repeatable)");
  command->add_option("-o,--output", options->output, "Output .glb or .gltf (default: output/<scene>.glb)");
  command->add_flag("--no-metadata", options->noMetadata, "Leave the resolved scene text out of the file");
  command->callback([options, &handler] { handler = [options] { return runExport(*options); }; });
}

}  // namespace rollspin::app
