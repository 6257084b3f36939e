#include "jobs/job_setup.hpp"

#include <algorithm>
#include <cmath>

#include "core/output_path.hpp"
#include "jobs/render_jobs.hpp"
#include "motion/scene_facts.hpp"
#include "scene/scene_tables.hpp"

namespace rollspin::jobs {

DrawJob prepareDrawJob(const DrawJobRequest& r) {
  for (const auto& [flag, value] : {std::pair{"--width", r.width}, std::pair{"--height", r.height}})
    if (value && (*value < scene::kMinImageSide || *value > scene::kMaxImageSide))
      throw badInput({flag}, "expected an image size in [{}, {}] pixels, got {}", scene::kMinImageSide,
                     scene::kMaxImageSide, *value);
  // Later overrides win: --set, then --quality (but not over a key given with
  // --set), then --width/--height; all validated by the scene loader, and an
  // error names the flag typed.
  std::vector<FlagOverride> flags = r.presetFlags;
  if (r.width)
    flags.push_back(flagOverride("--width " + std::to_string(*r.width), "render", scene::key::kWidth, *r.width));
  if (r.height)
    flags.push_back(flagOverride("--height " + std::to_string(*r.height), "render", scene::key::kHeight, *r.height));
  if (r.transparent) flags.push_back(flagOverride("--transparent", "render", scene::key::kTransparent, true));
  DrawJob job{loadSceneWithFlags(r.scenePath, r.overrides, flags, r.sceneText), nullptr, {}, {}};
  scene::SceneSpec& spec = job.spec;
  if (!r.sceneName.empty()) spec.name = r.sceneName;
  // Text without a name (an API caller's): the name Python gives one, not
  // "" (a job record without a scene, a default output "output/.mp4").
  if (spec.name.empty()) spec.name = "scene";
  const media::OutputFormat& format = chooseOutputFormat(spec, r.output, r.use);
  job.format = &format;
  // What the format's row asks of the output. A GIF: its own default size
  // when neither the scene nor a flag gives one (height by the aspect
  // ratio), and a frame rate capped so frames last whole 1/100 s.
  if (format.defaultWidth > 0 && !spec.locations.contains("render.width") &&
      !spec.locations.contains("render.height")) {
    const long long w = spec.render.width, h = spec.render.height;
    spec.render.width = format.defaultWidth;
    spec.render.height = std::max<long long>(1, std::llround(double(format.defaultWidth) * double(h) / double(w)));
  }
  if (format.fpsCap > 0 && spec.animation.fps.value() > format.fpsCap)
    spec.animation.fps = scene::FrameRate{format.fpsCap, 1};
  if (!r.output.empty()) {  // before any work: a folder for frames, else a file
    const SourceLoc where{"-o " + r.output.string()};
    if (format.isFolder()) checkOutputFolder(r.output, where);
    else checkOutputFile(r.output, where);
  }
  checkFrameMemory(spec, r.extraBytesPerPixel);
  job.model = model::buildSceneModel(spec);
  return job;
}

std::unique_ptr<draw::SceneDrawer> makeDrawer(const DrawJob& job, std::optional<double> figureStillAt) {
  const auto texture = job.spec.render.layout == scene::RenderLayout::Twin ? nullptr : loadBallTexture(job.spec);
  return std::make_unique<draw::SceneDrawer>(job.spec, job.model, texture, motion::makeSceneFacts(job.spec, job.model),
                                             figureStillAt, job.figureText);
}

GlRenderer::GlRenderer(const scene::SceneSpec& spec, const std::filesystem::path& shaderDir)
    : context(render::createContext(contextRequest(spec))), shaders(shaderDir), renderer(*context, shaders) {}

}  // namespace rollspin::jobs
