#include "media/gif_writer.hpp"

#include "media/av_library.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "media/sink_factory.hpp"

#include "media/av_support.hpp"

namespace rollspin::media {

namespace {

VideoSettings gifVideoSettings(const GifSettings& s) {
  VideoSettings v;
  v.width = s.width;
  v.height = s.height;
  v.fpsNum = s.fpsNum;
  v.fpsDen = s.fpsDen;
  v.container = "gif";
  v.encoder = "gif";
  v.pixelFormat = "pal8";
  v.evenSize = false;
  v.yuvBt709 = false;  // RGB palette entries: no matrix, no tags
  // The GIF muxer's loop: 0 = forever, -1 = play once.
  v.muxerOptions = {{"loop", s.loop ? "0" : "-1"}};
  v.describe = fmt::format("GIF {}", s.loop ? "looping" : "playing once");
  return v;
}

struct GraphDeleter {
  void operator()(AVFilterGraph* g) const { avfilter_graph_free(&g); }
};
struct FrameDeleter {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
using GraphPtr = std::unique_ptr<AVFilterGraph, GraphDeleter>;
using FramePtr = std::unique_ptr<AVFrame, FrameDeleter>;

}  // namespace

struct GifWriter::Graphs {
  GifSettings settings;
  std::filesystem::path file;
  // Pass 1: frames → palettegen → the palette (one 16×16 frame).
  GraphPtr paletteGraph;
  AVFilterContext* paletteIn = nullptr;
  AVFilterContext* paletteOut = nullptr;
  long long previewed = 0;
  // Pass 2: frames + the palette → paletteuse → pal8 frames.
  GraphPtr useGraph;
  AVFilterContext* frameIn = nullptr;
  AVFilterContext* frameOut = nullptr;
  FramePtr rgba{av_frame_alloc()};
  FramePtr converted{av_frame_alloc()};
  long long sent = 0;
  bool flushed = false;

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw runtimeError(SourceLoc{file.string()}, "{}: {}", what, av::errorText(code));
  }
  void check(int code, const std::string& what) const {
    if (code < 0) fail(what, code);
  }

  AVFilterContext* addFilter(AVFilterGraph* graph, const char* filter, const char* name, const std::string& args) {
    AVFilterContext* context = nullptr;
    const AVFilter* f = avfilter_get_by_name(filter);
    if (f == nullptr) throw runtimeError(SourceLoc{file.string()}, "libavfilter has no '{}' filter", filter);
    check(avfilter_graph_create_filter(&context, f, name, args.empty() ? nullptr : args.c_str(), nullptr, graph),
          fmt::format("setting up {}={}", filter, args));
    return context;
  }

  std::string bufferArgs(int width, int height, int pixelFormat) const {
    return fmt::format("video_size={}x{}:pix_fmt={}:time_base={}/{}:pixel_aspect=1/1", width, height, pixelFormat,
                       settings.fpsDen, settings.fpsNum);
  }

  void openPaletteGraph() {
    paletteGraph.reset(avfilter_graph_alloc());
    if (!paletteGraph) throw runtimeError(SourceLoc{file.string()}, "out of memory");
    paletteIn =
        addFilter(paletteGraph.get(), "buffer", "frames", bufferArgs(settings.width, settings.height, AV_PIX_FMT_RGBA));
    // stats_mode=full: every pixel of every shown frame counts, so large
    // still areas (the backdrop) get their share of the 256 colours. With
    // alpha, one entry is kept for "transparent".
    AVFilterContext* gen =
        addFilter(paletteGraph.get(), "palettegen", "palettegen",
                  fmt::format("max_colors=256:stats_mode=full:reserve_transparent={}", settings.alpha ? 1 : 0));
    paletteOut = addFilter(paletteGraph.get(), "buffersink", "palette", "");
    check(avfilter_link(paletteIn, 0, gen, 0), "linking palettegen");
    check(avfilter_link(gen, 0, paletteOut, 0), "linking palettegen");
    check(avfilter_graph_config(paletteGraph.get(), nullptr), "configuring palettegen");
  }

  // The preview frames are in; take the palette and build pass 2.
  void openUseGraph() {
    check(av_buffersrc_add_frame(paletteIn, nullptr), "finishing the palette");
    FramePtr palette{av_frame_alloc()};
    check(av_buffersink_get_frame(paletteOut, palette.get()), "taking the palette from palettegen");
    paletteGraph.reset();

    useGraph.reset(avfilter_graph_alloc());
    if (!useGraph) throw runtimeError(SourceLoc{file.string()}, "out of memory");
    frameIn =
        addFilter(useGraph.get(), "buffer", "frames", bufferArgs(settings.width, settings.height, AV_PIX_FMT_RGBA));
    AVFilterContext* paletteSource =
        addFilter(useGraph.get(), "buffer", "palette", bufferArgs(palette->width, palette->height, palette->format));
    // Bayer (ordered) dithering: no banding in the gradient, and unlike
    // error diffusion it does not crawl between frames; diff_mode=rectangle
    // re-dithers only what changed, so the still parts stay identical.
    AVFilterContext* use = addFilter(useGraph.get(), "paletteuse", "paletteuse",
                                     "dither=bayer:bayer_scale=3:diff_mode=rectangle:alpha_threshold=128");
    frameOut = addFilter(useGraph.get(), "buffersink", "gif", "");
    check(avfilter_link(frameIn, 0, use, 0), "linking paletteuse");
    check(avfilter_link(paletteSource, 0, use, 1), "linking paletteuse");
    check(avfilter_link(use, 0, frameOut, 0), "linking paletteuse");
    check(avfilter_graph_config(useGraph.get(), nullptr), "configuring paletteuse");
    palette->pts = 0;
    check(av_buffersrc_add_frame(paletteSource, palette.get()), "handing over the palette");
    check(av_buffersrc_add_frame(paletteSource, nullptr), "handing over the palette");
  }

