#include "app/render_jobs.hpp"

#include "core/memory_budget.hpp"
#include "core/stage_log.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "app/frame_poses.hpp"
#include "media/image_io.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"

namespace rollspin::app {

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

FrameOrientations solveFrame(const scene::SceneSpec& spec, const RollingModel& model, double s) {
  StageLog::instance().record("solver");
  const FrameSampling sampling = frameSampling(spec, model, s);
  std::vector<double> all = sampling.trail;
  all.insert(all.end(), sampling.strobe.begin(), sampling.strobe.end());
  all.push_back(s);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  std::vector<spin::Su2> orientation(all.size());
  marchScene(spec, model, all, [&](std::size_t i, double, const spin::Su2& q) { orientation[i] = q; });
  auto lookup = [&](double x) {
    const auto it = std::lower_bound(all.begin(), all.end(), x);
    return OrientedSample{x, orientation[static_cast<std::size_t>(it - all.begin())]};
  };
  FrameOrientations frame;
  frame.current = lookup(s);
  for (double x : sampling.trail) frame.trail.push_back(lookup(x));
  for (double x : sampling.strobe) frame.strobe.push_back(lookup(x));
  return frame;
}

FrameClock clipClock(const scene::SceneSpec& spec, const RollingModel& model) {
  if (!spec.isStoryboard()) return FrameClock(model.path->length(), spec);
  return FrameClock(model.segments, spec);
}

StoryPlace storyPlaceAt(const RollingModel& model, double s) {
  StoryPlace place;
  for (std::size_t k = 0; k < model.segments.size(); ++k)
    if (model.segments[k].end > model.segments[k].start && model.segments[k].start <= s) place.segment = k;
  return place;
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
    throw badInput(where, "ball.texture: {}x{} is larger than the 16384 px a texture may have", image.width, image.height);
  auto texture = std::make_shared<render::TextureImage>();
  texture->width = image.width;
  texture->height = image.height;
  texture->rgba = std::move(image.rgba);
  return texture;
}

void checkFrameMemory(const scene::SceneSpec& spec, std::uint64_t extraBytesPerPixel) {
  // Per pixel: multisampled colour and depth-stencil (4 + 4 bytes per sample),
  // the resolved colour, the read-back, the flipped image and the PNG rows
  // (4 bytes each); plus a fixed 96 MiB for the shadow map, the GL stack and
  // the meshes. Refuse before creating a context when that cannot fit.
  const std::uint64_t pixels = static_cast<std::uint64_t>(spec.render.width) * spec.render.height;
  const std::uint64_t needed = pixels * (8ULL * spec.render.msaa + 16ULL + extraBytesPerPixel) + (96ULL << 20);
  const auto available = availableMemoryBytes();
  if (available && needed > *available) {
    const std::string key = spec.locations.contains("render.height") ? "render.height" : "render.width";
    throw badInput(spec.where(key), "{}x{} with {}x MSAA needs about {} MiB for its frame buffers, but only {} MiB "
                                    "are available",
                   spec.render.width, spec.render.height, spec.render.msaa, needed >> 20, *available >> 20);
  }
}

render::ContextRequest contextRequest(const scene::SceneSpec& spec) {
  return {spec.render.backend, spec.where("render.backend"), spec.render.device, spec.where("render.device")};
}

std::filesystem::path renderStill(const StillOptions& o) {
  for (const auto& [flag, value] : {std::pair{"--width", o.width}, std::pair{"--height", o.height}})
    if (value && (*value < 1 || *value > 8192))
      throw badInput({flag}, "expected an image size in [1, 8192] pixels, got {}", *value);
  std::vector<std::string> overrides = o.overrides;
  // Command-line sizes go through the scene validation like --set does.
  if (o.width) overrides.push_back("render.width=" + std::to_string(*o.width));
  if (o.height) overrides.push_back("render.height=" + std::to_string(*o.height));
  if (o.transparent) overrides.push_back("render.transparent=true");
  const scene::SceneSpec spec = loadScene(o.scenePath, overrides);
  checkFrameMemory(spec);
  const RollingModel model = buildSceneModel(spec);
  const double length = model.path->length();
  double s = spec.render.strobe > 1 ? length : 0.5 * length;
  if (o.at) s = resolveArcPosition(parseArcPosition(*o.at), length, *o.at);
  const auto texture = spec.render.layout == scene::RenderLayout::Twin ? nullptr : loadBallTexture(spec);

  std::filesystem::path out = o.output;
  if (out.empty()) {
    std::filesystem::create_directories("output");
    out = std::filesystem::path("output") / (spec.name + ".png");
  }
  FrameOrientations frame = solveFrame(spec, model, s);
  frame.story = storyPlaceAt(model, s);
  const SceneDrawer drawer(spec, model, texture, makeSceneFacts(spec, model));
  const render::DrawList list = drawer.draw(frame);

  const auto context = render::createContext(contextRequest(spec));
  const render::ShaderLibrary shaders(o.shaderDir);
  render::Renderer renderer(*context, shaders);
  const media::Image image = renderer.render(list);
  StageLog::instance().record("png");
  media::writePng(out, image.view(), list.transparent ? media::PngChannels::Rgba : media::PngChannels::Rgb);
  return out;
}

}  // namespace rollspin::app
