// `rollspin export SCENE [-o NAME.glb | NAME.gltf]`: the glTF job
// (jobs/export_job.hpp) behind its flags.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "jobs/export_job.hpp"
#include "model/rolling_model.hpp"

namespace rollspin::cli {

namespace {

struct ExportOptions {
  std::string scenePath;
  std::vector<std::string> overrides;
  std::string output;
  bool noMetadata = false;
};

int runExport(const ExportOptions& o) {
  if (!o.output.empty()) jobs::checkExportOutput(o.output);  // before the solve, not after
  const scene::SceneSpec spec = model::loadScene(o.scenePath, o.overrides);
  const std::filesystem::path out = jobs::exportGltf({&spec, o.scenePath, o.output, !o.noMetadata});
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

}  // namespace rollspin::cli
