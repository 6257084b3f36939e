// Image files: PNG and JPEG writing (stb_image_write, through AtomicFile so a failed
// write leaves nothing) and PNG/JPG loading (stb_image) into RGBA.
#pragma once

#include <filesystem>

#include "core/error.hpp"
#include "media/image_view.hpp"

namespace rollspin::media {

enum class PngChannels { Rgb, Rgba };

// Writes a PNG; Rgb drops the alpha channel. Deterministic: the same pixels
// give the same bytes. Throws Error (Runtime) when the file cannot be written.
void writePng(const std::filesystem::path& file, const ImageView& image, PngChannels channels = PngChannels::Rgb);

// Writes a baseline JPEG (no alpha: it is dropped) at `quality` in [1, 100],
// through AtomicFile like writePng.
void writeJpeg(const std::filesystem::path& file, const ImageView& image, int quality);

// Loads a PNG or JPG as RGBA (top-down). A missing, unreadable or corrupt
// file throws Error (BadInput) at `where` (the scene key that named it).
[[nodiscard]] Image loadImage(const std::filesystem::path& file, const SourceLoc& where);

}  // namespace rollspin::media
