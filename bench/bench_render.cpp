// bench_render: milliseconds per 1920×1080 frame of the lollipop (or
// ROLLSPIN_BENCH_SCENE), side by side, 4× MSAA with the shadow map,
// including the DrawList build and the pixel read-back (not PNG encoding).
// The target is ≤ 40 ms on the 2-core reference machine so that rendering
// never costs more than the H.264 encoding it feeds. Run: ./build/bench/bench_render
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "bench_size.hpp"
#include "draw/scene_drawer.hpp"
#include "jobs/render_jobs.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"

namespace {

// ROLLSPIN_BENCH_SCENE=NAME: another scene of scenes/ (torus, say) for every
// benchmark, for experiments; the lollipop by default.
std::string benchScenePath() {
  const char* name = std::getenv("ROLLSPIN_BENCH_SCENE");
  return std::string(rollspin::bench::kSceneDir) + "/" + (name != nullptr && *name != '\0' ? name : "lollipop") +
         ".toml";
}

std::vector<std::string> sizeOverrides() {
  const rollspin::bench::FrameSize& size = rollspin::bench::benchFrameSize("bench_render");
  return {"render.width=" + std::to_string(size.width), "render.height=" + std::to_string(size.height)};
}
std::string sizeLabel() {
  const rollspin::bench::FrameSize& size = rollspin::bench::benchFrameSize("bench_render");
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

void BM_RenderFrame1080p(benchmark::State& state) {
  using namespace rollspin;
  std::vector<std::string> overrides = sizeOverrides();
  overrides.insert(overrides.end(), {"render.layout=side-by-side", "render.msaa=" + std::to_string(state.range(0))});
  // ROLLSPIN_BENCH_SET=key=value: one extra scene override, for experiments.
  if (const char* extra = std::getenv("ROLLSPIN_BENCH_SET")) overrides.emplace_back(extra);
  const scene::SceneSpec spec = scene::loadSceneFile(benchScenePath(), overrides);
  const model::RollingModel model = model::buildModel(spec);
  const motion::FrameOrientations frame = motion::solveFrame(spec, model, 0.3 * model.path->length());
  const draw::SceneDrawer drawer(spec, model, nullptr);
  const auto context = render::createContext(jobs::contextRequest(spec));
  // ROLLSPIN_SHADER_DIR: time edited shaders without rebuilding (development).
  const char* shaderDir = std::getenv("ROLLSPIN_SHADER_DIR");
  render::Renderer renderer(*context, render::ShaderLibrary{shaderDir != nullptr ? shaderDir : ""});
  renderer.setRetainLayers(false);            // a still's cost: the frame drawn whole
  (void)renderer.render(drawer.draw(frame));  // warm-up: shader JIT, uploads
  // CPU time of the whole process (llvmpipe's worker threads included): on a
  // busy shared machine wall time mostly measures the neighbours, this does
  // not. On an idle machine wall ≈ process CPU / cores.
  auto processCpuSeconds = [] {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
  };
  const render::RenderStats before = renderer.stats();
  const double cpuStart = processCpuSeconds();
  media::Image image;
  for (auto _ : state) {
    const render::DrawList list = drawer.draw(frame);
    renderer.render(list, image);
    benchmark::DoNotOptimize(image.rgba.data());
  }
  state.counters["process_cpu_ms_per_frame"] =
      1e3 * (processCpuSeconds() - cpuStart) / double(std::max<benchmark::IterationCount>(1, state.iterations()));
  state.counters["sampled_share"] = double(renderer.stats().sampledPixels - before.sampledPixels) /
                                    double(std::max(1LL, renderer.stats().wholeViewPixels - before.wholeViewPixels));
  state.SetLabel(sizeLabel() + ", " + std::to_string(spec.render.msaa) + "x MSAA, shadow, side-by-side");
}
// Arg = MSAA samples; 4 is the target configuration, 1 shows what MSAA costs
// (llvmpipe runs 2 samples as 4: same cost). Layers off: every frame is
// drawn whole, as a still is.
BENCHMARK(BM_RenderFrame1080p)->Arg(4)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Frames of a clip: the ball at 24 arc lengths in turn (s from 0.3 L on, a
// in steps of L/300, as a 10 s clip at 30 fps), or all 300, side by side,
// 4× MSAA. First argument 0: the fixed default camera, so every frame after
// the first two is drawn over the retained layer; 1: render.follow = true,
// the camera moves every frame (the ball's view is drawn whole, the twin's
// over the layer). Second argument: the number of frames.
void BM_ClipFrames1080p(benchmark::State& state) {
  using namespace rollspin;
  std::vector<std::string> overrides = sizeOverrides();
  overrides.emplace_back("render.layout=side-by-side");
  if (state.range(0) == 1) overrides.emplace_back("render.follow=true");
  if (const char* extra = std::getenv("ROLLSPIN_BENCH_SET")) overrides.emplace_back(extra);
  const scene::SceneSpec spec = scene::loadSceneFile(benchScenePath(), overrides);
  const jobs::RollingModel model = model::buildModel(spec);
  std::vector<motion::FrameOrientations> frames;
  // 24 frames from 0.3 L on, in turn (the cycle steps back at its end, so a
  // growing line's settled prefix shrinks there: more layer updates than a
  // clip has), or the 300 frames of the whole 10 s clip in order.
  const int count = int(state.range(1));
  const double start = count == 24 ? 0.3 : 0.0;
  for (int k = 0; k < count; ++k)
    frames.push_back(motion::solveFrame(spec, model, (start + double(k) / 300.0) * model.path->length()));
  const draw::SceneDrawer drawer(spec, model, nullptr);
  const auto context = render::createContext(jobs::contextRequest(spec));
  const char* shaderDir = std::getenv("ROLLSPIN_SHADER_DIR");
  render::Renderer renderer(*context, render::ShaderLibrary{shaderDir != nullptr ? shaderDir : ""});
  // One image with its history, as a video's pool keeps them (see ImageHistory).
  media::Image image;
  render::ImageHistory history;
  for (int k = 0; k < 3; ++k) renderer.render(drawer.draw(frames[std::size_t(k)]), image, history);  // warm-up
  auto processCpuSeconds = [] {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
  };
  const render::RenderStats before = renderer.stats();
  const double cpuStart = processCpuSeconds();
  std::size_t k = 3;
  for (auto _ : state) {
    renderer.render(drawer.draw(frames[k++ % frames.size()]), image, history);
    benchmark::DoNotOptimize(image.rgba.data());
  }
  const double n = double(std::max<benchmark::IterationCount>(1, state.iterations()));
  state.counters["process_cpu_ms_per_frame"] = 1e3 * (processCpuSeconds() - cpuStart) / n;
  state.counters["retained_share"] = double(renderer.stats().retainedFrames - before.retainedFrames) / n;
  state.counters["layer_builds_per_frame"] = double(renderer.stats().layerBuilds - before.layerBuilds) / n;
  state.counters["redrawn_share"] = double(renderer.stats().redrawnPixels - before.redrawnPixels) /
                                    double(std::max(1LL, renderer.stats().retainedPixels - before.retainedPixels));
  state.counters["layer_updates_per_frame"] = double(renderer.stats().layerUpdates - before.layerUpdates) / n;
  state.counters["sphere_replays_per_frame"] = double(renderer.stats().sphereReplays - before.sphereReplays) / n;
  state.counters["sphere_captures"] = double(renderer.stats().sphereCaptures - before.sphereCaptures);
  state.counters["sampled_share"] = double(renderer.stats().sampledPixels - before.sampledPixels) /
                                    double(std::max(1LL, renderer.stats().wholeViewPixels - before.wholeViewPixels));
  // The samples as the scene says them (ROLLSPIN_BENCH_SET may change them).
  state.SetLabel(sizeLabel() + ", " + std::to_string(spec.render.msaa) + "x MSAA" +
                 (state.range(0) == 1 ? ", camera follows the ball" : ", fixed camera") +
                 (count == 300 ? ", the whole clip in order" : ""));
}
BENCHMARK(BM_ClipFrames1080p)
    ->Args({0, 24})
    ->Args({1, 24})
    ->Args({0, 300})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The CPU-side half alone: (scene, orientations) → DrawList.
void BM_DrawList1080p(benchmark::State& state) {
  using namespace rollspin;
  const std::vector<std::string> overrides = sizeOverrides();
  const scene::SceneSpec spec = scene::loadSceneFile(benchScenePath(), overrides);
  const model::RollingModel model = model::buildModel(spec);
  const motion::FrameOrientations frame = motion::solveFrame(spec, model, 0.3 * model.path->length());
  const draw::SceneDrawer drawer(spec, model, nullptr);
  for (auto _ : state) {
    render::DrawList list = drawer.draw(frame);
    benchmark::DoNotOptimize(list.meshes.data());
  }
}
BENCHMARK(BM_DrawList1080p)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
