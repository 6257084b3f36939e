// Test helper: decodes a video file with the FFmpeg libraries (no ffprobe
// needed) and reports what a player would see: codec, pixel format, colour
// tags, every frame's presentation timestamp, and chosen frames as RGBA
// (BT.709, limited range → full-range RGB, the inverse of the encoder's
// conversion).
#pragma once

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "media/image_view.hpp"

namespace rollspin::test {

struct VideoProbe {
  std::string container;           // "mov,mp4,m4a,3gp,3g2,mj2"
  std::string codec;               // "h264"
  std::string pixelFormat;         // "yuv420p" (the stream's, as the container declares it)
  std::string decodedPixelFormat;  // what the decoder produced ("yuva420p" for VP9 with alpha)
  std::string profile;             // "4444", "HQ" (ProRes); "" when the codec has none
  int level = 0;                   // the stream's level as coded (H.264: level_idc, 31 for 3.1)
  std::string alphaMode;           // the stream's ALPHA_MODE tag (WebM with alpha: "1")
  std::string colorSpace, colorPrimaries, colorTransfer, colorRange;  // "bt709", …, "tv"
  std::string chromaLocation;  // "left", "center", … ("unspecified" when the stream does not say)
  int width = 0, height = 0;
  double frameRate = 0.0;                  // average, from the stream
  int frameRateNum = 0, frameRateDen = 0;  // the same, exactly (30000/1001)
  int timeBaseNum = 0, timeBaseDen = 0;    // the stream's time base
  std::vector<double> ptsSeconds;          // decoded frames, in presentation order
  std::vector<long long> ptsTicks;         // the same in time-base units, exactly
  std::vector<media::Image> kept;          // the frames asked for, in index order
  bool indexBeforeData = false;            // 'moov' before 'mdat' (+faststart)
  // The video stream's packets as the container stores them (decode order):
  // their decoding and presentation timestamps, in time-base units.
  std::vector<long long> packetDtsTicks, packetPtsTicks;
  long long durationTicks = 0;  // the stream's duration as the container states it (time-base units)
};

// VP9 with an ALPHA_MODE tag is decoded with libvpx (FFmpeg's own VP9
// decoder ignores the alpha stream), so `kept` frames carry the alpha that
// a browser shows. Throws std::runtime_error when the file cannot be opened or decoded.
VideoProbe probeVideo(const std::filesystem::path& file, const std::set<long long>& keepFrames = {});

}  // namespace rollspin::test
