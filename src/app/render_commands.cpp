// `rollspin render SCENE --still ...` and `rollspin compare A.png B.png ...`.
#include <fmt/format.h>

#include <cstdio>
#include <memory>

#include "app/animation_job.hpp"
#include "app/commands.hpp"
#include "app/render_jobs.hpp"
#include "core/output_path.hpp"
#include "media/image_compare.hpp"
#include "media/image_io.hpp"

namespace rollspin::app {

namespace {

struct RenderCliOptions {
  StillOptions still;
  bool stillFlag = false;
  std::string at, output, shaderDir;
  long long width = 0, height = 0;
  std::string frames, quality;
  bool quiet = false;
};

// Without --still: an animation (animation_job.hpp); 128 + signal when interrupted.
int runAnimation(const RenderCliOptions& o, const CLI::App& command) {
  for (const char* stillOnly : {"--at"})
    if (command.count(stillOnly) > 0) throw badInput({stillOnly}, "applies to --still only");
  AnimationOptions a;
  a.scenePath = o.still.scenePath;
  a.overrides = o.still.overrides;
  a.output = o.output;
  if (command.count("--frames") > 0) a.frames = o.frames;
  if (command.count("--quality") > 0) a.quality = o.quality;
  if (command.count("--width") > 0) a.width = o.width;
  if (command.count("--height") > 0) a.height = o.height;
  a.transparent = o.still.transparent;
  a.quiet = o.quiet;
  a.shaderDir = o.shaderDir;
  const AnimationResult result = renderAnimation(a);
  return result.interruptedBy != 0 ? 128 + result.interruptedBy : 0;
}

int runRender(RenderCliOptions& o, const CLI::App& command) {
  if (!o.stillFlag) return runAnimation(o, command);
  for (const char* animationOnly : {"--frames", "--quality"})
    if (command.count(animationOnly) > 0) throw badInput({animationOnly}, "applies to animations only (without --still)");
  if (command.count("--at") > 0) o.still.at = o.at;
  if (command.count("--width") > 0) o.still.width = o.width;
  if (command.count("--height") > 0) o.still.height = o.height;
  o.still.output = o.output;
  o.still.shaderDir = o.shaderDir;
  const auto written = renderStill(o.still);
  std::fprintf(stderr, "rollspin: wrote %s\n", written.string().c_str());
  return 0;
}

struct CompareOptions {
  std::string a, b, diff;
  double maxDelta = 0.0, meanDelta = 0.0;
};

int runCompare(const CompareOptions& o) {
  for (const auto& [flag, value] : {std::pair{"--max-delta", o.maxDelta}, std::pair{"--mean-delta", o.meanDelta}})
    if (!(value >= 0.0 && value <= 255.0))
      throw badInput({flag}, "expected a tolerance in [0, 255], got {}", value);
  // An unwritable --diff is the caller's mistake (exit 2), never "differ" (1).
  if (!o.diff.empty()) checkOutputFile(o.diff, SourceLoc{"--diff " + o.diff});
  const media::Image a = media::loadImage(o.a, SourceLoc{o.a});
  const media::Image b = media::loadImage(o.b, SourceLoc{o.b});
  if (a.width != b.width || a.height != b.height) {
    fmt::print("size mismatch: {}x{} vs {}x{}\n", a.width, a.height, b.width, b.height);
    return 1;
  }
  const media::ImageDifference d = media::compareImages(a.view(), b.view());
  fmt::print("max delta       R {} G {} B {} A {}  (overall {})\n", d.maxDelta[0], d.maxDelta[1], d.maxDelta[2],
             d.maxDelta[3], d.maxOverall());
  fmt::print("mean delta      R {:.4f} G {:.4f} B {:.4f} A {:.4f}  (overall {:.4f})\n", d.meanDelta[0], d.meanDelta[1],
             d.meanDelta[2], d.meanDelta[3], d.meanOverall());
  fmt::print("differing px    {} of {}\n", d.differingPixels, std::int64_t{a.width} * a.height);
  if (!o.diff.empty()) media::writePng(o.diff, media::differenceHeatMap(a.view(), b.view()).view());
  const bool within = d.maxOverall() <= o.maxDelta && d.meanOverall() <= o.meanDelta;
  fmt::print("{}\n", within ? "within tolerance" : "DIFFERENT");
  return within ? 0 : 1;
}

}  // namespace

void registerRenderCommands(CLI::App& cli, CommandHandler& handler) {
  auto options = std::make_shared<RenderCliOptions>();
  CLI::App* render =
      cli.add_subcommand("render", "Render a scene: an animation (MP4 or PNG frames), or a still PNG (--still)");
  render->add_option("scene", options->still.scenePath, "Scene file (TOML)")->required();
  render->add_flag("--still", options->stillFlag, "Render one still image");
  render->add_option("--at", options->at, "Where: s=ARC_LENGTH or fraction=F (default: fraction=0.5)");
  render->add_option("-o,--output", options->output,
                     "Output: FILE.mp4, or a folder for PNG frames; with --still a PNG "
                     "(default: output/<scene>.mp4, output/<scene>/ or output/<scene>.png)");
  render->add_option("--frames", options->frames, "Render only frames FIRST:LAST (0-based, inclusive) of the animation");
  render->add_option("--quality", options->quality,
                     "Animation size and frame rate: low (854x480@15), medium (1280x720@30), high (1920x1080@60), "
                     "4k (3840x2160@60)");
  render->add_flag("--quiet", options->quiet, "No progress bar or summary line");
  render->add_option("--width", options->width, "Image width in pixels (1..8192)");
  render->add_option("--height", options->height, "Image height in pixels (1..8192)");
  render->add_flag("--transparent", options->still.transparent, "RGBA PNG without background");
  render->add_option("--set", options->still.overrides, "Override a scene key: --set key.sub=value (repeatable)");
  render->add_option("--shader-dir", options->shaderDir, "Read shaders from this folder instead of the built-in copies");
  render->callback([options, render, &handler] {
    handler = [options, render] { return runRender(*options, *render); };
  });

  auto compare = std::make_shared<CompareOptions>();
  CLI::App* cmp = cli.add_subcommand("compare", "Compare two images (exit 0 within tolerance, 1 not, 2 bad input)");
  cmp->add_option("a", compare->a, "First image (PNG/JPG)")->required();
  cmp->add_option("b", compare->b, "Second image (PNG/JPG)")->required();
  // Negative or out-of-range tolerances are bad input (exit 2), not "different".
  cmp->add_option("--max-delta", compare->maxDelta, "Largest allowed per-channel difference (0-255, default 0)")
      ->check(CLI::Range(0.0, 255.0));
  cmp->add_option("--mean-delta", compare->meanDelta, "Largest allowed mean per-channel difference (default 0)")
      ->check(CLI::Range(0.0, 255.0));
  cmp->add_option("--diff", compare->diff, "Write a heat map of the difference (PNG)");
  cmp->callback([compare, &handler] { handler = [compare] { return runCompare(*compare); }; });
}

}  // namespace rollspin::app
