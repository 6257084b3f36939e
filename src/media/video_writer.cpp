#include "media/video_writer.hpp"

#include "core/temp_files.hpp"
#include "media/container_tags.hpp"

#include "media/av_library.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string_view>
#include <system_error>
#include <thread>

#include "core/error.hpp"
#include "media/av_support.hpp"
#include "media/yuv420_converter.hpp"

namespace rollspin::media {

namespace fs = std::filesystem;

fs::path partialName(const fs::path& finalPath) {
  fs::path out = finalPath;
  out.replace_filename(fmt::format("{}.partial{}", finalPath.stem().string(), finalPath.extension().string()));
  return out;
}

namespace {

// The conversion's threads: ROLLSPIN_CONVERT_THREADS, else `fallback`. On
// one core the encoder thread's conversion set the pace of a GPU-rendered
// 1080p video; both converters split rows, so the bytes do not depend on it.
int conversionThreads(int fallback) {
  if (const char* text = std::getenv("ROLLSPIN_CONVERT_THREADS"); text != nullptr && *text != '\0')
    return std::max(0, std::atoi(text));
  return fallback;
}

// RGBA → any other format (ProRes's 10-bit ones), bilinear, in swscale's own
// slice threads (0: swscale's "auto", one per core; FFmpeg >= 5.0).
SwsContext* makeConverter(int width, int height, AVPixelFormat to) {
  const int threads = conversionThreads(0);
  SwsContext* sws = sws_alloc_context();
  if (sws == nullptr) return nullptr;
  const bool set = av_opt_set_int(sws, "srcw", width, 0) >= 0 && av_opt_set_int(sws, "srch", height, 0) >= 0 &&
                   av_opt_set_int(sws, "dstw", width, 0) >= 0 && av_opt_set_int(sws, "dsth", height, 0) >= 0 &&
                   av_opt_set_pixel_fmt(sws, "src_format", AV_PIX_FMT_RGBA, 0) >= 0 &&
                   av_opt_set_pixel_fmt(sws, "dst_format", to, 0) >= 0 &&
                   av_opt_set_int(sws, "sws_flags", SWS_BILINEAR, 0) >= 0 &&
                   av_opt_set_int(sws, "threads", threads, 0) >= 0;
  if (!set || sws_init_context(sws, nullptr, nullptr) < 0) {
    sws_freeContext(sws);
    return nullptr;
  }
  return sws;
}

// The subtitle encoders read their default style from an ASS header (the
// one the ffmpeg tool gives text subtitles): white 16-px sans, bottom centre.
constexpr const char* kAssHeader =
    "[Script Info]\nScriptType: v4.00+\nPlayResX: 384\nPlayResY: 288\n\n[V4+ Styles]\n"
    "Format: Name, Fontname, Fontsize, PrimaryColour, SecondaryColour, OutlineColour, BackColour, Bold, Italic, "
    "Underline, StrikeOut, ScaleX, ScaleY, Spacing, Angle, BorderStyle, Outline, Shadow, Alignment, MarginL, MarginR, "
    "MarginV, Encoding\n"
    "Style: Default,Arial,16,&Hffffff,&Hffffff,&H0,&H0,0,0,0,0,100,100,0,0,1,1,0,2,10,10,10,0\n\n"
    "[Events]\nFormat: Layer, Start, End, Style, Name, MarginL, MarginR, MarginV, Effect, Text\n";

// A cue's text as an ASS event's: line breaks are \N. A brace or a
// backslash would open an ASS override code (which the encoders read as
// styling, not text), so in the track these become their full-width
// look-alikes; the sidecar files keep them as written.
std::string assEventText(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') out += "\\N";
    else if (c == '\r') continue;
    else if (c == '{') out += "\xef\xbd\x9b";   // U+FF5B
    else if (c == '}') out += "\xef\xbd\x9d";   // U+FF5D
    else if (c == '\\') out += "\xef\xbc\xbc";  // U+FF3C
    else out += c;
  }
  return out;
}

}  // namespace

