#include "media/image_io.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <fstream>
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
  int w = 0, h = 0, comp = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                          static_cast<int>(bytes.size()), &w, &h, &comp, 4);
  if (pixels == nullptr)
    throw badInput(where, "'{}' is not a readable PNG or JPG image ({})", file.string(), stbi_failure_reason());
  Image img(w, h);
  std::copy(pixels, pixels + static_cast<std::size_t>(w) * h * 4, img.rgba.begin());
  stbi_image_free(pixels);
  return img;
}

}  // namespace rollspin::media
