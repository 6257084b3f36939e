// `rollspin render SCENE --still ...` and `rollspin compare A.png B.png ...`.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

#include "cli/commands.hpp"
#include "core/output_path.hpp"
#include "core/text.hpp"
#include "jobs/animation_job.hpp"
#include "jobs/remembered_output.hpp"
#include "jobs/render_jobs.hpp"
#include "media/image_compare.hpp"
#include "media/image_io.hpp"

namespace rollspin::cli {

using namespace rollspin::model;
using namespace rollspin::motion;
using namespace rollspin::draw;

namespace {

struct RenderCliOptions {
  jobs::StillOptions still;
  bool stillFlag = false;
  std::string at, output, shaderDir;
  long long width = 0, height = 0;
  std::string frames, quality, shard, subtitles;
  bool quiet = false;
  std::string from;                           // --from FILE: an output that remembers its scene and job
  bool noMetadata = false;                    // --no-metadata
  bool atGiven = false, framesGiven = false;  // by the flag, or by the job --from remembers
};

// Without --still: an animation (animation_job.hpp); 128 + signal when interrupted.
int runAnimation(const RenderCliOptions& o, const CLI::App& command) {
  for (const char* stillOnly : {"--at", "--layout-json"})
    if (command.count(stillOnly) > 0) throw badInput({stillOnly}, "applies to --still only");
  jobs::AnimationOptions a;
  a.scenePath = o.still.scenePath;
  a.overrides = o.still.overrides;
  a.output = o.output;
  if (o.framesGiven) a.frames = o.frames;
  if (command.count("--shard") > 0) a.shard = o.shard;
  if (command.count("--quality") > 0) a.quality = o.quality;
  if (command.count("--subtitles") > 0) a.sidecars = media::parseSidecarFormats(o.subtitles, "--subtitles");
  if (command.count("--width") > 0) a.width = o.width;
  if (command.count("--height") > 0) a.height = o.height;
  a.transparent = o.still.transparent;
  a.quiet = o.quiet;
  a.shaderDir = o.shaderDir;
  a.sceneText = o.still.sceneText;
  a.sceneName = o.still.sceneName;
  a.metadata = !o.noMetadata;
  const jobs::AnimationResult result = renderAnimation(a);
  return result.interruptedBy != 0 ? 128 + result.interruptedBy : 0;
}

// --from FILE: the scene and the job the output remembers; the flags given
// now win over the job's (another --at, --frames, size or -o).
void takeRememberedJob(RenderCliOptions& o, const CLI::App& command) {
  if (!o.still.scenePath.empty()) throw badInput({"--from " + o.from}, "give a scene or --from FILE, not both");
  const jobs::RememberedOutput remembered = jobs::readRememberedOutput(o.from);
  o.still.sceneText = remembered.metadata.scene;
  o.still.scenePath = remembered.sourceName;
  o.still.sceneName = remembered.sceneName;
  if (o.output.empty()) {  // the same format, under the job's default name
    std::filesystem::create_directories("output");
    o.output = (std::filesystem::path("output") / remembered.sceneName).string() +
               asciiLowercase(std::filesystem::path(o.from).extension().string());
  }
  if (!remembered.job) return;
  const jobs::JobRecord& job = *remembered.job;
  if (job.kind != jobs::JobRecord::Kind::Clip) {
    o.stillFlag = true;
    if (!o.atGiven && job.at) {
      o.at = *job.at;
      o.atGiven = true;
    }
    o.still.figureLayout = job.figureLayout;
  } else if (!o.stillFlag && !o.framesGiven && command.count("--shard") == 0 && job.frames) {
    o.frames = *job.frames;
    o.framesGiven = true;
  }
}

int runRender(RenderCliOptions& o, const CLI::App& command) {
  o.still.metadata = !o.noMetadata;
  o.atGiven = command.count("--at") > 0;
  o.framesGiven = command.count("--frames") > 0;
  if (!o.from.empty()) takeRememberedJob(o, command);
  else if (o.still.scenePath.empty())
    throw badInput({"render"}, "give a scene file (or a bundled scene's name), or --from FILE");
  if (!o.stillFlag) return runAnimation(o, command);
  for (const char* animationOnly : {"--frames", "--shard", "--quality", "--subtitles"})
    if (command.count(animationOnly) > 0)
      throw badInput({animationOnly}, "applies to animations only (without --still)");
  if (o.atGiven) o.still.at = o.at;
  if (command.count("--width") > 0) o.still.width = o.width;
  if (command.count("--height") > 0) o.still.height = o.height;
  o.still.output = o.output;
  o.still.shaderDir = o.shaderDir;
  const auto written = jobs::renderStill(o.still);
  if (!o.quiet) std::fprintf(stderr, "rollspin: wrote %s\n", written.string().c_str());
  return 0;
}

struct CompareOptions {
  std::string a, diff, maxPixels;
  std::vector<std::string> references;
  double maxDelta = 0.0;
  std::optional<double> meanDelta, minSsim;
  bool json = false;
};

// --max-pixels: a count ("120") or a share of the image ("0.5%").
struct PixelAllowance {
  double count = 0.0;
  bool percent = false;
  [[nodiscard]] double allowedOf(std::int64_t total) const { return percent ? count / 100.0 * double(total) : count; }
};

PixelAllowance parsePixelAllowance(const std::string& text) {
  const SourceLoc loc{"--max-pixels " + text};
  PixelAllowance allowance;
  std::string number = text;
  if (!number.empty() && number.back() == '%') {
    allowance.percent = true;
    number.pop_back();
  }
  const char* first = number.data();
  const char* last = first + number.size();
  const auto [ptr, ec] = std::from_chars(first, last, allowance.count);
  const bool valid = !number.empty() && ec == std::errc() && ptr == last && allowance.count >= 0.0 &&
                     (allowance.percent ? allowance.count <= 100.0 : allowance.count == std::floor(allowance.count));
  if (!valid) throw badInput(loc, "expected a pixel count (e.g. 50) or a percentage of the image (e.g. 0.1%)");
  return allowance;
}

struct ReferenceResult {
  std::string path;
  int width = 0, height = 0;
  bool sizeMatches = false;
  media::ImageDifference d;
  std::int64_t overMaxDelta = 0;  // pixels whose largest channel difference exceeds --max-delta
  double ssim = 0.0;
  bool pass = false;
  // Each threshold it failed, in the options' words: "size" (no other
  // measure then exists), "max_delta" (with --max-pixels), "mean_delta",
  // "min_ssim"; `why` says each one with its numbers for the text output.
  std::vector<std::string> failed, why;
};

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += {'\\', c};
    else if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", int(c));
    else out += c;
  }
  return out + "\"";
}

