// Mp4Writer — H.264 in an MP4 file through the FFmpeg libraries, in-process
// (libavformat + libavcodec/libx264 + libswscale), following FFmpeg's
// doc/examples/mux.c: send_frame / receive_packet, packet timestamps
// rescaled from the codec's den/num (one tick per frame) to the stream's time base, a flushed
// encoder (null frame) and the trailer. RGBA is converted to yuv420p with the
// BT.709 matrix (full-range RGB → limited-range YUV) and tagged BT.709
// (colour space, primaries, transfer) and limited range, so browsers and
// players show the colours that were rendered; "+faststart" puts the index
// first so a browser can start playing before the download ends.
// The file is written under a temporary name in the same folder and renamed
// on finish(); a device (e.g. /dev/full) is written in place.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "media/container_tags.hpp"
#include "media/frame_sink.hpp"

namespace rollspin::media {

struct Mp4Settings {
  int width = 0, height = 0;  // both even (yuv420p halves the chroma planes)
  int fpsNum = 30, fpsDen = 1;  // frames per second as a rational (30000/1001 for NTSC 29.97)
  double crf = 18.0;           // constant rate factor, 0 … 51
  std::string preset = "medium";
  std::string encoder = "libx264";
  std::optional<ContainerTags> tags = std::nullopt;  // container metadata (a render's identity for `join`)
};

class Mp4Writer final : public FrameSink {
 public:
  // Opens the encoder and the output and writes the header. Throws Error:
  // BadInput for an odd or zero size, Runtime when the encoder is missing or
  // refuses the settings, or the file cannot be created.
  Mp4Writer(std::filesystem::path finalPath, const Mp4Settings& settings);
  ~Mp4Writer() override;  // unfinished: removes the temporary file
  Mp4Writer(const Mp4Writer&) = delete;
  Mp4Writer& operator=(const Mp4Writer&) = delete;

  // The frame must have the writer's size; alpha is ignored.
  void write(const ImageView& frame) override;
  std::filesystem::path finish() override;
  std::filesystem::path finishPartial() override;  // "NAME.partial.mp4"
  [[nodiscard]] long long framesWritten() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// "dir/NAME.partial.EXT" for "dir/NAME.EXT".
[[nodiscard]] std::filesystem::path partialName(const std::filesystem::path& finalPath);

}  // namespace rollspin::media
