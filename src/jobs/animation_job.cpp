#include "jobs/animation_job.hpp"
#include "jobs/viewer_job.hpp"

#include <fmt/format.h>
#include <pthread.h>

#include <array>
#include <cmath>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/bounded_queue.hpp"
#include "core/output_path.hpp"
#include "core/stage_log.hpp"
#include "core/temp_files.hpp"
#include "jobs/clip_captions.hpp"
#include "jobs/flag_overrides.hpp"
#include "jobs/interrupt_guard.hpp"
#include "jobs/job_setup.hpp"
#include "jobs/progress_meter.hpp"
#include "jobs/remembered_output.hpp"
#include "jobs/render_jobs.hpp"
#include "jobs/shard_range.hpp"
#include "media/container_tags.hpp"
#include "media/sink_factory.hpp"
#include "motion/frame_clock.hpp"
#include "motion/frame_poses.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_tables.hpp"
#include "scene/scene_writer.hpp"

namespace rollspin::jobs {

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

namespace {

// --quality NAME → the preset's keys, each remembering the flag that set it.
std::vector<FlagOverride> qualityFlags(const std::optional<std::string>& quality) {
  std::vector<FlagOverride> flags;
  if (!quality) return flags;
  const QualityPreset* preset = findQualityPreset(*quality);
  if (preset == nullptr)
    throw badInput({"--quality " + *quality},
                   "expected low (854x480@15), medium (1280x720@30), "
                   "high (1920x1080@60) or 4k (3840x2160@60)");
  const std::string flag = "--quality " + *quality;
  flags.push_back(flagOverride(flag, "render", scene::key::kWidth, (long long)preset->width, true));
  flags.push_back(flagOverride(flag, "render", scene::key::kHeight, (long long)preset->height, true));
  flags.push_back(flagOverride(flag, "animation", scene::key::kFps, (long long)preset->fps, true));
  return flags;
}

// Which frames this run renders and where they go: the whole clip, --frames
// A:B, or --shard K/N (a part that `rollspin join` makes whole).
struct ClipPart {
  FrameRange range;
  fs::path out;
  bool folder = false;  // PNG frames
};

ClipPart planClipPart(const DrawJob& job, const FrameClock& clock, const AnimationOptions& o) {
  const media::OutputFormat& format = *job.format;
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
  ClipPart part;
  part.range = o.frames ? parseFrameRange(*o.frames, clock.frameCount())
               : shard  ? shardFrames(*shard, clock.frameCount())
                        : FrameRange{0, clock.frameCount() - 1};
  part.folder = format.isFolder();
  part.out = o.output;
  if (part.out.empty()) {
    // A part of a clip must not take the whole clip's name; PNG frames keep
    // their clip index, so parts share the clip's folder.
    const std::string name =
        o.frames && !part.folder ? fmt::format(".frames_{}-{}", part.range.first, part.range.last) : "";
    part.out = defaultOutputFile(job.spec.name + name + format.defaultExtension());
  }
  // A shard of a video is a file of its own beside the clip's name, which
  // `rollspin join` makes whole; PNG frames keep their index in one folder.
  if (shard && !part.folder) part.out = shardPath(part.out, *shard);
  return part;
}

// The sink's settings: rate, the part's place in the clip, the tags `rollspin
// join` checks, the part's captions, and what the clip remembers.
media::SinkOptions clipSinkOptions(const DrawJob& job, const FrameClock& clock, const ClipPart& part,
                                   const media::SubtitleCues& cues, bool metadata) {
  const scene::SceneSpec& spec = job.spec;
  const FrameRange& range = part.range;
  media::SinkOptions sinkOpts = sinkOptions(spec, part.out);
  sinkOpts.fpsNum = static_cast<int>(clock.fps().num);  // < 2³¹: checked by the scene loader
  sinkOpts.fpsDen = static_cast<int>(clock.fps().den);
  sinkOpts.firstIndex = range.first;
  sinkOpts.wholeClip = range.first == 0 && range.last == clock.frameCount() - 1;
  sinkOpts.containerMetadata = media::containerMetadata(
      media::ContainerTags{media::sha256Hex(scene::writeScene(spec)), ROLLSPIN_VERSION,
                           fmt::format("{} preset={} crf={} {}{}x{} {}/{} fps", job.format->name, sinkOpts.preset,
                                       sinkOpts.crf ? fmt::format("{}", *sinkOpts.crf) : std::string("default"),
                                       sinkOpts.alpha ? "alpha " : "", spec.render.width, spec.render.height,
                                       sinkOpts.fpsNum, sinkOpts.fpsDen),
                           range.first, range.last, clock.frameCount()});
  // The captions as text: the part's own cues in its track, the whole
  // clip's in the sidecars; shown unasked when the pixels leave them out.
  sinkOpts.subtitles = media::cuesOfPart(cues, range.first, range.last);
  sinkOpts.subtitlesByDefault = !spec.render.burnCaptions;
  // What the clip remembers (remembered_output.hpp): tags in a container, comments in a GIF.
  if (metadata) {
    const std::optional<std::string> frames =
        sinkOpts.wholeClip ? std::nullopt : std::optional(fmt::format("{}:{}", range.first, range.last));
    sinkOpts.metadata =
        outputMetadata(spec, job.model, {JobRecord::Kind::Clip, spec.name, std::nullopt, frames, false});
    for (auto& tag : metadataTags(*sinkOpts.metadata)) sinkOpts.containerMetadata.push_back(std::move(tag));
  }
  return sinkOpts;
}

using Frame = std::shared_ptr<const media::Image>;

// Frames of one part, rendered on this thread (the GL context is current
// here): poses from one forward march; frame k is rendered and delivered when
// wanted(k). Held frames show the same pose: the same pixels, rendered once —
// unless a storyboard's caption or camera changes meanwhile. A pass stops
// early when deliver refuses or on a signal.
class FrameRenderer {
 public:
  FrameRenderer(const DrawJob& job, const FrameClock& clock, FrameRange range, const SceneDrawer& drawer,
                render::Renderer& renderer, const std::function<void(long long done, long long total)>& onFrame)
      : job_(job), clock_(clock), range_(range), drawer_(drawer), renderer_(renderer), onFrame_(onFrame) {}

