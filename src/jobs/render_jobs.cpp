#include "jobs/render_jobs.hpp"

#include "core/atomic_file.hpp"
#include "core/memory_budget.hpp"
#include "core/output_path.hpp"
#include "core/stage_log.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "jobs/address_space.hpp"
#include "jobs/figure_job.hpp"
#include "jobs/flag_overrides.hpp"
#include "jobs/job_setup.hpp"
#include "jobs/left_out_text.hpp"
#include "jobs/remembered_output.hpp"
#include "media/h264_levels.hpp"
#include "media/image_io.hpp"
#include "media/sink_factory.hpp"
#include "motion/frame_poses.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"

namespace rollspin::jobs {

using namespace rollspin::model;
using namespace rollspin::motion;
using namespace rollspin::draw;

ArcPosition parseArcPosition(const std::string& text) {
  const SourceLoc loc{"--at " + text};
  const auto eq = text.find('=');
  const std::string key = eq == std::string::npos ? "" : text.substr(0, eq);
  const std::string value = eq == std::string::npos ? "" : text.substr(eq + 1);
  ArcPosition at;
  if (key == "s") at.kind = ArcPosition::Kind::ArcLength;
  else if (key == "fraction") at.kind = ArcPosition::Kind::Fraction;
  else throw badInput(loc, "expected --at s=VALUE or --at fraction=F (e.g. --at fraction=0.5)");
  const char* first = value.data();
  const char* last = value.data() + value.size();
  const auto [ptr, ec] = std::from_chars(first, last, at.value);
  if (value.empty() || ec != std::errc() || ptr != last || !std::isfinite(at.value))
    throw badInput(loc, "'{}' is not a number", value);
  return at;
}

double resolveArcPosition(const ArcPosition& at, double length, const std::string& argument) {
  const SourceLoc loc{"--at " + argument};
  if (at.kind == ArcPosition::Kind::Fraction) {
    if (at.value < 0.0 || at.value > 1.0) throw badInput(loc, "fraction: expected a value in [0, 1], got {}", at.value);
    return at.value * length;
  }
  if (at.value < 0.0 || at.value > length * (1.0 + 1e-12))
    throw badInput(loc, "s: expected an arc length in [0, {}] (the path's length), got {}", length, at.value);
  return std::min(at.value, length);
}

std::shared_ptr<const render::TextureImage> loadBallTexture(const scene::SceneSpec& spec) {
  if (spec.ball.texture.empty()) return nullptr;
  StageLog::instance().record("ball-texture");
  const SourceLoc where = spec.where("ball.texture");
  std::filesystem::path file = spec.ball.texture;
  const bool fromCommandLine = where.file.rfind("--set", 0) == 0;
  if (file.is_relative() && !fromCommandLine && !spec.sourceFile.empty())
    file = std::filesystem::path(spec.sourceFile).parent_path() / file;
  media::Image image = media::loadImage(file, where);
  if (image.width > 16384 || image.height > 16384)
    throw badInput(where, "ball.texture: {}x{} is larger than the 16384 px a texture may have", image.width,
                   image.height);
  auto texture = std::make_shared<render::TextureImage>();
  texture->width = image.width;
  texture->height = image.height;
  texture->rgba = std::move(image.rgba);
  return texture;
}

std::uint64_t rendererBytes(std::uint64_t pixels, int msaa) {
  // Per pixel: multisampled colour and depth (4 + 4 bytes per sample), the
  // one-sample scene's colour and depth, the rows read back (composited on
  // the CPU), the retained layer's image, the image and the PNG rows (4
  // bytes each); plus a fixed 96 MiB for the shadow map, the GL stack and
  // the meshes; under ulimit -v, the driver's own reservations too.
  const std::uint64_t driver = addressSpaceLimitBytes() ? glDriverAddressSpaceBytes() : 0;
  return pixels * (8ULL * static_cast<std::uint64_t>(msaa) + 24ULL) + (96ULL << 20) + driver;
}

void checkFrameMemory(const scene::SceneSpec& spec, std::uint64_t extraBytesPerPixel) {
  // Refused before a context is created when it cannot fit.
  const std::uint64_t pixels = static_cast<std::uint64_t>(spec.render.width) * spec.render.height;
  const std::uint64_t needed = rendererBytes(pixels, spec.render.msaa) + pixels * extraBytesPerPixel;
  const auto available = availableMemoryBytes();
  if (available && needed > *available) {
    const std::string key = spec.locations.contains("render.height") ? "render.height" : "render.width";
    throw badInput(spec.where(key),
                   "{}x{} with {}x MSAA needs about {} MiB for its frame buffers{}, but "
                   "only {} MiB are available (out of memory)",
                   spec.render.width, spec.render.height, spec.render.msaa, needed >> 20,
                   addressSpaceLimitBytes() ? " and, under ulimit -v, the GL driver's own address space" : "",
                   *available >> 20);
  }
}

namespace {

// H.264 has no level for a frame over 139,264 macroblocks (6.2's MaxFS) or
// for more macroblocks a second than 6.2's MaxMBPS: libx264 would encode it
// anyway, tagged with a level it breaks, and players may refuse the file.
void checkH264Limits(const scene::SceneSpec& spec, const media::OutputFormat& format) {
  const int width = static_cast<int>(spec.render.width), height = static_cast<int>(spec.render.height);
  constexpr const char* elsewhere = "\"mov\" (ProRes), \"webm\" (VP9) or PNG frames (\"png\") hold it";
  if (!media::h264HoldsFrame(width, height)) {
    const std::string key = spec.locations.contains("render.height") ? "render.height" : "render.width";
    throw badInput(spec.where(key),
                   "{}: {}x{} is {} macroblocks of 16x16, over H.264's largest frame (level 6.2: "
                   "{} macroblocks, such as 8192x4320), so \"{}\" cannot hold it; {}",
                   key, width, height, media::h264Macroblocks(width, height), media::kH264LargestFrameMacroblocks,
                   format.name, elsewhere);
  }
  if (!media::lowestH264Level(width, height, spec.animation.fps.value()))
    throw badInput(spec.where("animation.fps"),
                   "animation.fps: {} frames a second of {}x{} is over H.264's largest "
                   "rate (level 6.2: 16711680 macroblocks a second), so \"{}\" cannot "
                   "hold it; lower the rate or the size, or {}",
                   spec.animation.fps.text(), width, height, format.name, elsewhere);
}

}  // namespace

const media::OutputFormat& chooseOutputFormat(const scene::SceneSpec& spec, const std::filesystem::path& output,
                                              media::OutputUse use) {
  const media::OutputFormat& format = media::chooseFormat(spec.render.format, spec.where("render.format"), output, use);
  if (spec.render.transparent && format.alpha == media::AlphaSupport::None) {
    std::string withAlpha;
    for (const media::OutputFormat& f : media::kOutputFormats)
      if (f.use() == use && f.alpha != media::AlphaSupport::None)
        withAlpha += fmt::format("{}{}", withAlpha.empty() ? "" : ", ", f.name);
    throw badInput(spec.where("render.transparent"),
                   "render.transparent: \"{}\" has no alpha channel ({}); for "
                   "transparency use {}",
                   format.name, format.name == "jpg" ? "JPEG has none" : "its codec has none", withAlpha);
  }
  if (format.evenSize)
    for (const auto& [key, value] :
         {std::pair{"render.width", spec.render.width}, std::pair{"render.height", spec.render.height}})
      if (value % 2 != 0)
        throw badInput(spec.where(key),
                       "{}: \"{}\" needs an even size (its chroma is subsampled), got {} (use {} or {})", key,
                       format.name, value, value - 1, value + 1);
  if (format.encodesH264()) checkH264Limits(spec, format);
  return format;
}

media::SinkOptions sinkOptions(const scene::SceneSpec& spec, const std::filesystem::path& path) {
  media::SinkOptions o;
  o.path = path;
  o.width = static_cast<int>(spec.render.width);
  o.height = static_cast<int>(spec.render.height);
  o.alpha = spec.render.transparent;
  o.crf = spec.animation.crf;
  o.preset = spec.animation.preset;
  o.loop = spec.animation.loop;
  o.jpegQuality = static_cast<int>(spec.render.jpegQuality);
  return o;
}

render::ContextRequest contextRequest(const scene::SceneSpec& spec) {
  return {spec.render.backend, spec.where("render.backend"), spec.render.device, spec.where("render.device")};
}

double stillArcLength(const DrawJob& job, const std::optional<std::string>& at) {
  const double length = job.model.path->length();
  if (at) return resolveArcPosition(parseArcPosition(*at), length, *at);
  return job.spec.render.strobe > 1 ? length : 0.5 * length;
}

FrameOrientations stillFrame(const DrawJob& job, double s) {
  FrameOrientations frame = solveFrame(job.spec, job.model, s);
  frame.story = storyPlaceAt(job.model, s);
  frame.still = true;
  return frame;
}

render::DrawList drawStill(const DrawJob& job, const std::optional<std::string>& at) {
  const double s = stillArcLength(job, at);
  return makeDrawer(job, s)->draw(stillFrame(job, s));
}

std::filesystem::path renderStill(const StillOptions& o) {
  DrawJob job = prepareDrawJob({o.scenePath,
                                o.overrides,
                                {},
                                o.width,
                                o.height,
                                o.transparent,
                                o.output,
                                media::OutputUse::Still,
                                0,
                                o.sceneText,
                                o.sceneName});
  const media::OutputFormat& format = *job.format;
  const auto figure = figureFormatOf(format);  // PDF/SVG: drawn by the vector backend (figure_job.hpp)
  if (figure) checkFigureSpec(job.spec);
  if (!o.layoutJson.empty() && !figure)
    throw badInput({"--layout-json"}, "applies to a figure (-o FILE.pdf or FILE.svg) only");
  // A figure's text is laid out for its printed size; a PNG still of a
  // scene that sets [figure] keys keeps the same composition, scaled.
  const bool figureLayout = o.figureLayout.value_or(setsFigureKeys(job.spec));
  // Recorded before the layout below changes the spec: loading the scene
  // and laying it out again gives the same.
  const std::optional<media::OutputMetadata> metadata =
      o.metadata ? std::optional(outputMetadata(job.spec, job.model,
                                                {figure ? JobRecord::Kind::Figure : JobRecord::Kind::Still,
                                                 job.spec.name, o.at, std::nullopt, figureLayout}))
                 : std::nullopt;
  if (figure || figureLayout) job.figureText = fitTextToFigure(job.spec);
  const scene::SceneSpec& spec = job.spec;

  // output/ is made only once the still is drawn (--at and the texture checked) and about to be written.
  const std::filesystem::path out =
      o.output.empty() ? defaultOutputFile(spec.name + format.defaultExtension()) : o.output;
  const render::DrawList list = drawStill(job, o.at);
  if (figure) {
    createOutputParent(out);
    writeFigureStill(spec, list, out, *figure, o.shaderDir, metadata ? &*metadata : nullptr);
    // Nothing left out silently: each text the layout had no room for, and
    // the width or size that keeps it.
    std::vector<render::FigureLayout::LeftOut> leftOut;
    if (!list.leftOut.empty()) {
      leftOut = whereLeftOutIsKept(job, o.at, list);
      reportLeftOut(leftOut, spec.figure.widthMm, figureTextPt(spec));
    }
    if (!o.layoutJson.empty()) {
      render::FigureLayout layout = render::figureLayout(list, figureStyleOf(spec, list));
      if (!leftOut.empty()) layout.leftOut = leftOut;
      AtomicFile json(o.layoutJson);
      json.write(render::figureLayoutJson(layout));
      json.commit();
    }
    return out;
  }

  GlRenderer gl(spec, o.shaderDir);
  const media::Image image = gl.renderer.render(list);
  StageLog::instance().record(std::string(format.name));
  createOutputParent(out);
  media::SinkOptions sinkOpts = sinkOptions(spec, out);
  sinkOpts.metadata = metadata;
  const auto sink = media::openSink(format, sinkOpts);
  sink->write(image.view());
  return sink->finish();
}

}  // namespace rollspin::jobs
