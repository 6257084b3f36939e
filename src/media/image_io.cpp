#include "media/image_io.hpp"

#include <fmt/format.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
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

void writePng(const std::filesystem::path& file, const ImageView& image, PngChannels channels,
              const OutputMetadata* metadata) {
  const int comp = channels == PngChannels::Rgba ? 4 : 3;
  const std::vector<std::uint8_t> packed = packRows(image, comp);
  std::string bytes;
  if (stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, comp, packed.data(), image.width * comp) ==
      0) {
    throw runtimeError({file.string()}, "PNG encoding failed ({}x{})", image.width, image.height);
  }
  if (metadata) bytes = withPngMetadata(bytes, *metadata);
  AtomicFile out(file);
  out.write(bytes);
  out.commit();
}

void writeJpeg(const std::filesystem::path& file, const ImageView& image, int quality, const OutputMetadata* metadata) {
  const std::vector<std::uint8_t> packed = packRows(image, 3);
  std::string bytes;
  if (stbi_write_jpg_to_func(appendBytes, &bytes, image.width, image.height, 3, packed.data(), quality) == 0)
    throw runtimeError({file.string()}, "JPEG encoding failed ({}x{})", image.width, image.height);
  if (metadata) bytes = withJpegMetadata(bytes, *metadata);
  AtomicFile out(file);
  out.write(bytes);
  out.commit();
}

namespace {

// Debian 12's stb_image (2.27) writes past its 257-entry size list when a
// JPEG's Huffman table (DHT) counts more than 256 codes (upstream checks
// since 2.28), and decodes a scan with a table that no DHT defined: its
// tables live in a malloc'ed struct, so it then reads symbol ids from
// uninitialised memory, millions of entries outside the list (both found by
// fuzz_image). Such files are refused here first: the markers are walked as
// stb_image walks them (each segment by its length, entropy-coded data up to
// the next 0xFF that is not stuffing or a restart), each DHT table's 16
// counts are added up, and each scan's tables must have been defined (a
// baseline scan uses its DC and AC tables; a progressive one its DC table
// in a first DC scan, its AC table in an AC scan). The reason, or nothing
// when every table fits (or it is not a JPEG).
std::string jpegHuffmanTableFault(std::string_view bytes) {
  const auto at = [&](std::size_t k) -> unsigned {
    return k < bytes.size() ? static_cast<unsigned char>(bytes[k]) : 0U;
  };
  // stb_image skips fill bytes (0xFF) before every marker, SOI included:
  // "FF FF D8" is a JPEG to it (found by fuzz_image), so it is one here.
  if (at(0) != 0xFF) return {};  // not a JPEG
  std::size_t start = 1;
  while (start < bytes.size() && at(start) == 0xFF) ++start;
  if (at(start) != 0xD8) return {};  // not a JPEG
  std::size_t pos = start + 1;
  unsigned definedDc = 0, definedAc = 0;  // bit k: table k defined
  bool progressive = false;
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
    if (marker == 0xC2) progressive = true;  // SOF2
    if (marker == 0xDA) {                    // SOS: Ns, then (Cs, Td << 4 | Ta) per component, Ss, Se, Ah << 4 | Al
      const std::size_t components = at(pos + 4);
      const unsigned ss = at(pos + 5 + 2 * components), ah = at(pos + 7 + 2 * components) >> 4;
      const bool usesDc = !progressive || (ss == 0 && ah == 0), usesAc = !progressive || ss > 0;
      for (std::size_t c = 0; c < components; ++c) {
        const unsigned tables = at(pos + 6 + 2 * c), dc = tables >> 4, ac = tables & 15;
        if ((usesDc && dc < 4 && !(definedDc & (1u << dc))) || (usesAc && ac < 4 && !(definedAc & (1u << ac))))
          return "a scan that uses a Huffman table no DHT segment defined";
      }
    }
    if (marker == 0xC4) {
      // stb_image reads tables while the segment has bytes left (zeros past the end).
      long left = static_cast<long>(length) - 2;
      std::size_t q = pos + 4;
      while (left > 0 && q < bytes.size()) {
        unsigned codes = 0;
        for (std::size_t i = 0; i < 16; ++i) codes += at(q + 1 + i);
        if (codes > 256) return "a Huffman table of more than 256 codes";
        const unsigned tableClass = at(q) >> 4, index = at(q) & 15;
        if (index < 4) (tableClass == 0 ? definedDc : definedAc) |= 1u << index;
        q += 17 + codes;
        left -= static_cast<long>(17 + codes);
      }
    }
    pos += 2 + std::max<std::size_t>(length, 2);
  }
  return {};
}

// stb_image (2.27) collects a PNG's IDAT chunks in a buffer that it grows
// to each chunk's claimed length, up to 1 GiB, before reading the data: a
// file of a few hundred bytes could make it allocate 2 GiB (found by
// fuzz_image). A chunk whose data runs past the end of the file is refused
// here first; a valid PNG never has one. The name of the first such chunk,
// its claim and what is left, or nothing when every chunk fits (or it is not
// a PNG).
std::string pngChunkPastTheEnd(std::string_view bytes) {
  constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
  if (bytes.substr(0, 8) != kSignature) return {};
  std::size_t pos = 8;
  while (pos + 8 <= bytes.size()) {
    std::uint64_t length = 0;
    for (std::size_t i = 0; i < 4; ++i) length = (length << 8) | static_cast<unsigned char>(bytes[pos + i]);
    const std::string_view type = bytes.substr(pos + 4, 4);
    const std::size_t left = bytes.size() - (pos + 8);
    if (length > left) {
      std::string printable;
      for (const char c : type) printable += (c >= 0x20 && c < 0x7f) ? c : '?';
      return fmt::format("its '{}' chunk claims {} bytes, {} are left", printable, length, left);
    }
    if (type == "IEND") break;
    pos += 8 + static_cast<std::size_t>(length) + 4;  // the data and its CRC
  }
  return {};
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

Image decodeImage(std::string_view bytes, const std::string& name, const SourceLoc& where, std::int64_t maxPixels) {
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw badInput(where, "'{}' is larger than the 2 GiB an image file may have", name);
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(bytes.size());
  // Before any stb_image call: reading the header builds the tables too.
  if (const std::string fault = jpegHuffmanTableFault(bytes); !fault.empty())
    throw badInput(where, "'{}' is not a readable PNG or JPG image ({})", name, fault);
  if (const std::string past = pngChunkPastTheEnd(bytes); !past.empty())
    throw badInput(where, "'{}' is not a readable PNG or JPG image ({})", name, past);
  int w = 0, h = 0, comp = 0;
  // The header first: a few bytes may claim an image of gigabytes, which
  // would be allocated before the data is found missing.
  if (stbi_info_from_memory(data, size, &w, &h, &comp) != 0 && static_cast<std::int64_t>(w) * h > maxPixels)
    throw badInput(where, "'{}' claims {}x{} pixels, more than the {} an image may have", name, w, h, maxPixels);
  stbi_uc* pixels = stbi_load_from_memory(data, size, &w, &h, &comp, 4);
  if (pixels == nullptr)
    throw badInput(where, "'{}' is not a readable PNG or JPG image ({})", name, stbi_failure_reason());
  Image img(w, h);
  std::copy(pixels, pixels + static_cast<std::size_t>(w) * h * 4, img.rgba.begin());
  stbi_image_free(pixels);
  return img;
}

}  // namespace rollspin::media