  void setTotal(long long framesTotal) { framesTotal_ = framesTotal; }
  [[nodiscard]] double poseWaitSeconds() const { return poseWait_; }

  template <class Wanted, class Deliver>
  void pass(const Wanted& wanted, const Deliver& deliver) {
    FramePoseStream poses(job_.spec, job_.model, clock_, range_);
    Frame previous;
    double previousS = std::nan(""), poseS = std::nan("");
    std::size_t previousSegment = 0;
    bool previousMoving = false;
    std::optional<FrameOrientations> pose;
    for (long long k = range_.first; k <= range_.last; ++k) {
      if (InterruptGuard::received() != 0) break;
      const double s = clock_.arcLength(k);
      const StoryPlace story = clock_.place(k);
      if (!pose || s != poseS) {  // the stream has one pose per distinct arc length
        pose = poses.next();
        if (!pose || pose->current.s != s) throw std::logic_error("frame pose stream out of step with the clock");
        poseS = s;
      }
      if (!wanted(k)) {
        previous.reset();
        continue;
      }
      const bool cameraMoving = drawer_.cameraMoving(story);
      // An image drawn mid-move shows the camera short of where it stops: the
      // first frame after the move is drawn again, as a part starting there is.
      pose->story = story;
      const std::optional<SceneDrawer::Fade> fade = drawer_.fadeAt(*pose);
      if (!previous || s != previousS || story.segment != previousSegment || cameraMoving || previousMoving || fade) {
        previous = draw(*pose, fade);
        previousS = s;
        previousSegment = story.segment;
      }
      previousMoving = cameraMoving;
      if (!deliver(previous)) break;
      if (onFrame_) onFrame_(++framesHanded_, framesTotal_);
    }
    poseWait_ += poses.waitSeconds();
  }

 private:
  Frame draw(const FrameOrientations& pose, const std::optional<SceneDrawer::Fade>& fade) {
    const std::shared_ptr<PooledImage> pooled = pool_->acquire();
    renderer_.render(drawer_.draw(pose), pooled->image, pooled->history);
    // A cross-fade to a new surface's view: the previous surface's picture over it, fading out.
    if (fade) media::crossFade(pooled->image, renderer_.render(fade->from), fade->weight);
    return Frame(pooled, &pooled->image);  // shares the pooled image's life
  }

