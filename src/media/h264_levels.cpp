#include "media/h264_levels.hpp"

#include <array>
#include <cmath>

namespace rollspin::media {

namespace {

// Table A-1, without level 1b (libx264 tags 1b only when asked to).
constexpr std::array<H264Level, 19> kLevels{{
    {10, 1485, 99},       {11, 3000, 396},       {12, 6000, 396},       {13, 11880, 396},       {20, 11880, 396},
    {21, 19800, 792},     {22, 20250, 1620},     {30, 40500, 1620},     {31, 108000, 3600},     {32, 216000, 5120},
    {40, 245760, 8192},   {41, 245760, 8192},    {42, 522240, 8704},    {50, 589824, 22080},    {51, 983040, 36864},
    {52, 2073600, 36864}, {60, 4177920, 139264}, {61, 8355840, 139264}, {62, 16711680, 139264},
}};

// A.3.1 items h and i: neither side may exceed √(8·MaxFS) macroblocks.
bool fitsFrame(const H264Level& level, int width, int height) {
  const double side = std::sqrt(8.0 * static_cast<double>(level.maxFrameMacroblocks));
  return h264Macroblocks(width, height) <= level.maxFrameMacroblocks && (width + 15) / 16 <= side &&
         (height + 15) / 16 <= side;
}

}  // namespace

std::int64_t h264Macroblocks(int width, int height) {
  return static_cast<std::int64_t>((width + 15) / 16) * ((height + 15) / 16);
}

bool h264HoldsFrame(int width, int height) { return fitsFrame(kLevels.back(), width, height); }

std::optional<H264Level> lowestH264Level(int width, int height, double fps) {
  for (const H264Level& level : kLevels)
    if (fitsFrame(level, width, height) &&
        static_cast<double>(h264Macroblocks(width, height)) * fps <= static_cast<double>(level.maxMacroblocksPerSecond))
      return level;
  return std::nullopt;
}

}  // namespace rollspin::media
