#include "media/image_io.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

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
