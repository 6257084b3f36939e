// H.264 levels (ITU-T H.264 Table A-1): the largest frame and macroblock
// rate each level allows, and the frame-size rule an MP4 is checked by.
// A frame of W×H pixels is ⌈W/16⌉·⌈H/16⌉ macroblocks; a level holds it when
// macroblocks ≤ MaxFS, each side ≤ √(8·MaxFS) macroblocks (A.3.1 h, i) and
// macroblocks · fps ≤ MaxMBPS. Level 6.2's MaxFS, 139,264 macroblocks
// (8192×4320), is the largest any level allows: libx264 encodes bigger
// frames anyway and tags them 6.2, a level they break, so rollspin refuses
// them. Libav-free, so the scene checks can use it.
#pragma once

#include <cstdint>
#include <optional>

namespace rollspin::media {

struct H264Level {
  int idc;                               // level_idc as the stream carries it: 31 for 3.1
  std::int64_t maxMacroblocksPerSecond;  // MaxMBPS
  std::int64_t maxFrameMacroblocks;      // MaxFS
};

// The largest frame of any level (6.2's MaxFS).
inline constexpr std::int64_t kH264LargestFrameMacroblocks = 139264;

[[nodiscard]] std::int64_t h264Macroblocks(int width, int height);
// Whether some level holds a frame of this size (at any frame rate).
[[nodiscard]] bool h264HoldsFrame(int width, int height);
// The lowest level that holds this size at this rate, or nullopt.
[[nodiscard]] std::optional<H264Level> lowestH264Level(int width, int height, double fps);

}  // namespace rollspin::media
