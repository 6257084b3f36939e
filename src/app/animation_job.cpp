#include "app/animation_job.hpp"

#include <fmt/format.h>
#include <pthread.h>

#include <array>
#include <cctype>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "app/bounded_queue.hpp"
#include "app/frame_clock.hpp"
#include "app/frame_poses.hpp"
#include "app/interrupt_guard.hpp"
#include "app/progress_meter.hpp"
#include "app/render_jobs.hpp"
#include "core/stage_log.hpp"
#include "media/mp4_writer.hpp"
#include "media/png_sequence.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"

namespace rollspin::app {

namespace fs = std::filesystem;

namespace {

constexpr std::array<QualityPreset, 4> kQualityPresets{{
    {"low", 854, 480, 15},
    {"medium", 1280, 720, 30},
    {"high", 1920, 1080, 60},
    {"4k", 3840, 2160, 60},
}};

std::string lowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// render.format wins; otherwise the output's extension; otherwise MP4.
// An explicit format that contradicts the extension is an error.
scene::VideoFormat chooseFormat(const scene::SceneSpec& spec, const fs::path& output) {
  const std::string ext = lowercase(output.extension().string());
  const SourceLoc outputLoc{"-o " + output.string()};
  std::error_code ec;  // a path through a file is simply not a folder
  const bool isFolder = fs::is_directory(output, ec);
  const bool folderLike = !output.empty() && (!output.has_extension() || isFolder);
  if (spec.render.format) {
    const scene::VideoFormat f = *spec.render.format;
    if (f == scene::VideoFormat::Png && ext == ".mp4")
      throw badInput(spec.where("render.format"), "render.format = \"png\" writes a folder of frames, but -o names {}",
                     output.string());
    if (f == scene::VideoFormat::Mp4 && isFolder)
      throw badInput(outputLoc, "render.format = \"mp4\" needs a file name, but {} is a folder", output.string());
    return f;
  }
  if (output.empty() || ext == ".mp4") return scene::VideoFormat::Mp4;
  if (folderLike) return scene::VideoFormat::Png;
  if (ext == ".png")
    throw badInput(outputLoc, "an animation's PNG frames go to a folder (e.g. -o output/frames/); for one image pass --still");
  throw badInput(outputLoc, "unknown video format '{}': expected a .mp4 file, or a folder for PNG frames", ext);
}

// Frames travel to the encoder thread and come back here for reuse: a few
// buffers for the whole clip instead of a fresh allocation (and its page
// faults) per frame.
class ImagePool : public std::enable_shared_from_this<ImagePool> {
 public:
  std::shared_ptr<media::Image> acquire() {
    std::unique_ptr<media::Image> image;
    {
      std::lock_guard lock(mutex_);
      if (!free_.empty()) {
        image = std::move(free_.back());
        free_.pop_back();
      }
    }
    if (!image) image = std::make_unique<media::Image>();
    return {image.release(), [pool = shared_from_this()](media::Image* used) {
              std::lock_guard lock(pool->mutex_);
              pool->free_.emplace_back(used);
            }};
  }

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<media::Image>> free_;
};

}  // namespace

const QualityPreset* findQualityPreset(const std::string& name) {
  for (const auto& p : kQualityPresets)
    if (name == p.name) return &p;
  return nullptr;
}

AnimationResult renderAnimation(const AnimationOptions& o) {
  for (const auto& [flag, value] : {std::pair{"--width", o.width}, std::pair{"--height", o.height}})
    if (value && (*value < 1 || *value > 8192))
      throw badInput({flag}, "expected an image size in [1, 8192] pixels, got {}", *value);
  // Later overrides win: --set, then --quality, then --width/--height; all of
  // them validated by the scene loader like the file.
  std::vector<std::string> overrides = o.overrides;
  if (o.quality) {
    const QualityPreset* preset = findQualityPreset(*o.quality);
    if (preset == nullptr)
      throw badInput({"--quality " + *o.quality}, "expected low (854x480@15), medium (1280x720@30), "
                                                  "high (1920x1080@60) or 4k (3840x2160@60)");
    overrides.push_back(fmt::format("render.width={}", preset->width));
    overrides.push_back(fmt::format("render.height={}", preset->height));
    overrides.push_back(fmt::format("animation.fps={}", preset->fps));
  }
  if (o.width) overrides.push_back("render.width=" + std::to_string(*o.width));
  if (o.height) overrides.push_back("render.height=" + std::to_string(*o.height));
  if (o.transparent) overrides.push_back("render.transparent=true");
  const scene::SceneSpec spec = loadScene(o.scenePath, overrides);
  // Measured: a 1080p MP4 render peaks ~230 bytes per pixel above the still's
  // estimate (three queued RGBA frames, the yuv420p copy, x264's look-ahead).
  checkFrameMemory(spec, 256);
  const RollingModel model = buildSceneModel(spec);
  const FrameClock clock = clipClock(spec, model);
  const FrameRange range = o.frames ? parseFrameRange(*o.frames, clock.frameCount())
                                    : FrameRange{0, clock.frameCount() - 1};
  const scene::VideoFormat format = chooseFormat(spec, o.output);
  const int width = static_cast<int>(spec.render.width), height = static_cast<int>(spec.render.height);

  fs::path out = o.output;
  if (out.empty()) {
    // A part of a clip must not take the whole clip's name; PNG frames keep
    // their clip index, so parts share the clip's folder.
    const bool mp4 = format == scene::VideoFormat::Mp4;
    const std::string part = o.frames && mp4 ? fmt::format(".frames_{}-{}", range.first, range.last) : "";
    out = fs::path("output") / (spec.name + part + (mp4 ? ".mp4" : ""));
    std::error_code ec;
    fs::create_directories("output", ec);
  }

  // From here on a Ctrl-C only raises a flag: the loop below then finishes
  // what exists (nothing, if it comes during set-up) instead of leaving a
  // temporary file behind.
  InterruptGuard interrupts;
  std::unique_ptr<media::FrameSink> sink;
  if (format == scene::VideoFormat::Mp4) {
    if (spec.render.transparent)
      throw badInput(spec.where("render.transparent"),
                     "H.264 video has no alpha channel; use render.format = \"png\" for transparent frames");
    for (const auto& [key, value] : {std::pair{"render.width", width}, std::pair{"render.height", height}})
      if (value % 2 != 0)
        throw badInput(spec.where(key), "{}: H.264 in yuv420p needs an even size, got {} (use {} or {})", key, value,
                       value - 1, value + 1);
    media::Mp4Settings settings;
    settings.width = width;
    settings.height = height;
    settings.fpsNum = static_cast<int>(clock.fps().num);  // < 2³¹: checked by the scene loader
    settings.fpsDen = static_cast<int>(clock.fps().den);
    settings.crf = spec.animation.crf;
    settings.preset = spec.animation.preset;
    StageLog::instance().record("encoder");
    sink = std::make_unique<media::Mp4Writer>(out, settings);
  } else {
    StageLog::instance().record("png-frames");
    const bool wholeClip = range.first == 0 && range.last == clock.frameCount() - 1;
    sink = std::make_unique<media::PngSequenceWriter>(
        out, range.first, spec.render.transparent ? media::PngChannels::Rgba : media::PngChannels::Rgb,
        wholeClip ? media::PngSequenceScope::WholeClip : media::PngSequenceScope::Part);
  }

  const auto texture = spec.render.layout == scene::RenderLayout::Twin ? nullptr : loadBallTexture(spec);
  const SceneDrawer drawer(spec, model, texture, makeSceneFacts(spec, model));
  const auto context = render::createContext(contextRequest(spec));
  const render::ShaderLibrary shaders(o.shaderDir);
  render::Renderer renderer(*context, shaders);

  // Render here (the context is current on this thread), encode there.
  using Frame = std::shared_ptr<const media::Image>;
  BoundedQueue<Frame> queue(3);
  ProgressMeter progress(range.count(), o.quiet);
  std::exception_ptr encodeError;
  std::thread encoder([&] {
    pthread_setname_np(pthread_self(), "rollspin-encode");  // tells the stages apart in perf and top -H
    try {
      while (const auto frame = queue.pop()) {
        sink->write((*frame)->view());
        progress.frameDone();
      }
    } catch (...) {
      encodeError = std::current_exception();
      queue.abort();  // unblocks the renderer
    }
  });

  const auto pool = std::make_shared<ImagePool>();
  double poseWait = 0.0;
  try {
    // All poses from one forward march, a frame or two ahead of us.
    FramePoseStream poses(spec, model, clock, range);
    Frame previous;
    double previousS = std::nan("");
    std::size_t previousSegment = 0;
    std::optional<FrameOrientations> pose;
    for (long long k = range.first; k <= range.last; ++k) {
      if (InterruptGuard::received() != 0) break;
      const double s = clock.arcLength(k);
      const StoryPlace story = clock.place(k);
      // Held frames show the same pose: the same pixels, rendered once —
      // unless a storyboard's caption or camera changes meanwhile.
      const bool cameraMoving = story.segment > 0 && story.seconds < std::min(SceneDrawer::kCameraMove, story.duration);
      if (!previous || s != previousS || story.segment != previousSegment || cameraMoving) {
        if (!pose || s != previousS) {  // the stream has one pose per distinct arc length
          pose = poses.next();
          if (!pose || pose->current.s != s) throw std::logic_error("frame pose stream out of step with the clock");
        }
        pose->story = story;
        const std::shared_ptr<media::Image> image = pool->acquire();
        renderer.render(drawer.draw(*pose), *image);
        previous = image;
        previousS = s;
        previousSegment = story.segment;
      }
      if (!queue.push(previous)) break;  // the encoder failed
    }
    queue.close();
    poseWait = poses.waitSeconds();
  } catch (...) {
    queue.abort();
    encoder.join();
    progress.clear();
    throw;  // the sink's destructor removes its temporary file
  }
  encoder.join();
  progress.clear();
  if (encodeError) std::rethrow_exception(encodeError);
  if (StageLog::instance().echo())  // which stage sets the pace
    std::fprintf(stderr,
                 "rollspin: pipeline: %.2f s in all; the renderer waited %.2f s for poses and %.2f s on a full "
                 "encoder queue; the encoder waited %.2f s for frames\n",
                 progress.elapsedSeconds(), poseWait, queue.producerWaitSeconds(), queue.consumerWaitSeconds());

  AnimationResult result;
  result.framesRequested = range.count();
  result.interruptedBy = InterruptGuard::received();
  result.framesWritten = sink->framesWritten();
  const double seconds = progress.elapsedSeconds();
  if (result.interruptedBy != 0 && result.framesWritten < result.framesRequested) {
    result.written = sink->finishPartial();
    const char* name = result.interruptedBy == SIGINT ? "SIGINT" : "SIGTERM";
    if (result.written.empty())
      std::fprintf(stderr, "rollspin: interrupted (%s) before the first frame: nothing written\n", name);
    else if (format == scene::VideoFormat::Mp4)
      std::fprintf(stderr, "rollspin: interrupted (%s) after %lld of %lld frames: wrote a shorter, playable video %s\n",
                   name, result.framesWritten, result.framesRequested, result.written.string().c_str());
    else {
      std::error_code ec;
      const std::string untouched = fs::exists(out, ec) ? fmt::format("; {} is unchanged", out.string()) : "";
      std::fprintf(stderr, "rollspin: interrupted (%s) after %lld of %lld frames: %s holds complete frames %05lld to "
                           "%05lld only%s\n",
                   name, result.framesWritten, result.framesRequested, result.written.string().c_str(), range.first,
                   range.first + result.framesWritten - 1, untouched.c_str());
    }
    return result;
  }
  result.interruptedBy = 0;  // a signal after the last frame changes nothing
  result.written = sink->finish();
  if (!o.quiet)
    std::fprintf(stderr, "rollspin: wrote %s: %lld frames, %dx%d @ %s fps (%.2f s of video) in %.1f s (%.1f frames/s)\n",
                 result.written.string().c_str(), result.framesWritten, width, height, clock.fps().describe().c_str(),
                 double(result.framesWritten) / clock.fps().value(), seconds,
                 seconds > 0.0 ? double(result.framesWritten) / seconds : 0.0);
  return result;
}

}  // namespace rollspin::app