  const DrawJob& job_;
  const FrameClock& clock_;
  FrameRange range_;
  const SceneDrawer& drawer_;
  render::Renderer& renderer_;
  const std::function<void(long long, long long)>& onFrame_;
  std::shared_ptr<ImagePool> pool_ = std::make_shared<ImagePool>();
  double poseWait_ = 0.0;
  long long framesHanded_ = 0, framesTotal_ = 0;
};

// Renders the part into the sink: a preview pass first where the sink needs
// to see the clip (a GIF's palette), then render here, encode on a second
// thread, with a small queue between them. Returns the queue's wait times.
struct PipelineWaits {
  double renderer = 0.0, encoder = 0.0;
};

PipelineWaits renderIntoSink(FrameRenderer& frames, media::FrameSink& sink, const FrameRange& range,
                             const std::vector<long long>& previewFrames, ProgressMeter& progress) {
  if (!previewFrames.empty()) {
    std::size_t next = 0;
    frames.pass([&](long long k) { return next < previewFrames.size() && k - range.first == previewFrames[next]; },
                [&](const Frame& frame) {
                  sink.preview(frame->view());
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
        sink.write((*frame)->view());
        progress.frameDone();
      }
    } catch (...) {
      encodeError = std::current_exception();
      queue.abort();  // unblocks the renderer
    }
  });
  try {
    frames.pass([](long long) { return true; }, [&](const Frame& frame) { return queue.push(frame); });
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
  return {queue.producerWaitSeconds(), queue.consumerWaitSeconds()};
}

// --verbose: which stage set the pace, and how many frames the retained
// layers spared.
void printPipelineStats(double seconds, double poseWait, const PipelineWaits& waits, const media::FrameSink& sink,
                        const render::RenderStats& st) {
  if (!StageLog::instance().echo()) return;
  std::fprintf(stderr,
               "rollspin: pipeline: %.2f s in all; the renderer waited %.2f s for poses and %.2f s on a full "
               "encoder queue; the encoder waited %.2f s for frames\n",
               seconds, poseWait, waits.renderer, waits.encoder);
  if (const std::string line = sink.verboseSummary(); !line.empty())
    std::fprintf(stderr, "rollspin: encoder: %s\n", line.c_str());
  auto percent = [](long long part, long long whole) { return whole > 0 ? 100.0 * double(part) / double(whole) : 0.0; };
  std::fprintf(stderr,
               "rollspin: renderer: %lld frames drawn whole, %lld over a retained layer (%lld layers built, "
               "%lld updated in place, %lld views drawn whole beside one, %.1f %% of their pixels redrawn; "
               "there, meshes drew %.1f %% of their triangles and lines %.1f %% of their segments)\n",
               st.wholeFrames, st.retainedFrames, st.layerBuilds, st.layerUpdates, st.freshViews,
               percent(st.redrawnPixels, st.retainedPixels), percent(st.meshIndicesDrawn, st.meshIndicesInRects),
               percent(st.lineSegmentsDrawn, st.lineSegmentsInRects));
}

// A signal before the last frame: the sink keeps what it has (a shorter,
// playable video; complete PNG frames) under a name that says so, or nothing.
void finishInterrupted(media::FrameSink& sink, const ClipPart& part, AnimationResult& result) {
  result.written = sink.finishPartial();
  const std::string signal = signalName(result.interruptedBy);
  const char* name = signal.c_str();
  if (result.written.empty()) {
    std::fprintf(stderr, "rollspin: interrupted (%s) before the first frame: nothing written\n", name);
  } else if (!part.folder) {
    std::fprintf(stderr, "rollspin: interrupted (%s) after %lld of %lld frames: wrote a shorter, playable video %s\n",
                 name, result.framesWritten, result.framesRequested, result.written.string().c_str());
  } else {
    std::error_code ec;
    const std::string untouched = fs::exists(part.out, ec) ? fmt::format("; {} is unchanged", part.out.string()) : "";
    std::fprintf(stderr,
                 "rollspin: interrupted (%s) after %lld of %lld frames: %s holds complete frames %05lld to "
                 "%05lld only%s\n",
                 name, result.framesWritten, result.framesRequested, result.written.string().c_str(), part.range.first,
                 part.range.first + result.framesWritten - 1, untouched.c_str());
  }
}

}  // namespace

AnimationResult renderAnimation(const AnimationOptions& o) {
  // Measured: a 1080p MP4 render peaks ~235 bytes per pixel above the still's
  // estimate (three queued RGBA frames, the yuv420p frame and the converter's
  // copy of the last RGBA frame, x264's look-ahead).
  const DrawJob job =
      prepareDrawJob({o.scenePath, o.overrides, qualityFlags(o.quality), o.width, o.height, o.transparent, o.output,
                      media::OutputUse::Animation, 256, o.sceneText, o.sceneName});
  const scene::SceneSpec& spec = job.spec;
  if (job.format->kind == media::OutputKind::Viewer) return writeViewerOutput(job, o);
  const FrameClock clock = clipClock(spec, job.model);
  const ClipPart part = planClipPart(job, clock, o);

  // From here on a Ctrl-C only raises a flag: the render then finishes
  // what exists (nothing, if it comes during set-up) instead of leaving a
  // temporary file behind.
  InterruptGuard interrupts;
  const media::SubtitleCues cues = clipCaptionCues(spec, clock);
  const media::SinkOptions sinkOpts = clipSinkOptions(job, clock, part, cues, o.metadata);
  // The drawer first: it loads the texture, the last input to check; then
  // output/ (when no -o names a place) and the sink, the first writes.
  const std::unique_ptr<SceneDrawer> drawer = makeDrawer(job);
  // A view the scene's own camera keys force, that hides the ball: say where.
  for (const std::string& line : drawer->cameraWarnings()) fmt::print(stderr, "{}\n", line);
  StageLog::instance().record(part.folder ? "png-frames" : "encoder");
  if (o.output.empty()) createOutputParent(part.out);
  const std::unique_ptr<media::FrameSink> sink = media::openSink(*job.format, sinkOpts);
  GlRenderer gl(spec, o.shaderDir);

  FrameRenderer frames(job, clock, part.range, *drawer, gl.renderer, o.onFrame);
  const std::vector<long long> previewFrames = sink->previewFrames(part.range.count());
  const long long framesTotal = part.range.count() + static_cast<long long>(previewFrames.size());
  frames.setTotal(framesTotal);
  ProgressMeter progress(framesTotal, o.quiet);
  const PipelineWaits waits = renderIntoSink(frames, *sink, part.range, previewFrames, progress);
  printPipelineStats(progress.elapsedSeconds(), frames.poseWaitSeconds(), waits, *sink, gl.renderer.stats());

  AnimationResult result;
  result.framesRequested = part.range.count();
  result.interruptedBy = InterruptGuard::received();
  result.framesWritten = sink->framesWritten();
  const double seconds = progress.elapsedSeconds();
  if (result.interruptedBy != 0 && result.framesWritten < result.framesRequested) {
    finishInterrupted(*sink, part, result);
    return result;
  }
  result.interruptedBy = 0;  // a signal after the last frame changes nothing
  // Written before the video is finished, renamed into place after it: a
  // failure on either way leaves neither.
  std::optional<media::SubtitleSidecars> sidecars;
  if (sinkOpts.wholeClip && sink->carriesSubtitles())
    sidecars.emplace(part.out, o.sidecars, cues, sinkOpts.fpsNum, sinkOpts.fpsDen);
  result.written = sink->finish();
  if (sidecars) sidecars->commit();
  if (!o.quiet)
    std::fprintf(stderr,
                 "rollspin: wrote %s: %lld frames, %dx%d @ %s fps (%.2f s of video) in %.1f s (%.1f frames/s)\n",
                 result.written.string().c_str(), result.framesWritten, int(spec.render.width), int(spec.render.height),
                 clock.fps().describe().c_str(), double(result.framesWritten) / clock.fps().value(), seconds,
                 seconds > 0.0 ? double(result.framesWritten) / seconds : 0.0);
  return result;
}

}  // namespace rollspin::jobs
