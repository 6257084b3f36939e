#include "media/yuv420_converter.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>
#include <thread>

namespace rollspin::media {
namespace {

// Coefficients in units of 2^-16, rounded; each row's last one is chosen so
// that the row sums exactly as the matrix does (white → 235, greys → 128).
constexpr int kShift = 16;
constexpr int fixed(double c) { return static_cast<int>(c * (1 << kShift) + (c < 0 ? -0.5 : 0.5)); }

constexpr double kKr = 0.2126, kKb = 0.0722, kKg = 1.0 - kKr - kKb;
constexpr double kLumaScale = 219.0 / 255.0, kChromaScale = 224.0 / 255.0;

constexpr int kYr = fixed(kLumaScale * kKr), kYb = fixed(kLumaScale * kKb);
constexpr int kYg = fixed(kLumaScale) - kYr - kYb;
constexpr int kCbR = fixed(-kChromaScale * kKr / (2 * (1 - kKb))), kCbG = fixed(-kChromaScale * kKg / (2 * (1 - kKb)));
constexpr int kCbB = -kCbR - kCbG;
constexpr int kCrB = fixed(-kChromaScale * kKb / (2 * (1 - kKr))), kCrG = fixed(-kChromaScale * kKg / (2 * (1 - kKr)));
constexpr int kCrR = -kCrG - kCrB;

constexpr int kLumaOffset = (16 << kShift) + (1 << (kShift - 1));
// Chroma comes from sums of four pixels: two more bits of shift.
constexpr int kChromaOffset = (128 << (kShift + 2)) + (1 << (kShift + 1));

inline int lumaOf(int r, int g, int b) { return (kYr * r + kYg * g + kYb * b + kLumaOffset) >> kShift; }
// Chroma of a 2×2 block from its sums of R, G and B (0 … 1020 each).
inline int cbOf(int r, int g, int b) { return (kCbR * r + kCbG * g + kCbB * b + kChromaOffset) >> (kShift + 2); }
inline int crOf(int r, int g, int b) { return (kCrR * r + kCrG * g + kCrB * b + kChromaOffset) >> (kShift + 2); }

// A pixel as one 32-bit load (RGBA in memory order): loops over words
// vectorise where loops over bytes four apart do not.
inline std::uint32_t word(const std::uint8_t* row, int x) {
  std::uint32_t w;
  std::memcpy(&w, row + 4 * x, 4);
  return w;
}
static_assert(std::endian::native == std::endian::little, "red() … blue() read RGBA from a little-endian word");
inline int red(std::uint32_t w) { return static_cast<int>(w & 0xff); }
inline int green(std::uint32_t w) { return static_cast<int>((w >> 8) & 0xff); }
inline int blue(std::uint32_t w) { return static_cast<int>((w >> 16) & 0xff); }

void lumaRow(const std::uint8_t* row, int x0, int x1, std::uint8_t* out) {
  for (int x = x0; x < x1; ++x) {
    const std::uint32_t w = word(row, x);
    out[x] = static_cast<std::uint8_t>(lumaOf(red(w), green(w), blue(w)));
  }
}

constexpr int kBlock = Yuv420Converter::kBlockWidth;

// Rows y and y + 1 (from the top), pixels [x0, x1) (both even, at most a block) into the planes.
void convertBlock(const std::uint8_t* row0, const std::uint8_t* row1, int y, int x0, int x1, const Yuv420Planes& out) {
  std::uint8_t* lumaTop = out.y + y * out.yStride;
  lumaRow(row0, x0, x1, lumaTop);
  lumaRow(row1, x0, x1, lumaTop + out.yStride);
  std::uint8_t* cb = out.u + (y / 2) * out.uStride;
  std::uint8_t* cr = out.v + (y / 2) * out.vStride;
  // Column sums of the two rows first (a loop that vectorises), then pairs.
  int redSum[kBlock], greenSum[kBlock], blueSum[kBlock];
  const int n = x1 - x0;
  for (int i = 0; i < n; ++i) {
    const std::uint32_t top = word(row0, x0 + i), bottom = word(row1, x0 + i);
    redSum[i] = red(top) + red(bottom);
    greenSum[i] = green(top) + green(bottom);
    blueSum[i] = blue(top) + blue(bottom);
  }
  for (int i = 0; i < n / 2; ++i) {
    const int r = redSum[2 * i] + redSum[2 * i + 1], g = greenSum[2 * i] + greenSum[2 * i + 1];
    const int b = blueSum[2 * i] + blueSum[2 * i + 1];
    cb[x0 / 2 + i] = static_cast<std::uint8_t>(cbOf(r, g, b));
    cr[x0 / 2 + i] = static_cast<std::uint8_t>(crOf(r, g, b));
  }
  if (out.a != nullptr) {
    std::uint8_t* alphaTop = out.a + y * out.aStride;
    std::uint8_t* alphaBottom = alphaTop + out.aStride;
    for (int x = x0; x < x1; ++x) {
      alphaTop[x] = static_cast<std::uint8_t>(word(row0, x) >> 24);
      alphaBottom[x] = static_cast<std::uint8_t>(word(row1, x) >> 24);
    }
  }
}

}  // namespace

std::uint8_t bt709Luma(int r, int g, int b) { return static_cast<std::uint8_t>(lumaOf(r, g, b)); }
std::uint8_t bt709Cb(int r, int g, int b) { return static_cast<std::uint8_t>(cbOf(r, g, b)); }
std::uint8_t bt709Cr(int r, int g, int b) { return static_cast<std::uint8_t>(crOf(r, g, b)); }

Yuv420Converter::Yuv420Converter(int width, int height, int threads)
    : width_(width),
      height_(height),
      threads_(std::max(1, threads)),
      previous_(static_cast<std::size_t>(width) * height * 4) {
  assert(width > 0 && height > 0 && width % 2 == 0 && height % 2 == 0);
}

long long Yuv420Converter::convert(const ImageView& frame, const Yuv420Planes& planes) {
  assert(frame.width == width_ && frame.height == height_);
  const int pairs = height_ / 2;
  // Bands of at least 32 row pairs: below that a thread costs more than it saves.
  const int bands = std::min(threads_, std::max(1, pairs / 32));
  long long converted = 0;
  if (bands == 1) {
    converted = convertRows(frame, planes, 0, pairs);
  } else {
    std::vector<long long> counts(static_cast<std::size_t>(bands), 0);
    {
      std::vector<std::jthread> workers;
      for (int k = 1; k < bands; ++k)
        workers.emplace_back(
            [&, k] { counts[k] = convertRows(frame, planes, pairs * k / bands, pairs * (k + 1) / bands); });
      counts[0] = convertRows(frame, planes, 0, pairs / bands);
    }  // the workers join here
    for (const long long c : counts) converted += c;
  }
  havePrevious_ = true;
  return converted;
}

long long Yuv420Converter::convertRows(const ImageView& frame, const Yuv420Planes& planes, int firstPair, int endPair) {
  const auto rowBytes = static_cast<std::size_t>(width_) * 4;
  long long converted = 0;
  for (int y = 2 * firstPair; y < 2 * endPair; y += 2) {
    const std::uint8_t* row0 = frame.rowFromTop(y);
    const std::uint8_t* row1 = frame.rowFromTop(y + 1);
    std::uint8_t* kept0 = previous_.data() + static_cast<std::size_t>(y) * rowBytes;
    std::uint8_t* kept1 = kept0 + rowBytes;
    for (int x0 = 0; x0 < width_; x0 += kBlockWidth) {
      const int x1 = std::min(width_, x0 + kBlockWidth);
      const auto offset = static_cast<std::size_t>(x0) * 4, bytes = static_cast<std::size_t>(x1 - x0) * 4;
      // Unchanged blocks keep what the planes already hold.
      if (havePrevious_ && std::memcmp(row0 + offset, kept0 + offset, bytes) == 0 &&
          std::memcmp(row1 + offset, kept1 + offset, bytes) == 0)
        continue;
      convertBlock(row0, row1, y, x0, x1, planes);
      std::memcpy(kept0 + offset, row0 + offset, bytes);
      std::memcpy(kept1 + offset, row1 + offset, bytes);
      converted += 2LL * (x1 - x0);
    }
  }
  return converted;
}

}  // namespace rollspin::media
