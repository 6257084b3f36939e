// MOV: Apple ProRes for video editors. With transparency, ProRes 4444 in
// yuva444p10le (a 16-bit alpha plane); otherwise ProRes 422 HQ in
// yuv422p10le. Intra-only and near-lossless, so the files are large (≈ 10×
// an MP4); crf and preset do not apply. BT.709 tags (video_writer.hpp).
// The encoder is prores_aw, not prores_ks: at 1080p it takes about a third
// of prores_ks's CPU a frame, and its 422 HQ is closer to the frames (PSNR
// 49.2 against 48.0 dB on lollipop frames); its 4444 is 58 dB against 62,
// both far below a level of error (docs/rendering.md#animations, the mov row).
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
  v.encoder = "prores_aw";
  v.pixelFormat = o.alpha ? "yuva444p10le" : "yuv422p10le";
  // prores_aw takes the profile as libavcodec's number (FF_PROFILE_PRORES_HQ
  // 3, _4444 4): it has no names for them. "apl0": the vendor Apple's own
  // encoder writes; Final Cut and some players check it. threads 0: a frame
  // thread per core, as the ffmpeg tool does (libavcodec's default is one
  // thread); frames are intra-only, so the bytes do not depend on it.
  v.codecOptions = {{"profile", o.alpha ? "4" : "3"}, {"vendor", "apl0"}, {"threads", "0"}};
  v.muxerOptions = {{"movflags", "+faststart+write_colr"}};
  v.containerMetadata = o.containerMetadata;
  v.subtitleEncoder = "mov_text";
  v.subtitles = o.subtitles;
  v.subtitlesByDefault = o.subtitlesByDefault;
  v.describe = o.alpha ? "ProRes 4444 with alpha" : "ProRes 422 HQ";
  return std::make_unique<VideoWriter>(o.path, v);
}

}  // namespace rollspin::media
