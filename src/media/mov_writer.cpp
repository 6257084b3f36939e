// MOV: Apple ProRes (prores_ks) for video editors. With transparency,
// ProRes 4444 in yuva444p10le (a 16-bit alpha plane); otherwise ProRes 422
// HQ in yuv422p10le. Intra-only and near-lossless, so the files are large
// (≈ 10× an MP4); crf and preset do not apply. BT.709 tags (video_writer.hpp).
#include <fmt/format.h>

#include "media/sink_factory.hpp"

namespace rollspin::media {

std::unique_ptr<FrameSink> openMovSink(const SinkOptions& o) {
  VideoSettings v;
  v.width = o.width;
  v.height = o.height;
  v.fpsNum = o.fpsNum;
  v.fpsDen = o.fpsDen;
  v.container = "mov";
  v.encoder = "prores_ks";
  v.pixelFormat = o.alpha ? "yuva444p10le" : "yuv422p10le";
  // "apl0": the vendor Apple's own encoder writes; Final Cut and some
  // players check it.
  // threads 0: slice threads on every core, as the ffmpeg tool does
  // (libavcodec's default is one thread).
  v.codecOptions = {{"profile", o.alpha ? "4444" : "hq"}, {"vendor", "apl0"}, {"threads", "0"}};
  if (o.alpha) v.codecOptions.emplace_back("alpha_bits", "16");
  v.muxerOptions = {{"movflags", "+faststart+write_colr"}};
  v.containerMetadata = o.containerMetadata;
  v.describe = o.alpha ? "ProRes 4444 with alpha" : "ProRes 422 HQ";
  return std::make_unique<VideoWriter>(o.path, v);
}

}  // namespace rollspin::media