// As typed: the shortest text that reads back as the same double (0.6, not 0.59999999999999998).
std::string jsonNumber(std::optional<double> v) { return v ? fmt::format("{}", *v) : "null"; }

std::string jsonList(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + jsonString(item);
  return "[" + out + "]";
}

void printText(const CompareOptions& o, const std::vector<ReferenceResult>& results, const media::Image& a) {
  const std::int64_t pixels = std::int64_t{a.width} * a.height;
  for (const ReferenceResult& r : results) {
    if (results.size() > 1) fmt::print("reference       {}\n", r.path);
    if (!r.sizeMatches) {
      fmt::print("size mismatch   {}x{} vs {}x{}: no pixel was compared\nDIFFERENT: the sizes differ\n", a.width,
                 a.height, r.width, r.height);
      continue;
    }
    const media::ImageDifference& d = r.d;
    fmt::print("max delta       R {} G {} B {} A {}  (overall {})\n", d.maxDelta[0], d.maxDelta[1], d.maxDelta[2],
               d.maxDelta[3], d.maxOverall());
    fmt::print("mean delta      R {:.4f} G {:.4f} B {:.4f} A {:.4f}  (overall {:.4f})\n", d.meanDelta[0],
               d.meanDelta[1], d.meanDelta[2], d.meanDelta[3], d.meanOverall());
    fmt::print("differing px    {} of {} ({} by more than {} levels)\n", d.differingPixels, pixels, r.overMaxDelta,
               o.maxDelta);
    fmt::print("ssim            {:.6f}\n", r.ssim);
    if (r.pass) fmt::print("within tolerance\n");
    else fmt::print("DIFFERENT: {}\n", fmt::join(r.why, "; "));
  }
}

