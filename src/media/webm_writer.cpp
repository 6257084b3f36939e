// WebM: VP9 (libvpx-vp9) in a WebM (Matroska) file, for web pages and HTML
// slides. yuv420p, or yuva420p with transparency: libvpx encodes the alpha
// plane as a second VP9 stream in each block's BlockAdditional, and the
// track's AlphaMode = 1 tells browsers (Chromium, Firefox) to use it.
// Constant quality (bit rate 0 + crf), BT.709 tags (video_writer.hpp).
#include <fmt/format.h>

#include <map>

#include "media/sink_factory.hpp"

namespace rollspin::media {

namespace {

// VP9's crf runs 0 … 63 (x264's 0 … 51); 31 is libvpx's recommendation for
// 1080p on the web (Google's VOD settings), visually clean on our frames.
constexpr double kDefaultWebmCrf = 31.0;

// animation.preset (x264's names) → libvpx's cpu-used in "good" mode:
// higher is faster and a little larger.
int cpuUsed(const std::string& preset) {
  static const std::map<std::string, int> kSpeed{{"ultrafast", 8}, {"superfast", 7}, {"veryfast", 6},
                                                 {"faster", 5},    {"fast", 5},      {"medium", 4},
                                                 {"slow", 3},      {"slower", 2},    {"veryslow", 1}};
  const auto it = kSpeed.find(preset);
  return it == kSpeed.end() ? 4 : it->second;
}

}  // namespace

std::unique_ptr<FrameSink> openWebmSink(const SinkOptions& o) {
  VideoSettings v;
  v.width = o.width;
  v.height = o.height;
  v.fpsNum = o.fpsNum;
  v.fpsDen = o.fpsDen;
  v.container = "webm";
  v.encoder = "libvpx-vp9";
  v.pixelFormat = o.alpha ? "yuva420p" : "yuv420p";
  const double crf = o.crf.value_or(kDefaultWebmCrf);
  v.codecOptions = {{"b", "0"},  // with crf: constant quality, no bit-rate target
                    {"crf", fmt::format("{}", crf)},
                    {"deadline", "good"},
                    {"cpu-used", std::to_string(cpuUsed(o.preset))},
                    {"row-mt", "1"},
                    {"threads", "0"}};  // automatic, as the ffmpeg tool does (libavcodec's default is 1)
  if (o.alpha) v.streamMetadata = {{"alpha_mode", "1"}};
  v.containerMetadata = o.containerMetadata;
  v.subtitleEncoder = "webvtt";
  v.subtitles = o.subtitles;
  v.subtitlesByDefault = o.subtitlesByDefault;
  v.describe = fmt::format("VP9 crf {}, cpu-used {}{}", crf, cpuUsed(o.preset), o.alpha ? ", alpha" : "");
  return std::make_unique<VideoWriter>(o.path, v);
}

}  // namespace rollspin::media
