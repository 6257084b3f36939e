#include "media/image_io.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <limits>
#include <iterator>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"

namespace rollspin::media {

namespace {
void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}


// stb wants tightly packed top-down rows of 3 or 4 channels: repack once.
std::vector<std::uint8_t> packRows(const ImageView& image, int comp) {
  std::vector<std::uint8_t> packed(static_cast<std::size_t>(image.width) * image.height * comp);
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* src = image.rowFromTop(y);
    std::uint8_t* dst = packed.data() + static_cast<std::size_t>(y) * image.width * comp;
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < comp; ++c) dst[x * comp + c] = src[x * 4 + c];
  }
  return packed;
}
}  // namespace

void writePng(const std::filesystem::path& file, const ImageView& image, PngChannels channels) {
  const int comp = channels == PngChannels::Rgba ? 4 : 3;
  const std::vector<std::uint8_t> packed = packRows(image, comp);
  std::string bytes;
  if (stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, comp, packed.data(),
                             image.width * comp) == 0) {
    throw runtimeError({file.string()}, "PNG encoding failed ({}x{})", image.width, image.height);
  }
  AtomicFile out(file);
  out.write(bytes);
  out.commit();
}

void writeJpeg(const std::filesystem::path& file, const ImageView& image, int quality) {
  const std::vector<std::uint8_t> packed = packRows(image, 3);
  std::string bytes;
  if (stbi_write_jpg_to_func(appendBytes, &bytes, image.width, image.height, 3, packed.data(), quality) == 0)
    throw runtimeError({file.string()}, "JPEG encoding failed ({}x{})", image.width, image.height);
  AtomicFile out(file);
  out.write(bytes);
  out.commit();
}

namespace {

// Debian 12's stb_image (2.27) writes past its 257-entry size list when a
// JPEG's Huffman table (DHT) counts more than 256 codes (found by
// fuzz_image; upstream checks since 2.28). Such a table is refused here
// first: the markers are walked as stb_image walks them (each segment by its
// length, entropy-coded data up to the next 0xFF that is not stuffing or a
// restart), and each DHT table's 16 counts are added up.
bool jpegHuffmanTablesFit(std::string_view bytes) {
  const auto at = [&](std::size_t k) -> unsigned { return k < bytes.size() ? static_cast<unsigned char>(bytes[k]) : 0U; };
  // stb_image skips fill bytes (0xFF) before every marker, SOI included:
  // "FF FF D8" is a JPEG to it (found by fuzz_image), so it is one here.
  if (at(0) != 0xFF) return true;  // not a JPEG
  std::size_t start = 1;
  while (start < bytes.size() && at(start) == 0xFF) ++start;
  if (at(start) != 0xD8) return true;  // not a JPEG
  std::size_t pos = start + 1;
  while (pos + 1 < bytes.size()) {
    const unsigned marker = at(pos + 1);
    if (at(pos) != 0xFF || marker == 0xFF) {  // entropy-coded data, or a fill byte
      ++pos;
      continue;
    }
    if (marker == 0x00 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8)) {  // stuffing, TEM, RSTn, SOI
      pos += 2;
      continue;
    }
    if (marker == 0xD9) break;  // EOI
    const std::size_t length = (at(pos + 2) << 8) | at(pos + 3);
    if (marker == 0xC4) {
      // stb_image reads tables while the segment has bytes left (zeros past the end).
      long left = static_cast<long>(length) - 2;
      std::size_t q = pos + 4;
      while (left > 0 && q < bytes.size()) {
        unsigned codes = 0;
        for (std::size_t i = 0; i < 16; ++i) codes += at(q + 1 + i);
        if (codes > 256) return false;
        q += 17 + codes;
        left -= static_cast<long>(17 + codes);
      }
    }
    pos += 2 + std::max<std::size_t>(length, 2);
  }
  return true;
}

}  // namespace

Image loadImage(const std::filesystem::path& file, const SourceLoc& where) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec))
    throw badInput(where, "cannot read the image file '{}'", file.string());
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return decodeImage(bytes, file.string(), where);
}

Image decodeImage(std::string_view bytes, const std::string& name, const SourceLoc& where) {
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw badInput(where, "'{}' is larger than the 2 GiB an image file may have", name);
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(bytes.size());
  // Before any stb_image call: reading the header builds the tables too.
  if (!jpegHuffmanTablesFit(bytes))
    throw badInput(where, "'{}' is not a readable PNG or JPG image (a Huffman table of more than 256 codes)", name);
  int w = 0, h = 0, comp = 0;
  // The header first: a few bytes may claim an image of gigabytes, which
  // would be allocated before the data is found missing.
  if (stbi_info_from_memory(data, size, &w, &h, &comp) != 0 &&
      static_cast<std::int64_t>(w) * h > kMaxImagePixels)
    throw badInput(where, "'{}' claims {}x{} pixels, more than the {} an image may have", name, w, h, kMaxImagePixels);
  stbi_uc* pixels = stbi_load_from_memory(data, size, &w, &h, &comp, 4);
  if (pixels == nullptr)
    throw badInput(where, "'{}' is not a readable PNG or JPG image ({})", name, stbi_failure_reason());
  Image img(w, h);
  std::copy(pixels, pixels + static_cast<std::size_t>(w) * h * 4, img.rgba.begin());
  stbi_image_free(pixels);
  return img;
}

}  // namespace rollspin::media