int runCompareChecked(const CompareOptions& o) {
  for (const auto& [flag, value] :
       {std::pair{"--max-delta", std::optional<double>(o.maxDelta)}, std::pair{"--mean-delta", o.meanDelta}})
    if (value && !(*value >= 0.0 && *value <= 255.0))
      throw badInput({flag}, "expected a tolerance in [0, 255], got {}", *value);
  if (o.minSsim && !(*o.minSsim >= -1.0 && *o.minSsim <= 1.0))
    throw badInput({"--min-ssim"}, "expected an SSIM in [-1, 1] (1: identical), got {}", *o.minSsim);
  const PixelAllowance allowance = o.maxPixels.empty() ? PixelAllowance{} : parsePixelAllowance(o.maxPixels);
  // An unwritable --diff is the caller's mistake (exit 2), never "differ" (1).
  if (!o.diff.empty()) checkOutputFile(o.diff, SourceLoc{"--diff " + o.diff});
  const media::Image a = media::loadImage(o.a, SourceLoc{o.a});
  const std::int64_t pixels = std::int64_t{a.width} * a.height;
  std::vector<ReferenceResult> results;
  std::vector<media::Image> images;
  for (const std::string& path : o.references) {
    images.push_back(media::loadImage(path, SourceLoc{path}));
    const media::Image& b = images.back();
    ReferenceResult r;
    r.path = path;
    r.width = b.width;
    r.height = b.height;
    r.sizeMatches = a.width == b.width && a.height == b.height;
    if (!r.sizeMatches) {
      std::fprintf(stderr, "rollspin: size mismatch: %s is %dx%d, %s is %dx%d\n", o.a.c_str(), a.width, a.height,
                   path.c_str(), b.width, b.height);
      r.failed.push_back("size");
      r.why.push_back(fmt::format("the sizes differ ({}x{} vs {}x{})", a.width, a.height, b.width, b.height));
    } else {
      r.d = media::compareImages(a.view(), b.view());
      r.overMaxDelta = r.d.pixelsAbove(static_cast<int>(std::floor(o.maxDelta)));
      r.ssim = media::structuralSimilarity(a.view(), b.view());
      // Every threshold is checked, so the message names each one that failed.
      if (const double allowed = allowance.allowedOf(pixels); double(r.overMaxDelta) > allowed) {
        r.failed.push_back("max_delta");
        r.why.push_back(fmt::format("--max-delta {}: {} pixels differ by more than {} levels, {} allowed{}", o.maxDelta,
                                    r.overMaxDelta, o.maxDelta, std::floor(allowed),
                                    o.maxPixels.empty() ? "" : " (--max-pixels " + o.maxPixels + ")"));
      }
      if (o.meanDelta && !(r.d.meanOverall() <= *o.meanDelta)) {
        r.failed.push_back("mean_delta");
        r.why.push_back(fmt::format("--mean-delta {}: the mean delta is {:.4f}", *o.meanDelta, r.d.meanOverall()));
      }
      if (o.minSsim && !(r.ssim >= *o.minSsim)) {
        r.failed.push_back("min_ssim");
        r.why.push_back(fmt::format("--min-ssim {}: the SSIM is {:.6f}", *o.minSsim, r.ssim));
      }
      r.pass = r.failed.empty();
    }
    results.push_back(r);
  }
  // The diff shows the reference that matched, else the closest same-size one, else the first.
  std::size_t best = 0;
  for (std::size_t k = 0; k < results.size(); ++k) {
    const ReferenceResult &r = results[k], &b = results[best];
    const bool better = (r.pass && !b.pass) ||
                        (r.pass == b.pass && r.sizeMatches && (!b.sizeMatches || r.overMaxDelta < b.overMaxDelta));
    if (better) best = k;
  }
  const bool pass = results[best].pass;
  if (!o.diff.empty()) media::writePng(o.diff, media::differenceHeatMap(a.view(), images[best].view()).view());
  if (o.json) {
    std::string refs;
    for (const ReferenceResult& r : results) {
      const media::ImageDifference& d = r.d;
      // A size mismatch compares no pixel: its measures are null, not zeros.
      const auto measured = [&](std::string text) { return r.sizeMatches ? text : std::string("null"); };
      refs += fmt::format(
          "{}    {{\"path\": {}, \"width\": {}, \"height\": {}, \"size_matches\": {}, \"max_delta\": {}, "
          "\"mean_delta\": {}, \"differing_pixels\": {}, \"pixels_over_max_delta\": {}, \"ssim\": {}, "
          "\"pass\": {}, \"failed\": {}, \"why\": {}}}",
          refs.empty() ? "" : ",\n", jsonString(r.path), r.width, r.height, r.sizeMatches,
          measured(fmt::format("[{}, {}, {}, {}]", d.maxDelta[0], d.maxDelta[1], d.maxDelta[2], d.maxDelta[3])),
          measured(fmt::format("[{:.6g}, {:.6g}, {:.6g}, {:.6g}]", d.meanDelta[0], d.meanDelta[1], d.meanDelta[2],
                               d.meanDelta[3])),
          measured(std::to_string(d.differingPixels)), measured(std::to_string(r.overMaxDelta)),
          measured(fmt::format("{:.9f}", r.ssim)), r.pass, jsonList(r.failed), jsonList(r.why));
    }
    fmt::print(
        "{{\n  \"image\": {},\n  \"width\": {},\n  \"height\": {},\n  \"pass\": {},\n  \"matched\": {},\n"
        "  \"thresholds\": {{\"max_delta\": {}, \"max_pixels\": {}, \"mean_delta\": {}, \"min_ssim\": {}}},\n"
        "  \"diff\": {},\n  \"references\": [\n{}\n  ]\n}}\n",
        jsonString(o.a), a.width, a.height, pass, pass ? jsonString(results[best].path) : "null",
        jsonNumber(o.maxDelta), o.maxPixels.empty() ? "0" : jsonString(o.maxPixels), jsonNumber(o.meanDelta),
        jsonNumber(o.minSsim), o.diff.empty() ? "null" : jsonString(o.diff), refs);
  } else {
    printText(o, results, a);
    if (results.size() > 1)
      fmt::print("{}\n", pass ? "matches " + results[best].path : "DIFFERENT from every reference");
  }
  return pass ? 0 : 1;
}

