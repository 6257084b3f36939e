// `rollspin report errors [SCENE.toml ...] | stress | paper [-o DIR]`: the
// report library (src/report) does the work; this file turns scene files
// into contact paths, prints progress on stderr and the headline on stdout.
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "core/temp_files.hpp"
#include "model/rolling_model.hpp"
#include "report/report.hpp"
#include "scene/scene_loader.hpp"

namespace rollspin::cli {

using namespace rollspin::model;

namespace {

struct ReportArgs {
  std::vector<std::string> scenes;
  std::vector<std::string> overrides;
  std::string outDir = "output/report";
};

// The output folder: made before the work (a folder that cannot be made
// fails first, not after it), and removed again, with any parents this run
// made, when the report fails or is interrupted before it writes a file.
std::unique_ptr<CreatedFolders> makeOutputFolder(const ReportArgs& a) {
  checkOutputFolder(a.outDir, SourceLoc{"--output-dir " + a.outDir});
  std::error_code ec;
  auto folders = std::make_unique<CreatedFolders>(a.outDir, ec);
  if (ec) throw runtimeError(SourceLoc{"--output-dir " + a.outDir}, "cannot create {}: {}", a.outDir, ec.message());
  return folders;
}

report::ReportOptions optionsFrom(const ReportArgs& a) {
  report::ReportOptions o;
  o.outDir = a.outDir;
  o.progress = [](const std::string& line) { std::fprintf(stderr, "rollspin: %s\n", line.c_str()); };
  return o;
}

// Runs one report into its folder, then prints what it wrote and its headline.
template <typename Report>
int writeReport(const ReportArgs& a, const Report& run) {
  const std::unique_ptr<CreatedFolders> folders = makeOutputFolder(a);
  const report::ReportOutcome out = run(optionsFrom(a));
  folders->keep();
  for (const auto& p : out.written) std::fprintf(stderr, "rollspin: wrote %s\n", p.string().c_str());
  std::printf("%s\n", out.headline.c_str());
  if (!out.plotError.empty())
    throw runtimeError(SourceLoc{}, "report written, but the plot is missing: {}", out.plotError);
  return 0;
}

int runErrors(const ReportArgs& a) {
  std::vector<report::ReportScene> scenes;
  if (a.scenes.empty()) {
    scenes = report::defaultErrorScenes();
  } else {
    for (const std::string& file : a.scenes) {
      const scene::SceneSpec spec = scene::loadSceneFile(file, a.overrides);
      RollingModel model = buildModel(spec);
      scenes.push_back({spec.name, model.path->describe(),
                        std::shared_ptr<const geometry::ContactPath>(std::move(model.path)), model.ballRadius});
    }
  }
  return writeReport(a, [&](report::ReportOptions options) {
    options.lollipopSpeedRatio = a.scenes.empty();
    return report::errorsReport(scenes, options);
  });
}

}  // namespace

void registerReportCommands(CLI::App& cli, CommandHandler& handler) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* report = cli.add_subcommand("report", "Accuracy and cost reports (output/report/)");
  report->require_subcommand(1);
  auto addOut = [&](CLI::App* c) {
    c->add_option("-o,--output-dir", args->outDir, "Output folder (default output/report)");
  };

  CLI::App* errors = report->add_subcommand("errors", "Error against run time for every method (CSV, PNG, Markdown)");
  errors->add_option("scenes", args->scenes,
                     "Scene files or bundled scenes' names (default: a built-in set: plane, sphere outside/inside, "
                     "torus knot, clothoid, stiff lollipop)");
  errors->add_option("--set", args->overrides, "Override a key in every given scene: --set key.sub=value");
  addOut(errors);
  errors->callback([args, &handler] { handler = [args] { return runErrors(*args); }; });

  CLI::App* stress = report->add_subcommand("stress", "Stiff and extreme cases x methods, pass/fail against bounds");
  addOut(stress);
  stress->callback([args, &handler] { handler = [args] { return writeReport(*args, report::stressReport); }; });

  CLI::App* paper = report->add_subcommand("paper", "The paper's closed-form claims against the solver");
  addOut(paper);
  paper->callback([args, &handler] { handler = [args] { return writeReport(*args, report::paperReport); }; });
}

}  // namespace rollspin::cli