struct VideoWriter::Impl {
  fs::path finalPath, writePath;
  bool direct = false;
  VideoSettings settings;
  AVPixelFormat pixelFormat = AV_PIX_FMT_NONE;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVCodecContext* subtitleCodec = nullptr;  // the captions' encoder and stream, when there are cues
  AVStream* subtitleStream = nullptr;
  std::size_t nextCue = 0;
  AVFrame* frame = nullptr;
  AVFrame* source = nullptr;  // the caller's RGBA image, wrapped (never copied) for sws_scale_frame
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  // 8-bit 4:2:0 (H.264, VP9): converted here, only the blocks that changed
  // since the last frame; other formats (ProRes) through swscale.
  std::optional<Yuv420Converter> yuv420;
  long long pixelsGiven = 0, pixelsConverted = 0;  // over the frames given to yuv420
  long long framesWritten = 0;
  bool fileOpen = false, done = false, headerWritten = false;
  // av_write_trailer was called, whatever it returned: the muxer has freed
  // its state then, and a second call (Matroska after a failed write on a
  // full disk) reads freed memory.
  bool trailerCalled = false;

  ~Impl() {
    // Unfinished after its header: the trailer frees what the muxer still
    // holds (queued packets); the file it completes is removed below.
    if (!done && headerWritten && !trailerCalled && format != nullptr && format->pb != nullptr)
      av_write_trailer(format);
    release();
    if (!done && fileOpen && !direct) {
      std::error_code ec;
      fs::remove(writePath, ec);
    }
    if (!direct) unregisterTemporary(writePath);
  }