  // Copies an RGBA view (any row order) into a frame the graph can keep.
  AVFrame* rgbaFrame(const ImageView& image, long long pts) {
    if (image.width != settings.width || image.height != settings.height)
      throw runtimeError(SourceLoc{file.string()}, "frame of {}x{} for a {}x{} GIF", image.width, image.height,
                         settings.width, settings.height);
    av_frame_unref(rgba.get());
    rgba->format = AV_PIX_FMT_RGBA;
    rgba->width = image.width;
    rgba->height = image.height;
    check(av_frame_get_buffer(rgba.get(), 0), "allocating a frame");
    for (int y = 0; y < image.height; ++y)
      std::memcpy(rgba->data[0] + static_cast<std::ptrdiff_t>(y) * rgba->linesize[0], image.rowFromTop(y),
                  static_cast<std::size_t>(image.width) * 4);
    rgba->pts = pts;
    return rgba.get();
  }
};

GifWriter::GifWriter(std::filesystem::path finalPath, const GifSettings& settings)
    : VideoWriter(finalPath, gifVideoSettings(settings)), graphs_(std::make_unique<Graphs>()) {
  graphs_->settings = settings;
  graphs_->file = std::move(finalPath);
  graphs_->openPaletteGraph();
}

GifWriter::~GifWriter() = default;

std::vector<long long> GifWriter::previewFrames(long long count) const {
  std::vector<long long> frames;
  if (count <= 0) return frames;
  const long long n = std::min(count, kPaletteFrames);
  for (long long i = 0; i < n; ++i)
    frames.push_back(n == 1 ? 0 : std::llround(double(i) * double(count - 1) / double(n - 1)));
  return frames;
}

void GifWriter::preview(const ImageView& frame) {
  Graphs& g = *graphs_;
  if (!g.paletteGraph) throw runtimeError(SourceLoc{g.file.string()}, "a GIF's palette frames come before its frames");
  g.check(av_buffersrc_add_frame_flags(g.paletteIn, g.rgbaFrame(frame, g.previewed), AV_BUFFERSRC_FLAG_KEEP_REF),
          "collecting the palette");
  ++g.previewed;
}

void GifWriter::write(const ImageView& frame) {
  Graphs& g = *graphs_;
  if (!g.useGraph) {
    // Nothing previewed (a caller that skips the first pass): the palette
    // comes from this first frame alone.
    if (g.previewed == 0) preview(frame);
    g.openUseGraph();
  }
  g.check(av_buffersrc_add_frame_flags(g.frameIn, g.rgbaFrame(frame, g.sent), AV_BUFFERSRC_FLAG_KEEP_REF),
          "dithering a frame");
  ++g.sent;
  while (true) {
    const int ret = av_buffersink_get_frame(g.frameOut, g.converted.get());
    if (ret == AVERROR(EAGAIN) || ret == AVERROR_EOF) break;
    g.check(ret, "dithering a frame");
    writeConverted(g.converted.get());
    av_frame_unref(g.converted.get());
  }
}

namespace {
// Drains what paletteuse still holds once its input has ended.
template <typename Write>
void drain(AVFilterContext* in, AVFilterContext* out, AVFrame* frame, Write write) {
  if (av_buffersrc_add_frame(in, nullptr) < 0) return;
  while (av_buffersink_get_frame(out, frame) >= 0) {
    write(frame);
    av_frame_unref(frame);
  }
}
}  // namespace

std::filesystem::path GifWriter::finish() {
  Graphs& g = *graphs_;
  if (g.useGraph && !g.flushed) {
    g.flushed = true;
    drain(g.frameIn, g.frameOut, g.converted.get(), [this](AVFrame* f) { writeConverted(f); });
  }
  const std::filesystem::path written = VideoWriter::finish();
  // The muxer writes no comments: they go in before the trailer, and the
  // file is replaced whole (a temporary, then a rename).
  if (g.settings.metadata) {
    std::ifstream in(written, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    AtomicFile out(written);
    out.write(withGifMetadata(bytes, *g.settings.metadata));
    out.commit();
  }
  return written;
}

std::filesystem::path GifWriter::finishPartial() {
  Graphs& g = *graphs_;
  if (g.useGraph && !g.flushed) {
    g.flushed = true;
    drain(g.frameIn, g.frameOut, g.converted.get(), [this](AVFrame* f) { writeConverted(f); });
  }
  return VideoWriter::finishPartial();
}

std::unique_ptr<FrameSink> openGifSink(const SinkOptions& o) {
  GifSettings s;
  s.width = o.width;
  s.height = o.height;
  s.fpsNum = o.fpsNum;
  s.fpsDen = o.fpsDen;
  s.loop = o.loop;
  s.alpha = o.alpha;
  s.metadata = o.metadata;
  return std::make_unique<GifWriter>(o.path, s);
}

}  // namespace rollspin::media
