#include "media/png_sequence.hpp"

#include <fmt/format.h>

#include <system_error>

#include "core/error.hpp"

namespace rollspin::media {

namespace fs = std::filesystem;

PngSequenceWriter::PngSequenceWriter(fs::path folder, long long firstIndex, PngChannels channels)
    : folder_(std::move(folder)), next_(firstIndex), channels_(channels) {
  std::error_code ec;
  if (fs::exists(folder_, ec) && !fs::is_directory(folder_, ec))
    throw runtimeError(SourceLoc{folder_.string()}, "a PNG sequence needs a folder, but this is a file");
  fs::create_directories(folder_, ec);
  if (ec) throw runtimeError(SourceLoc{folder_.string()}, "cannot create the frame folder: {}", ec.message());
}

fs::path PngSequenceWriter::framePath(const fs::path& folder, long long index) {
  return folder / fmt::format("frame_{:05d}.png", index);
}

void PngSequenceWriter::write(const ImageView& frame) {
  writePng(framePath(folder_, next_), frame, channels_);
  ++next_;
  ++written_;
}

}  // namespace rollspin::media