  void release() {
    sws_freeContext(sws);
    sws = nullptr;
    av_frame_free(&source);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    avcodec_free_context(&subtitleCodec);
    if (format != nullptr) {
      if (format->pb != nullptr) avio_closep(&format->pb);
      avformat_free_context(format);
      format = nullptr;
    }
  }

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw runtimeError(SourceLoc{finalPath.string()}, "{}: {}", what, av::errorText(code));
  }
  void check(int code, const std::string& what) const {
    if (code < 0) fail(what, code);
  }
  // Write errors (a full disk) surface in the I/O context, sometimes only here.
  void checkIo(const std::string& what) const {
    if (format->pb != nullptr && format->pb->error < 0) fail(what, format->pb->error);
  }

  // mux.c's encode loop: one frame in (null = flush), every packet out.
  void encode(const AVFrame* input) {
    check(avcodec_send_frame(codec, input), "encoding a frame");
    while (true) {
      const int ret = avcodec_receive_packet(codec, packet);
      if (ret == AVERROR(EAGAIN) || ret == AVERROR_EOF) break;
      check(ret, "encoding a frame");
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      check(av_interleaved_write_frame(format, packet), "writing " + writePath.string());
    }
    checkIo("writing " + writePath.string());
  }

  // The subtitle stream, before the header: the encoder makes its
  // extradata (mov_text's sample description).
  void openSubtitles(const SourceLoc& where) {
    if (settings.subtitles.empty() || settings.subtitleEncoder.empty()) return;
    const AVCodec* encoder = avcodec_find_encoder_by_name(settings.subtitleEncoder.c_str());
    if (encoder == nullptr)
      throw runtimeError(where, "this FFmpeg build has no '{}' subtitle encoder", settings.subtitleEncoder);
    subtitleCodec = avcodec_alloc_context3(encoder);
    if (subtitleCodec == nullptr) throw runtimeError(where, "out of memory");
    subtitleCodec->time_base = codec->time_base;
    // The context frees its header with av_free: it must come from av_malloc.
    subtitleCodec->subtitle_header = reinterpret_cast<std::uint8_t*>(av_strdup(kAssHeader));
    if (subtitleCodec->subtitle_header == nullptr) throw runtimeError(where, "out of memory");
    subtitleCodec->subtitle_header_size = static_cast<int>(std::strlen(kAssHeader));
    check(avcodec_open2(subtitleCodec, encoder, nullptr), "opening the " + settings.subtitleEncoder + " encoder");
    subtitleStream = avformat_new_stream(format, nullptr);
    if (subtitleStream == nullptr) throw runtimeError(where, "out of memory");
    check(avcodec_parameters_from_context(subtitleStream->codecpar, subtitleCodec), "configuring the subtitle stream");
    subtitleStream->time_base = codec->time_base;
    if (settings.subtitlesByDefault) subtitleStream->disposition = AV_DISPOSITION_DEFAULT;
  }

  // Every cue that starts at or before `frame`, as one packet each.
  void writeCuesUpTo(long long frame) {
    for (; subtitleStream != nullptr && nextCue < settings.subtitles.size() &&
           settings.subtitles[nextCue].firstFrame <= frame;
         ++nextCue) {
      const SubtitleCue& cue = settings.subtitles[nextCue];
      std::string event = "0,0,Default,,0,0,0,," + assEventText(cue.text);
      AVSubtitleRect rect{};
      rect.type = SUBTITLE_ASS;
      rect.ass = event.data();
      AVSubtitleRect* rects[] = {&rect};
      AVSubtitle subtitle{};
      subtitle.num_rects = 1;
      subtitle.rects = rects;
      subtitle.format = 1;  // text
      // Both encoders write the text (escaped: at most a few bytes a byte) and a small header.
      std::vector<std::uint8_t> bytes(8 * event.size() + 1024);
      const int size = avcodec_encode_subtitle(subtitleCodec, bytes.data(), static_cast<int>(bytes.size()), &subtitle);
      check(size, "encoding a caption");
      check(av_new_packet(packet, size), "encoding a caption");
      std::memcpy(packet->data, bytes.data(), static_cast<std::size_t>(size));
      packet->pts = packet->dts = cue.firstFrame;
      packet->duration = cue.endFrame - cue.firstFrame;
      packet->flags |= AV_PKT_FLAG_KEY;
      av_packet_rescale_ts(packet, codec->time_base, subtitleStream->time_base);
      packet->stream_index = subtitleStream->index;
      check(av_interleaved_write_frame(format, packet), "writing " + writePath.string());
    }
  }

  void close() {
    encode(nullptr);
    trailerCalled = true;
    check(av_write_trailer(format), "finishing " + writePath.string());
    avio_flush(format->pb);
    checkIo("finishing " + writePath.string());
    check(avio_closep(&format->pb), "closing " + writePath.string());
    release();
  }

  // ---- the constructor's setup steps, in order ----

  const AVCodec* findVideoEncoder(const SourceLoc& where) {
    const AVCodec* encoder = avcodec_find_encoder_by_name(settings.encoder.c_str());
    if (encoder == nullptr)
      throw runtimeError(where,
                         "this FFmpeg build has no '{}' encoder (Debian: libavcodec59 has libx264, libvpx-vp9, "
                         "prores_aw and gif)",
                         settings.encoder);
    pixelFormat = av_get_pix_fmt(settings.pixelFormat.c_str());
    if (pixelFormat == AV_PIX_FMT_NONE)
      throw runtimeError(where, "libavutil has no pixel format '{}'", settings.pixelFormat);
    return encoder;
  }

  void chooseWritePath() {
    direct = av::isDevice(finalPath);
    writePath = finalPath;
    if (!direct) {
      // A temporary left by a run that died hard goes; ours goes on SIGINT/SIGTERM.
      removeStaleTemporaries(finalPath);
      writePath = temporaryPathFor(finalPath);
      registerTemporary(writePath, finalPath);
    }
  }

  void allocateOutput(const SourceLoc& where, const AVCodec* encoder, const std::string& url) {
    if (avformat_alloc_output_context2(&format, nullptr, settings.container.c_str(), url.c_str()) < 0 ||
        format == nullptr)
      throw runtimeError(where, "libavformat has no '{}' muxer", settings.container);
    codec = avcodec_alloc_context3(encoder);
    frame = av_frame_alloc();
    packet = av_packet_alloc();
    if (codec == nullptr || frame == nullptr || packet == nullptr) throw runtimeError(where, "out of memory");
    stream = avformat_new_stream(format, nullptr);
    if (stream == nullptr) throw runtimeError(where, "out of memory");
  }

  // 8-bit 4:2:0 goes through rollspin's converter (yuv420), the rest through swscale.
  [[nodiscard]] bool convertsOwnYuv420() const {
    return settings.yuvBt709 && (pixelFormat == AV_PIX_FMT_YUV420P || pixelFormat == AV_PIX_FMT_YUVA420P);
  }

  // The encoder's size, rate and colour tags, the caller's options; then the
  // video stream's parameters from the opened encoder.
  void openVideoEncoder(const AVCodec* encoder) {
    AVCodecContext* c = codec;
    c->width = settings.width;
    c->height = settings.height;
    // One tick per frame: frame k's pts is k, at exactly k·den/num seconds.
    c->time_base = AVRational{settings.fpsDen, settings.fpsNum};
    c->framerate = AVRational{settings.fpsNum, settings.fpsDen};
    c->sample_aspect_ratio = AVRational{1, 1};
    c->pix_fmt = pixelFormat;
    // rollspin's converter's chroma is the mean of each 2×2 block: sited at
    // the block's centre, not H.264's default left.
    if (convertsOwnYuv420()) c->chroma_sample_location = AVCHROMA_LOC_CENTER;
    if (settings.yuvBt709) {
      // BT.709 everywhere: the matrix of the conversion, and the tags.
      c->color_range = AVCOL_RANGE_MPEG;
      c->color_primaries = AVCOL_PRI_BT709;
      c->color_trc = AVCOL_TRC_BT709;
      c->colorspace = AVCOL_SPC_BT709;
    }
    if ((format->oformat->flags & AVFMT_GLOBALHEADER) != 0) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    for (const auto& [key, value] : settings.codecOptions)
      if (const int ret = av_opt_set(c, key.c_str(), value.c_str(), AV_OPT_SEARCH_CHILDREN); ret < 0)
        fail(fmt::format("{} has no option {} = {}", settings.encoder, key, value), ret);
    if (const int ret = avcodec_open2(c, encoder, nullptr); ret < 0)
      fail(fmt::format("{} refuses {}x{} at {}/{} fps ({})", settings.encoder, settings.width, settings.height,
                       settings.fpsNum, settings.fpsDen, settings.describe),
           ret);
    check(avcodec_parameters_from_context(stream->codecpar, c), "configuring the stream");
    stream->time_base = c->time_base;
    stream->avg_frame_rate = c->framerate;
    for (const auto& [key, value] : settings.streamMetadata)
      av_dict_set(&stream->metadata, key.c_str(), value.c_str(), 0);
  }

  void allocateFrame() {
    const AVCodecContext* c = codec;
    frame->format = c->pix_fmt;
    frame->width = c->width;
    frame->height = c->height;
    // Some encoders (ProRes) write the frame's tags, not the context's.
    frame->color_range = c->color_range;
    frame->color_primaries = c->color_primaries;
    frame->color_trc = c->color_trc;
    frame->colorspace = c->colorspace;
    frame->chroma_location = c->chroma_sample_location;
    check(av_frame_get_buffer(frame, 0), "allocating a frame");
  }

  void setUpConversion(const SourceLoc& where) {
    if (convertsOwnYuv420()) {
      // A quarter of the cores (at most 8): a fixed camera converts a few
      // percent of a frame, a moving one all of it; on 2 cores, one thread.
      const int cores = static_cast<int>(std::thread::hardware_concurrency());
      yuv420.emplace(codec->width, codec->height, conversionThreads(std::clamp(cores / 4, 1, 8)));
    } else if (pixelFormat != AV_PIX_FMT_PAL8) {  // a palette comes from a filter graph (gif_writer), not swscale
      sws = makeConverter(codec->width, codec->height, pixelFormat);
      if (sws == nullptr)
        throw runtimeError(where, "libswscale cannot convert RGBA to {} at this size", settings.pixelFormat);
      source = av_frame_alloc();
      if (source == nullptr) throw runtimeError(where, "out of memory allocating a frame");
      const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
      // Source: full-range RGB (its table is unused); destination: limited range.
      if (settings.yuvBt709) sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    }
  }

  void openFileAndWriteHeader(const std::string& url) {
    if (const int ret = avio_open(&format->pb, url.c_str(), AVIO_FLAG_WRITE); ret < 0) {
      format->pb = nullptr;
      fail(direct ? "cannot open for writing" : "cannot create " + writePath.string(), ret);
    }
    fileOpen = true;
    // Each packet goes to the file as it is muxed: the file grows with the
    // render (visible progress) and the muxer buffers at most one packet.
    format->flush_packets = 1;
    AVDictionary* options = nullptr;
    for (const auto& [key, value] : settings.muxerOptions) {
      // faststart rewrites the file at the end: only for a regular file.
      const std::string v = direct && key == "movflags" ? "+write_colr" : value;
      av_dict_set(&options, key.c_str(), v.c_str(), 0);
    }
    if (!settings.containerMetadata.empty()) allowCustomContainerKeys(format, &options);
    const int ret = avformat_write_header(format, &options);
    av_dict_free(&options);
    check(ret, "writing the " + settings.container + " header");
    headerWritten = true;
    checkIo("writing the " + settings.container + " header");
  }
};

