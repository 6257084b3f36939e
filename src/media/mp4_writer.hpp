// Mp4Writer — H.264 (libx264) in yuv420p in an MP4 file, a VideoWriter
// (video_writer.hpp: temporary name + rename, BT.709, partial output).
// "+faststart" puts the index first so a browser can start playing before
// the download ends; "+write_colr" writes the colour tags.
#pragma once

#include <filesystem>
#include <string>

#include "media/video_writer.hpp"

namespace rollspin::media {

struct Mp4Settings {
  int width = 0, height = 0;    // both even (yuv420p halves the chroma planes)
  int fpsNum = 30, fpsDen = 1;  // frames per second as a rational (30000/1001 for NTSC 29.97)
  double crf = 18.0;            // constant rate factor, 0 … 51
  std::string preset = "medium";
  std::string encoder = "libx264";
};

[[nodiscard]] VideoSettings mp4VideoSettings(const Mp4Settings& settings);

class Mp4Writer final : public VideoWriter {
 public:
  // Throws Error: BadInput for an odd or zero size, Runtime when the encoder
  // is missing or refuses the settings, or the file cannot be created.
  Mp4Writer(std::filesystem::path finalPath, const Mp4Settings& settings)
      : VideoWriter(std::move(finalPath), mp4VideoSettings(settings)) {}
};

}  // namespace rollspin::media
