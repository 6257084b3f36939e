#include "media/mp4_writer.hpp"

#include <fmt/format.h>

#include "media/sink_factory.hpp"

namespace rollspin::media {

VideoSettings mp4VideoSettings(const Mp4Settings& s) {
  VideoSettings v;
  v.width = s.width;
  v.height = s.height;
  v.fpsNum = s.fpsNum;
  v.fpsDen = s.fpsDen;
  v.container = "mp4";
  v.encoder = s.encoder;
  v.pixelFormat = "yuv420p";
  v.codecOptions = {{"preset", s.preset}, {"crf", fmt::format("{}", s.crf)}};
  v.muxerOptions = {{"movflags", "+faststart+write_colr"}};
  v.describe = fmt::format("preset {}, crf {}", s.preset, s.crf);
  return v;
}

std::unique_ptr<FrameSink> openMp4Sink(const SinkOptions& o) {
  Mp4Settings s;
  s.width = o.width;
  s.height = o.height;
  s.fpsNum = o.fpsNum;
  s.fpsDen = o.fpsDen;
  if (o.crf) s.crf = *o.crf;
  s.preset = o.preset;
  VideoSettings v = mp4VideoSettings(s);
  v.containerMetadata = o.containerMetadata;
  v.subtitleEncoder = "mov_text";
  v.subtitles = o.subtitles;
  v.subtitlesByDefault = o.subtitlesByDefault;
  return std::make_unique<VideoWriter>(o.path, v);
}

}  // namespace rollspin::media
