// StillImageSink — a still (PNG or JPEG) as a FrameSink of exactly one
// frame, so the still and the animation jobs open their output through the
// same factory. The image is written on finish(), under a temporary name
// and renamed (image_io.hpp); an unfinished or interrupted sink leaves nothing.
#pragma once

#include <filesystem>
#include <optional>

#include "media/frame_sink.hpp"
#include "media/image_io.hpp"

namespace rollspin::media {

enum class StillEncoding { Png, Jpeg };

class StillImageSink final : public FrameSink {
 public:
  // `alpha`: keep the alpha channel (PNG only); `jpegQuality` in [1, 100].
  // `metadata`: written into the file (output_metadata.hpp); nullopt: none.
  StillImageSink(std::filesystem::path file, StillEncoding encoding, bool alpha, int jpegQuality,
                 std::optional<OutputMetadata> metadata = std::nullopt);

  void write(const ImageView& frame) override;  // a second frame is a Runtime error
  std::filesystem::path finish() override;
  std::filesystem::path finishPartial() override { return {}; }  // one frame: complete or nothing
  [[nodiscard]] long long framesWritten() const override { return image_ ? 1 : 0; }

 private:
  std::filesystem::path file_;
  StillEncoding encoding_;
  bool alpha_;
  int jpegQuality_;
  std::optional<Image> image_;
  std::optional<OutputMetadata> metadata_;
};

}  // namespace rollspin::media
