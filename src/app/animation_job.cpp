#include "app/animation_job.hpp"
#include "app/viewer_job.hpp"

#include <fmt/format.h>
#include <pthread.h>

#include <array>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "app/clip_captions.hpp"
#include "app/flag_overrides.hpp"
#include "app/interrupt_guard.hpp"
#include "app/job_setup.hpp"
#include "app/progress_meter.hpp"
#include "app/remembered_output.hpp"
#include "app/render_jobs.hpp"
#include "app/shard_range.hpp"
#include "core/bounded_queue.hpp"
#include "core/output_path.hpp"
#include "core/stage_log.hpp"
#include "core/temp_files.hpp"
#include "media/container_tags.hpp"
#include "media/sink_factory.hpp"
#include "motion/frame_clock.hpp"
#include "motion/frame_poses.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_tables.hpp"
#include "scene/scene_writer.hpp"

namespace rollspin::app {

using namespace rollspin::model;
using namespace rollspin::motion;
using namespace rollspin::draw;

namespace fs = std::filesystem;

namespace {

constexpr std::array<QualityPreset, 4> kQualityPresets{{
    {"low", 854, 480, 15},
    {"medium", 1280, 720, 30},
    {"high", 1920, 1080, 60},
    {"4k", 3840, 2160, 60},
}};

// An image only the renderer writes (the encoder reads it through a const
// pointer), with what the renderer last wrote into it: a frame over the
// retained layer then puts back only what differs from the layer.
struct PooledImage {
  media::Image image;
  render::ImageHistory history;
};

// Frames travel to the encoder thread and come back here for reuse: a few
// buffers for the whole clip instead of a fresh allocation (and its page
// faults) per frame.
class ImagePool : public std::enable_shared_from_this<ImagePool> {
 public:
  std::shared_ptr<PooledImage> acquire() {
    std::unique_ptr<PooledImage> image;
    {
      std::lock_guard lock(mutex_);
      if (!free_.empty()) {
        image = std::move(free_.back());
        free_.pop_back();
      }
    }
    if (!image) image = std::make_unique<PooledImage>();
    return {image.release(), [pool = shared_from_this()](PooledImage* used) {
              std::lock_guard lock(pool->mutex_);
              pool->free_.emplace_back(used);
            }};
  }

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<PooledImage>> free_;
};

// The web viewer (the "html" row): one page, no frames (viewer_job.hpp).
AnimationResult writeViewerOutput(const DrawJob& job, const AnimationOptions& o) {
  if (o.frames || o.shard)
    throw badInput({o.frames ? "--frames " + *o.frames : "--shard " + *o.shard},
                   "applies to clips, not to the web viewer (html), which holds the whole path");
  fs::path out = o.output;
  if (out.empty()) {
    out = fs::path("output") / (job.spec.name + job.format->defaultExtension());
    std::error_code ec;
    fs::create_directories("output", ec);
  }
  writeViewerHtml(job, o.scenePath, out);
  if (!o.quiet) std::fprintf(stderr, "rollspin: wrote %s\n", out.string().c_str());
  return {out, 0, 0, 0};
}

}  // namespace

const QualityPreset* findQualityPreset(const std::string& name) {
  for (const auto& p : kQualityPresets)
    if (name == p.name) return &p;
  return nullptr;
}

AnimationResult renderAnimation(const AnimationOptions& o) {
  std::vector<FlagOverride> presetFlags;
  if (o.quality) {
    const QualityPreset* preset = findQualityPreset(*o.quality);
    if (preset == nullptr)
      throw badInput({"--quality " + *o.quality}, "expected low (854x480@15), medium (1280x720@30), "
                                                  "high (1920x1080@60) or 4k (3840x2160@60)");
    const std::string flag = "--quality " + *o.quality;
    presetFlags.push_back(flagOverride(flag, "render", scene::key::kWidth, (long long)preset->width, true));
    presetFlags.push_back(flagOverride(flag, "render", scene::key::kHeight, (long long)preset->height, true));
    presetFlags.push_back(flagOverride(flag, "animation", scene::key::kFps, (long long)preset->fps, true));
  }
  // Measured: a 1080p MP4 render peaks ~235 bytes per pixel above the still's
  // estimate (three queued RGBA frames, the yuv420p frame and the converter's
  // copy of the last RGBA frame, x264's look-ahead).
  const DrawJob job = prepareDrawJob({o.scenePath, o.overrides, presetFlags, o.width, o.height, o.transparent,
                                      o.output, media::OutputUse::Animation, 256, o.sceneText, o.sceneName});
  const scene::SceneSpec& spec = job.spec;
  const media::OutputFormat& format = *job.format;
  const RollingModel& model = job.model;
  if (format.kind == media::OutputKind::Viewer) return writeViewerOutput(job, o);
  const FrameClock clock = clipClock(spec, model);
  if (o.frames && o.shard) throw badInput({"--shard " + *o.shard}, "give --frames or --shard, not both");
  const std::optional<Shard> shard = o.shard ? std::optional(parseShard(*o.shard)) : std::nullopt;
  // Refused before any frame is rendered: parts that `join` would refuse
  // afterwards are hours of work for nothing.
  if (shard && !format.shards) {
    std::string joinable;  // from the format table: ".mp4, .webm, .mov"
    for (const media::OutputFormat& f : media::kOutputFormats)
      if (f.shards && f.kind == media::OutputKind::Video)
        joinable += (joinable.empty() ? "" : ", ") + f.defaultExtension();
    throw badInput({"--shard " + *o.shard},
                   "{} parts cannot be joined ({} files carry no part tags and each has its own palette); render "
                   "the shards as {} and join those, or as PNG frames into one folder, or render the {} whole "
                   "without --shard",
                   format.name, format.name, joinable, format.name);
  }
  const FrameRange range = o.frames  ? parseFrameRange(*o.frames, clock.frameCount())
                           : shard ? shardFrames(*shard, clock.frameCount())
                                   : FrameRange{0, clock.frameCount() - 1};
  const int width = static_cast<int>(spec.render.width), height = static_cast<int>(spec.render.height);
  const bool folder = format.isFolder();

  fs::path out = o.output;
  if (out.empty()) {
    // A part of a clip must not take the whole clip's name; PNG frames keep
    // their clip index, so parts share the clip's folder.
    const std::string part = o.frames && !folder ? fmt::format(".frames_{}-{}", range.first, range.last) : "";
    out = defaultOutputFile(spec.name + part + format.defaultExtension());
  }
  // A shard of a video is a file of its own beside the clip's name, which
  // `rollspin join` makes whole; PNG frames keep their index in one folder.
  if (shard && !folder) out = shardPath(out, *shard);

  // From here on a Ctrl-C only raises a flag: the loop below then finishes
  // what exists (nothing, if it comes during set-up) instead of leaving a
  // temporary file behind.
  InterruptGuard interrupts;
  media::SinkOptions sinkOpts = sinkOptions(spec, out);
  sinkOpts.fpsNum = static_cast<int>(clock.fps().num);  // < 2³¹: checked by the scene loader
  sinkOpts.fpsDen = static_cast<int>(clock.fps().den);
  sinkOpts.firstIndex = range.first;
  sinkOpts.wholeClip = range.first == 0 && range.last == clock.frameCount() - 1;
  // What `rollspin join` checks before it puts parts together.
  sinkOpts.containerMetadata = media::containerMetadata(media::ContainerTags{
      media::sha256Hex(scene::writeScene(spec)), ROLLSPIN_VERSION,
      fmt::format("{} preset={} crf={} {}{}x{} {}/{} fps", format.name, sinkOpts.preset,
                  sinkOpts.crf ? fmt::format("{}", *sinkOpts.crf) : std::string("default"),
                  sinkOpts.alpha ? "alpha " : "", width, height, sinkOpts.fpsNum, sinkOpts.fpsDen),
      range.first, range.last, clock.frameCount()});
  // The captions as text: the part's own cues in its track, the whole
  // clip's in the sidecars; shown unasked when the pixels leave them out.
  const media::SubtitleCues cues = clipCaptionCues(spec, clock);
  sinkOpts.subtitles = media::cuesOfPart(cues, range.first, range.last);
  sinkOpts.subtitlesByDefault = !spec.render.burnCaptions;
  // What the clip remembers (remembered_output.hpp): tags in a container, comments in a GIF.
  if (o.metadata) {
    const bool whole = range.first == 0 && range.last == clock.frameCount() - 1;
    sinkOpts.metadata = outputMetadata(spec, model, {JobRecord::Kind::Clip, spec.name, std::nullopt,
                                                     whole ? std::nullopt
                                                           : std::optional(fmt::format("{}:{}", range.first, range.last)),
                                                     false});
    for (auto& tag : metadataTags(*sinkOpts.metadata)) sinkOpts.containerMetadata.push_back(std::move(tag));
  }
  // The drawer first: it loads the texture, the last input to check; then
  // output/ (when no -o names a place) and the sink, the first writes.
  const std::unique_ptr<SceneDrawer> drawerOwner = makeDrawer(job);
  const SceneDrawer& drawer = *drawerOwner;
  // A view the scene's own camera keys force, that hides the ball: say where.
  for (const std::string& line : drawer.cameraWarnings()) fmt::print(stderr, "{}\n", line);
  StageLog::instance().record(folder ? "png-frames" : "encoder");
  if (o.output.empty()) createOutputParent(out);
  const std::unique_ptr<media::FrameSink> sink = media::openSink(format, sinkOpts);
  GlRenderer gl(spec, o.shaderDir);
  render::Renderer& renderer = gl.renderer;

  // Render here (the context is current on this thread), encode there.
  using Frame = std::shared_ptr<const media::Image>;
  const auto pool = std::make_shared<ImagePool>();
  double poseWait = 0.0;
  long long framesHanded = 0, framesTotal = 0;  // for o.onFrame
  // One pass over the range: poses from one forward march; frame k is
  // rendered and delivered when wanted(k). Held frames show the same pose:
  // the same pixels, rendered once — unless a storyboard's caption or camera
  // changes meanwhile. Stops early when deliver refuses or on a signal.
  const auto renderPass = [&](const auto& wanted, const auto& deliver) {
    FramePoseStream poses(spec, model, clock, range);
    Frame previous;
    double previousS = std::nan(""), poseS = std::nan("");
    std::size_t previousSegment = 0;
    bool previousMoving = false;
    std::optional<FrameOrientations> pose;
    for (long long k = range.first; k <= range.last; ++k) {
      if (InterruptGuard::received() != 0) break;
      const double s = clock.arcLength(k);
      const StoryPlace story = clock.place(k);
      if (!pose || s != poseS) {  // the stream has one pose per distinct arc length
        pose = poses.next();
        if (!pose || pose->current.s != s) throw std::logic_error("frame pose stream out of step with the clock");
        poseS = s;
      }
      if (!wanted(k)) {
        previous.reset();
        continue;
      }
      const bool cameraMoving = drawer.cameraMoving(story);
      // An image drawn mid-move shows the camera short of where it stops: the
      // first frame after the move is drawn again, as a part starting there is.
      pose->story = story;
      const std::optional<SceneDrawer::Fade> fade = drawer.fadeAt(*pose);
      if (!previous || s != previousS || story.segment != previousSegment || cameraMoving || previousMoving || fade) {
        const std::shared_ptr<PooledImage> pooled = pool->acquire();
        renderer.render(drawer.draw(*pose), pooled->image, pooled->history);
        // A cross-fade to a new surface's view: the previous surface's picture over it, fading out.
        if (fade) media::crossFade(pooled->image, renderer.render(fade->from), fade->weight);
        previous = Frame(pooled, &pooled->image);  // shares the pooled image's life
        previousS = s;
        previousSegment = story.segment;
      }
      previousMoving = cameraMoving;
      if (!deliver(previous)) break;
      if (o.onFrame) o.onFrame(++framesHanded, framesTotal);
    }
    poseWait += poses.waitSeconds();
  };

  // A sink that needs to see the clip first (a GIF's palette) gets its
  // frames in a first pass, here on this thread.
  const std::vector<long long> previewFrames = sink->previewFrames(range.count());
  framesTotal = range.count() + static_cast<long long>(previewFrames.size());
  ProgressMeter progress(framesTotal, o.quiet);
  if (!previewFrames.empty()) {
    std::size_t next = 0;
    renderPass([&](long long k) { return next < previewFrames.size() && k - range.first == previewFrames[next]; },
               [&](const Frame& frame) {
                 sink->preview(frame->view());
                 progress.frameDone();
                 ++next;
                 return true;
               });
  }

  BoundedQueue<Frame> queue(3);
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

  try {
    renderPass([](long long) { return true; }, [&](const Frame& frame) { return queue.push(frame); });
    queue.close();
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
  if (const std::string line = sink->verboseSummary(); StageLog::instance().echo() && !line.empty())
    std::fprintf(stderr, "rollspin: encoder: %s\n", line.c_str());
  if (StageLog::instance().echo()) {  // how many frames the retained layers spared
    const render::RenderStats& st = renderer.stats();
    auto percent = [](long long part, long long whole) { return whole > 0 ? 100.0 * double(part) / double(whole) : 0.0; };
    std::fprintf(stderr,
                 "rollspin: renderer: %lld frames drawn whole, %lld over a retained layer (%lld layers built, "
                 "%lld updated in place, %lld views drawn whole beside one, %.1f %% of their pixels redrawn; "
                 "there, meshes drew %.1f %% of their triangles and lines %.1f %% of their segments)\n",
                 st.wholeFrames, st.retainedFrames, st.layerBuilds, st.layerUpdates, st.freshViews,
                 percent(st.redrawnPixels, st.retainedPixels), percent(st.meshIndicesDrawn, st.meshIndicesInRects),
                 percent(st.lineSegmentsDrawn, st.lineSegmentsInRects));
  }

  AnimationResult result;
  result.framesRequested = range.count();
  result.interruptedBy = InterruptGuard::received();
  result.framesWritten = sink->framesWritten();
  const double seconds = progress.elapsedSeconds();
  if (result.interruptedBy != 0 && result.framesWritten < result.framesRequested) {
    result.written = sink->finishPartial();
    const std::string signal = signalName(result.interruptedBy);
    const char* name = signal.c_str();
    if (result.written.empty())
      std::fprintf(stderr, "rollspin: interrupted (%s) before the first frame: nothing written\n", name);
    else if (!folder)
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
  // Written before the video is finished, renamed into place after it: a
  // failure on either way leaves neither.
  std::optional<media::SubtitleSidecars> sidecars;
  if (sinkOpts.wholeClip && sink->carriesSubtitles())
    sidecars.emplace(out, o.sidecars, cues, sinkOpts.fpsNum, sinkOpts.fpsDen);
  result.written = sink->finish();
  if (sidecars) sidecars->commit();
  if (!o.quiet)
    std::fprintf(stderr, "rollspin: wrote %s: %lld frames, %dx%d @ %s fps (%.2f s of video) in %.1f s (%.1f frames/s)\n",
                 result.written.string().c_str(), result.framesWritten, width, height, clock.fps().describe().c_str(),
                 double(result.framesWritten) / clock.fps().value(), seconds,
                 seconds > 0.0 ? double(result.framesWritten) / seconds : 0.0);
  return result;
}

}  // namespace rollspin::app
