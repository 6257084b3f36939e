// Yuv420Converter — 8-bit RGBA (full range) → 8-bit 4:2:0 Y'CbCr, BT.709
// matrix, limited range, converting only what changed since the last frame:
//   Y' = 16  + 219/255 (0.2126 R + 0.7152 G + 0.0722 B)
//   Cb = 128 + 224/255 (B − Y)/1.8556,  Cr = 128 + 224/255 (R − Y)/1.5748
// (Y the unscaled luma), Cb and Cr of each 2×2 block from the block's mean
// RGB (chroma sited at the block's centre). Fixed-point and pixel-local: a
// block's output depends on its four pixels alone, so converting a frame
// whole or only its changed blocks gives the same bytes.
// A video frame over a retained layer differs from the one before it in a
// few percent of its pixels; the converter keeps the last frame's RGBA and
// converts only the blocks of 2 rows × 32 pixels that differ from it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "media/image_view.hpp"

namespace rollspin::media {

struct Yuv420Planes {
  std::uint8_t* y = nullptr;
  std::uint8_t* u = nullptr;  // Cb, (width/2) × (height/2)
  std::uint8_t* v = nullptr;  // Cr
  std::uint8_t* a = nullptr;  // alpha, width × height; nullptr: no alpha plane
  std::ptrdiff_t yStride = 0, uStride = 0, vStride = 0, aStride = 0;
};

class Yuv420Converter {
 public:
  static constexpr int kBlockWidth = 32;  // pixels; a block is 2 rows high

  // Width and height must be even (the caller checks: BadInput there).
  // `threads` > 1 splits each frame's row pairs into that many bands, one
  // thread each; the bytes do not depend on it (the output is row-local).
  Yuv420Converter(int width, int height, int threads = 1);

  // Writes `frame` (the converter's size) into `planes`. After the first
  // call, `planes` must still hold what the previous call wrote there: only
  // the blocks whose RGBA differs from the previous frame's are written.
  // Returns the number of pixels converted.
  long long convert(const ImageView& frame, const Yuv420Planes& planes);

  // The next convert() converts the whole frame (the planes were replaced).
  void forget() { havePrevious_ = false; }

 private:
  // Row pairs [firstPair, endPair): converts their changed blocks.
  long long convertRows(const ImageView& frame, const Yuv420Planes& planes, int firstPair, int endPair);

  int width_, height_, threads_;
  std::vector<std::uint8_t> previous_;  // the last frame, top-down, packed RGBA
  bool havePrevious_ = false;
};

// One pixel's limited-range BT.709 luma, and the chroma of a 2×2 block from
// the sums of its four pixels' R, G and B (0 … 1020): the converter's
// arithmetic, for tests.
[[nodiscard]] std::uint8_t bt709Luma(int r, int g, int b);
[[nodiscard]] std::uint8_t bt709Cb(int rSum4, int gSum4, int bSum4);
[[nodiscard]] std::uint8_t bt709Cr(int rSum4, int gSum4, int bSum4);

}  // namespace rollspin::media