// Exit 1 means "the images differ" and nothing else: a CI script must not
// read a broken environment as a golden mismatch, so any failure is 2.
int runCompare(const CompareOptions& o) {
  try {
    return runCompareChecked(o);
  } catch (const Error& e) {
    if (e.kind() == ErrorKind::BadInput) throw;
    throw Error(ErrorKind::BadInput, e.where(), e.message());
  }
}

}  // namespace

void registerRenderCommands(CLI::App& cli, CommandHandler& handler) {
  auto options = std::make_shared<RenderCliOptions>();
  CLI::App* render =
      cli.add_subcommand("render",
                         "Render a scene: a clip (MP4, WebM, MOV, GIF or PNG frames), or with --still an "
                         "image (PNG, JPEG) or a figure (PDF, SVG)");
  render->add_option("scene", options->still.scenePath,
                     "Scene file (TOML), or a bundled scene's name (rollspin scenes); or give --from FILE");
  render->add_option("--from", options->from,
                     "Render again what an output rollspin wrote remembers: its scene and its job (a still as a "
                     "still at its --at, a figure as a figure, a clip as a clip); flags given now win");
  render->add_flag("--no-metadata", options->noMetadata,
                   "Leave the scene, the job, the version and the description out of the output");
  render->add_flag("--still", options->stillFlag, "Render one still image");
  render->add_option("--at", options->at, "Where: s=ARC_LENGTH or fraction=F (default: fraction=0.5)");
  render->add_option("-o,--output", options->output,
                     "Output; its extension picks the format: a clip FILE.mp4|.webm|.mov|.gif or a folder for PNG "
                     "frames; with --still FILE.png|.jpg|.pdf|.svg (default: output/<scene>.mp4, or "
                     "output/<scene>.png; render.format overrides)");
  render->add_option("--frames", options->frames,
                     "Render only frames FIRST:LAST (0-based, inclusive) of the animation");
  render->add_option("--shard", options->shard,
                     "Render the K-th of N near-equal frame ranges (K/N, 1-based) to NAME.part-K-of-N.mp4 "
                     "(PNG frames: into the clip's folder); `rollspin join` makes the parts whole");
  render->add_option("--quality", options->quality,
                     "Animation size and frame rate: low (854x480@15), medium (1280x720@30), high (1920x1080@60), "
                     "4k (3840x2160@60)");
  render->add_option("--subtitles", options->subtitles,
                     "An MP4, WebM or MOV clip's captions and title as files beside it: vtt (NAME.vtt, the "
                     "default), srt (NAME.vtt and NAME.srt) or none; the clip's subtitle track carries them "
                     "whatever this says");
  render->add_flag("--quiet", options->quiet, "No progress bar or summary line (a still: no \"wrote FILE\" line)");
  const std::string sides = fmt::format("({}..{})", scene::kMinImageSide, scene::kMaxImageSide);
  render->add_option("--width", options->width, "Image width in pixels " + sides);
  render->add_option("--height", options->height, "Image height in pixels " + sides);
  render->add_flag("--transparent", options->still.transparent,
                   "No background: alpha in a PNG still or PNG frames, a WebM (VP9) or MOV "
                   "(ProRes 4444) clip, a PDF/SVG figure; GIF: 1-bit");
  render->add_option("--set", options->still.overrides, "Override a scene key: --set key.sub=value (repeatable)");
  render->add_option("--layout-json", options->still.layoutJson,
                     "With --still and a PDF/SVG figure: also write its layout (text boxes, plates, arrows, paths; "
                     "page points) as JSON");
  render->add_option("--shader-dir", options->shaderDir,
                     "Read shaders from this folder instead of the built-in copies");
  render->callback(
      [options, render, &handler] { handler = [options, render] { return runRender(*options, *render); }; });

  auto compare = std::make_shared<CompareOptions>();
  CLI::App* cmp = cli.add_subcommand(
      "compare",
      "Compare an image with one or more references (exit 0: matches one, 1: differs from all, 2: bad "
      "input or environment)");
  cmp->add_option("a", compare->a, "The image to check (PNG/JPG)")->required();
  cmp->add_option("references", compare->references, "Reference images: passes if any one matches")->required();
  // Out-of-range tolerances are bad input (exit 2), not "different": checked in runCompare.
  cmp->add_option("--max-delta", compare->maxDelta,
                  "Largest per-pixel difference (any channel, 0-255 levels) not counted as differing (default 0)");
  cmp->add_option("--max-pixels", compare->maxPixels,
                  "How many pixels may differ by more than --max-delta: a count or a percentage (e.g. 0.1%; "
                  "default 0)");
  cmp->add_option("--mean-delta", compare->meanDelta,
                  "Largest allowed mean per-channel difference (not checked "
                  "by default)");
  cmp->add_option("--min-ssim", compare->minSsim,
                  "Smallest allowed SSIM of the luma (Gaussian 11x11 window; 1 is "
                  "identical; not checked by default)");
  cmp->add_option("--diff", compare->diff, "Write a heat map of the difference (PNG) against the best reference");
  cmp->add_flag("--json", compare->json, "Print the measurements and the verdict as JSON");
  cmp->callback([compare, &handler] { handler = [compare] { return runCompare(*compare); }; });
}

}  // namespace rollspin::cli