VideoWriter::VideoWriter(fs::path finalPath, const VideoSettings& settings) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.finalPath = std::move(finalPath);
  m.settings = settings;
  const SourceLoc where{m.finalPath.string()};
  if (settings.width <= 0 || settings.height <= 0 ||
      (settings.evenSize && (settings.width % 2 != 0 || settings.height % 2 != 0)))
    throw badInput(where, "{} in {} needs an even, non-zero width and height; got {}x{}", settings.encoder,
                   settings.pixelFormat, settings.width, settings.height);
  if (settings.fpsNum <= 0 || settings.fpsDen <= 0)
    throw badInput(where, "expected frames per second > 0, got {}/{}", settings.fpsNum, settings.fpsDen);
  av_log_set_level(AV_LOG_ERROR);  // the encoders' statistics are not for lecturers

  const AVCodec* encoder = m.findVideoEncoder(where);
  m.chooseWritePath();
  // The container is named, so the temporary name's extension does not matter.
  // "file:" keeps a colon in a file name from reading as a protocol.
  const std::string url = "file:" + m.writePath.string();
  m.allocateOutput(where, encoder, url);
  m.openVideoEncoder(encoder);
  m.openSubtitles(where);
  // File-level metadata: the one place it is set (see VideoSettings).
  for (const auto& [key, value] : settings.containerMetadata)
    av_dict_set(&m.format->metadata, key.c_str(), value.c_str(), 0);
  m.allocateFrame();
  m.setUpConversion(where);
  m.openFileAndWriteHeader(url);
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::write(const ImageView& image) {
  Impl& m = *impl_;
  if (image.width != m.settings.width || image.height != m.settings.height)
    throw runtimeError(SourceLoc{m.finalPath.string()}, "frame of {}x{} for a {}x{} video", image.width, image.height,
                       m.settings.width, m.settings.height);
  // The encoder may still hold the previous frame's buffer (lookahead):
  // then this copies it, so the planes still hold the previous frame.
  m.check(av_frame_make_writable(m.frame), "allocating a frame");
  if (m.yuv420) {
    AVFrame* f = m.frame;
    m.pixelsConverted += m.yuv420->convert(image, {f->data[0], f->data[1], f->data[2], f->data[3], f->linesize[0],
                                                   f->linesize[1], f->linesize[2], f->linesize[3]});
    m.pixelsGiven += static_cast<long long>(image.width) * image.height;
    writeConverted(f);
    return;
  }
  // Rows from the top whatever the storage order: a negative stride flips.
  const std::uint8_t* top = image.rowFromTop(0);
  const int stride = static_cast<int>(image.rows == RowOrder::TopDown ? image.stride : -image.stride);
  AVFrame* source = m.source;
  source->format = AV_PIX_FMT_RGBA;
  source->width = image.width;
  source->height = image.height;
  source->data[0] = const_cast<std::uint8_t*>(top);
  source->linesize[0] = stride;
  // A reference that frees nothing: swscale takes a reference to its input,
  // and one to memory without a buffer would be a copy of the whole image.
  const auto bytes = static_cast<std::size_t>(image.stride) * static_cast<std::size_t>(image.height);
  source->buf[0] = av_buffer_create(
      const_cast<std::uint8_t*>(image.rgba), bytes, [](void*, std::uint8_t*) {}, nullptr, AV_BUFFER_FLAG_READONLY);
  if (source->buf[0] == nullptr) throw runtimeError(SourceLoc{m.finalPath.string()}, "out of memory wrapping a frame");
  const int converted = sws_scale_frame(m.sws, m.frame, source);
  av_frame_unref(source);
  m.check(converted, "converting a frame to " + m.settings.pixelFormat);
  writeConverted(m.frame);
}

