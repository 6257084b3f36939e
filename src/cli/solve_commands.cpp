#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "core/output_path.hpp"
#include "core/stage_log.hpp"
#include "jobs/scene_print.hpp"
#include "jobs/timeline_csv.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_clock.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_writer.hpp"
#include "spin/su2.hpp"

namespace rollspin::cli {

using namespace rollspin::model;
using namespace rollspin::motion;

namespace {

struct SolveOptions {
  std::string scenePath;
  std::vector<std::string> overrides;
  bool json = false;
  bool print = false;
  bool commentHeader = false;  // timeline: the '#' line above the CSV's header row
  std::string output;
  std::string atS;  // timeline --at-s FILE: the arc lengths to sample, one a line
};

// JSON has no inf or NaN: an estimate that could not be made is null.
std::string jsonNumber(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : "null"; }

int runSolve(const SolveOptions& o) {
  const scene::SceneSpec spec = loadScene(o.scenePath, o.overrides);
  const RollingModel model = buildSceneModel(spec);
  SolverChoice choice = chooseSolver(spec, model);
  StageLog::instance().record("solver");
  const spin::SolveStats stats = solveScene(spec, model, choice);
  const spin::AngleAxis aa = spin::rotationAngleAxis(stats.final);
  const double psi = spin::spinorAngle(stats.final);
  const spin::Su2& q = stats.final;
  if (o.json) {
    fmt::print(
        "{{\n  \"scene\": \"{}\",\n  \"length\": {:.17g},\n  \"method\": \"{}\",\n  \"steps\": {},\n"
        "  \"quaternion\": [{:.17g}, {:.17g}, {:.17g}, {:.17g}],\n  \"angle\": {:.17g},\n"
        "  \"axis\": [{:.17g}, {:.17g}, {:.17g}],\n  \"spinor_angle\": {:.17g},\n"
        "  \"unitarity_error\": {:.6g},\n  \"solve_seconds\": {:.6g},\n"
        "  \"error_estimate\": {},\n  \"error_estimate_basis\": \"{}\",\n"
        "  \"error_estimate_seconds\": {:.6g},\n  \"error_estimate_skipped\": {}\n}}\n",
        spec.name, model.path->length(), spin::methodName(choice.method), stats.steps, q.w, q.x, q.y, q.z, aa.angle,
        aa.axis.x(), aa.axis.y(), aa.axis.z(), psi, stats.unitarityError, stats.seconds,
        jsonNumber(stats.errorEstimate), stats.errorEstimateBasis, stats.errorEstimateSeconds,
        spec.solver.errorEstimate ? "false" : "true");
    return 0;
  }
  constexpr double deg = 180.0 / std::numbers::pi;
  fmt::print("scene            {}\n", o.scenePath);
  fmt::print("path             {}\n", model.path->describe());
  fmt::print("ball radius      {:.17g}\n", model.ballRadius);
  fmt::print("length           {:.17g}\n", model.path->length());
  fmt::print("method           {} ({} steps{})\n", spin::methodName(choice.method), stats.steps,
             choice.method == spin::Method::Exact ? ", closed form"
             : spin::isAdaptive(choice.method)
                 ? fmt::format(", adaptive, tolerance {:g}, {} rejected", choice.tolerance, stats.rejectedSteps)
             : choice.automaticSteps ? ", automatic"
                                     : "");
  fmt::print("quaternion       [{:.17g}, {:.17g}, {:.17g}, {:.17g}]  (qw, qx, qy, qz)\n", q.w, q.x, q.y, q.z);
  fmt::print("rotation angle   {:.17g} rad ({:.12g} deg)\n", aa.angle, aa.angle * deg);
  fmt::print("rotation axis    [{:.17g}, {:.17g}, {:.17g}]\n", aa.axis.x(), aa.axis.y(), aa.axis.z());
  fmt::print("spinor angle     {:.17g} rad ({:.12g} deg; {} sheet)\n", psi, psi * deg,
             spin::onNegativeSheet(q) ? "negative (U ~ -1)" : "positive");
  fmt::print("unitarity error  {:.3g}\n", stats.unitarityError);
  fmt::print("solve time       {:.3g} s\n", stats.seconds);
  if (spec.solver.errorEstimate)
    fmt::print("error estimate   {:.2g} rad  ({}; took {:.3g} s)\n", stats.errorEstimate, stats.errorEstimateBasis,
               stats.errorEstimateSeconds);
  else fmt::print("error estimate   {}\n", stats.errorEstimateBasis);
  return 0;
}

// `timeline --at-s FILE`: the arc lengths in FILE (numbers separated by
// white space; '#' starts a comment), sorted, each in [0, length]; a bad one
// is BadInput at FILE:line.
std::vector<double> readArcLengths(const std::string& path, double length) {
  std::ifstream in(path);
  if (!in) throw badInput({"--at-s " + path}, "cannot read the file");
  std::vector<double> arcs;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line.substr(0, line.find('#')));
    for (std::string word; words >> word;) {
      double s = 0.0;
      const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), s);
      if (ec != std::errc() || end != word.data() + word.size() || !(s >= 0.0 && s <= length))
        throw badInput(SourceLoc{path, number, 1}, "expected an arc length in [0, {:.17g}], got '{}'", length, word);
      arcs.push_back(s);
    }
  }
  if (arcs.empty()) throw badInput({"--at-s " + path}, "the file holds no arc length");
  std::sort(arcs.begin(), arcs.end());
  return arcs;
}

