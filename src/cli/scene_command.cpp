// `rollspin scene SCENE --print` and `rollspin scene --from FILE`: the scene
// as the engine will run it, or as an output remembers it
// (remembered_output.hpp). Apart from solve_commands.cpp because reading an
// output needs the image and video libraries.
#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "jobs/remembered_output.hpp"
#include "jobs/scene_print.hpp"
#include "model/rolling_model.hpp"
#include "scene/scene_loader.hpp"

namespace rollspin::cli {

namespace {

struct SceneOptions {
  std::string scenePath, from;
  std::vector<std::string> overrides;
  bool print = false;
};

int runScene(const SceneOptions& o) {
  if (o.from.empty()) {
    if (o.scenePath.empty()) throw badInput({"scene"}, "give a scene file (or a bundled scene's name), or --from FILE");
    if (!o.print) throw badInput({"scene"}, "--print is required (or --from FILE)");
    fmt::print("{}", jobs::resolvedSceneText(o.scenePath, model::loadScene(o.scenePath, o.overrides)));
    return 0;
  }
  if (!o.scenePath.empty()) throw badInput({"--from " + o.from}, "give a scene or --from FILE, not both");
  const jobs::RememberedOutput remembered = jobs::readRememberedOutput(o.from);
  // Loaded either way: a scene that does not load is refused, naming the output.
  scene::SceneSpec spec = scene::loadSceneText(remembered.metadata.scene, remembered.sourceName, o.overrides);
  spec.name = remembered.sceneName;
  // As stored (what `render --from` loads), or resolved with --print/--set.
  if (o.print || !o.overrides.empty()) fmt::print("{}", jobs::resolvedSceneText(o.from, spec));
  else fmt::print("{}", remembered.metadata.scene);
  return 0;
}

}  // namespace

void registerSceneCommand(CLI::App& cli, CommandHandler& handler) {
  auto options = std::make_shared<SceneOptions>();
  CLI::App* sceneCmd = cli.add_subcommand("scene",
                                          "Show a scene as the engine will run it, or the scene an output "
                                          "remembers (--from)");
  sceneCmd->add_option("scene", options->scenePath, "Scene file (TOML), or a bundled scene's name (rollspin scenes)");
  sceneCmd->add_option("--set", options->overrides, "Override a scene key: --set key.sub=value (repeatable)");
  sceneCmd->add_flag("--print", options->print, "Print the fully resolved scene as TOML");
  sceneCmd->add_option("--from", options->from,
                       "Print the scene an output remembers (PNG, JPEG, PDF, SVG, MP4, WebM, MOV, GIF, a timeline's "
                       "NAME.csv or its .csv.json, glTF, the viewer's HTML)");
  sceneCmd->callback([options, &handler] { handler = [options] { return runScene(*options); }; });
}

}  // namespace rollspin::cli
