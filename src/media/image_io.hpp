// Image files: PNG and JPEG writing (stb_image_write, through AtomicFile so a failed
// write leaves nothing) and PNG/JPG loading (stb_image) into RGBA.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "media/image_view.hpp"
#include "media/output_metadata.hpp"

namespace rollspin::media {

enum class PngChannels { Rgb, Rgba };

// Writes a PNG; Rgb drops the alpha channel. Deterministic: the same pixels
// give the same bytes. Throws Error (Runtime) when the file cannot be written.
// `metadata`: also the iTXt chunks of output_metadata.hpp (null: none).
void writePng(const std::filesystem::path& file, const ImageView& image, PngChannels channels = PngChannels::Rgb,
              const OutputMetadata* metadata = nullptr);

// Writes a baseline JPEG (no alpha: it is dropped) at `quality` in [1, 100],
// through AtomicFile like writePng.
void writeJpeg(const std::filesystem::path& file, const ImageView& image, int quality,
               const OutputMetadata* metadata = nullptr);

// Loads a PNG or JPG as RGBA (top-down). A missing, unreadable or corrupt
// file throws Error (BadInput) at `where` (the scene key that named it).
[[nodiscard]] Image loadImage(const std::filesystem::path& file, const SourceLoc& where);

// The most pixels a loaded image may have (16384 x 16384: a texture's
// limit, and 1 GiB of RGBA): a larger claim in a header is refused before
// anything is allocated.
inline constexpr std::int64_t kMaxImagePixels = std::int64_t{16384} * 16384;

// loadImage's decoder, on a file's bytes; `name` is the file in messages.
// Any bytes at all: an image, or Error (BadInput), never a crash (fuzzed:
// tests/fuzz/fuzz_image.cpp, which lowers maxPixels: a few bytes may claim
// the whole 1 GiB, which is work, not a bug, past libFuzzer's memory limit).
[[nodiscard]] Image decodeImage(std::string_view bytes, const std::string& name, const SourceLoc& where,
                                std::int64_t maxPixels = kMaxImagePixels);

}  // namespace rollspin::media