int runTimeline(const SolveOptions& o) {
  if (!o.output.empty()) {                          // before the solve, not after
    checkOutputFile(o.output, {"-o " + o.output});  // a folder, a missing folder: said first
    (void)jobs::timelineFormatOf(o.output, {"-o " + o.output});
  }
  const scene::SceneSpec spec = loadScene(o.scenePath, o.overrides);
  const RollingModel model = buildSceneModel(spec);
  SolverChoice choice = chooseSolver(spec, model);
  StageLog::instance().record("solver");
  const spin::SolveStats solved = solveScene(spec, model, choice);
  StageLog::instance().record("timeline-csv");
  std::vector<double> atS;  // --at-s: the file's arc lengths instead of the scene's sampling
  if (!o.atS.empty()) atS = readArcLengths(o.atS, model.path->length());
  const spin::SampleArcLengths samples = atS.empty() ? timelineArcLengths(spec, model) : spin::SampleArcLengths(atS);
  const std::filesystem::path out =
      o.output.empty() ? defaultOutputFile(spec.name + ".csv") : std::filesystem::path(o.output);
  createOutputParent(out);  // output/: only now, with the timeline solved
  const spin::SolveStats stats =
      jobs::writeTimelineFile(out, model, choice, samples, solved, {scene::writeScene(spec), o.commentHeader});
  std::fprintf(stderr, "rollspin: wrote %zu samples to %s (%s, %lld steps, %.3g s)\n", samples.size(),
               out.string().c_str(), std::string(spin::methodName(choice.method)).c_str(), stats.steps, stats.seconds);
  return 0;
}

}  // namespace

void registerSolveCommands(CLI::App& cli, CommandHandler& handler) {
  auto options = std::make_shared<SolveOptions>();

  CLI::App* solve = cli.add_subcommand("solve", "Propagate the rolling spinor and print the final orientation");
  solve->add_option("scene", options->scenePath, "Scene file (TOML), or a bundled scene's name (rollspin scenes)")
      ->required();
  solve->add_option("--set", options->overrides, "Override a scene key: --set key.sub=value (repeatable)");
  solve->add_flag("--json", options->json, "Print JSON");
  solve->callback([options, &handler] { handler = [options] { return runSolve(*options); }; });

  CLI::App* timeline = cli.add_subcommand("timeline",
                                          "Write the orientation timeline as CSV (with a NAME.csv.json "
                                          "sidecar), JSON, or numpy's .npy/.npz");
  timeline->add_option("scene", options->scenePath, "Scene file (TOML), or a bundled scene's name (rollspin scenes)")
      ->required();
  timeline->add_option("--set", options->overrides, "Override a scene key: --set key.sub=value (repeatable)");
  timeline->add_option(
      "-o,--output", options->output,
      "Output: its extension picks the format, .csv, .json, .npy or .npz (default: output/<scene>.csv)");
  timeline->add_flag("--comment-header", options->commentHeader,
                     "CSV: put the '# rollspin timeline: method, steps, error estimate' line above the header row");
  timeline->add_option("--at-s", options->atS,
                       "Sample at the arc lengths in this file (numbers, one or more a line, sorted on output) "
                       "instead of timeline.samples");
  timeline->callback([options, &handler] { handler = [options] { return runTimeline(*options); }; });

  // `scene` is registered by registerSceneCommand (scene_command.cpp): it reads outputs too.
}

}  // namespace rollspin::cli