void VideoWriter::writeConverted(AVFrame* frame) {
  Impl& m = *impl_;
  frame->pts = m.framesWritten;
  m.writeCuesUpTo(m.framesWritten);
  m.encode(frame);
  ++m.framesWritten;
}

const fs::path& VideoWriter::finalPath() const { return impl_->finalPath; }

fs::path VideoWriter::finish() {
  Impl& m = *impl_;
  m.close();
  if (!m.direct) {
    std::error_code ec;
    fs::rename(m.writePath, m.finalPath, ec);
    if (ec)
      throw runtimeError(SourceLoc{m.finalPath.string()}, "cannot rename the finished video into place: {}",
                         ec.message());
  }
  m.done = true;
  return m.finalPath;
}

fs::path VideoWriter::finishPartial() {
  Impl& m = *impl_;
  if (m.framesWritten == 0) return {};  // the destructor removes the empty file
  // The tags say which frames the file holds: the ones written, not the
  // ones asked for. MP4/MOV write them with the trailer; Matroska (WebM)
  // wrote them with the header, so the finished file is patched.
  const std::optional<FramesRetag> retag = retagPartial(m.format, m.framesWritten);
  const bool tagsInHeader = std::string_view(m.format->oformat->name).find("matroska") != std::string_view::npos ||
                            std::string_view(m.format->oformat->name) == "webm";
  m.close();
  if (!m.direct && tagsInHeader && retag && retag->after != retag->before &&
      !patchMatroskaFramesTag(m.writePath, retag->before, retag->after))
    std::fprintf(stderr, "rollspin: warning: %s still says it holds frames %s (it holds %s)\n",
                 partialName(m.finalPath).string().c_str(), retag->before.c_str(), retag->after.c_str());
  if (m.direct) {
    m.done = true;
    return m.finalPath;
  }
  const fs::path partial = partialName(m.finalPath);
  std::error_code ec;
  fs::rename(m.writePath, partial, ec);
  if (ec)
    throw runtimeError(SourceLoc{partial.string()}, "cannot rename the partial video into place: {}", ec.message());
  m.done = true;
  return partial;
}

long long VideoWriter::framesWritten() const { return impl_->framesWritten; }

bool VideoWriter::carriesSubtitles() const { return !impl_->settings.subtitleEncoder.empty(); }

std::string VideoWriter::verboseSummary() const {
  const Impl& m = *impl_;
  if (!m.yuv420 || m.pixelsGiven == 0) return {};
  return fmt::format("converted {:.1f} % of the pixels to {}; the rest were as in the frame before",
                     100.0 * double(m.pixelsConverted) / double(m.pixelsGiven), m.settings.pixelFormat);
}

}  // namespace rollspin::media
