// Fuzzes the image loaders: the bytes a ball.texture or either side of
// `rollspin compare` may hold, through media::decodeImage (stb_image: PNG,
// JPEG), then what compare does with the image (differences against itself
// and against a small fixed image of another size, SSIM, the heat map).
// Error (BadInput) is a correct answer; crashes, sanitizer reports and other
// exceptions are bugs. Seeds: tests/fuzz/seeds/image, small PNG and JPEG
// files of every kind stb_image reads differently (grey, grey + alpha,
// 1-bit, palette, 8/16-bit RGB, RGBA; JPEG 4:2:0, 4:4:4, grey), made with
//   ffmpeg -f lavfi -i testsrc2=size=12x8:rate=1 -frames:v 1 -pix_fmt FMT FMT.png
// (FMT: rgb24 rgba gray gray16be pal8 rgb48be ya8 monob; yuvj420p,
// yuvj444p and gray, at 16x16, 9x7 and 8x8, for the JPEG files).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "media/image_compare.hpp"
#include "media/image_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rollspin;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    // At most 2048 x 2048: a 4 KiB JPEG may claim the 16384 x 16384 a
    // texture may have, and decoding it under ASan passes libFuzzer's 2 GiB
    // (found by CI's run). That is work, not a bug; the limit is the fuzzer's.
    constexpr std::int64_t kFuzzMaxPixels = std::int64_t{2048} * 2048;
    const media::Image image = media::decodeImage(bytes, "fuzz", SourceLoc{"fuzz"}, kFuzzMaxPixels);
    // Comparing is linear in the pixels (SSIM: 121 taps each): only images
    // small enough to keep the fuzzer fast; the decode above saw them all.
    if (std::int64_t{image.width} * image.height > (1 << 18)) return 0;
    media::Image other(3, 5);
    for (std::size_t k = 0; k < other.rgba.size(); ++k) other.rgba[k] = static_cast<std::uint8_t>(k * 37);
    const media::ImageDifference same = media::compareImages(image.view(), image.view());
    if (same.differingPixels != 0) __builtin_trap();  // an image equals itself
    (void)media::structuralSimilarity(image.view(), image.view());
    (void)media::differenceHeatMap(image.view(), other.view());
    if (image.width == other.width && image.height == other.height)
      (void)media::compareImages(image.view(), other.view());
  } catch (const Error&) {
  }
  return 0;
}
