// GifWriter — an animated GIF through libavfilter's palettegen/paletteuse
// and libavcodec's GIF encoder (a VideoWriter: temporary name + rename,
// NAME.partial.gif when interrupted).
// Two passes: GIF holds 256 colours, chosen here from the clip's own: the
// caller first shows the frames previewFrames() names (≤ 60, evenly spread
// over the clip) to palettegen (a colour histogram: memory flat in the clip's
// length), then every frame goes through paletteuse with that one palette,
// ordered (Bayer) dithering so the backdrop's gradient does not band and a
// still background stays the same pixels from frame to frame (the encoder
// then stores only the changed rectangle). Timestamps become 1/100 s
// delays (the GIF muxer); loop forever or play once. Alpha is 1-bit: a
// pixel is transparent below alpha 128.
#pragma once

#include <optional>

#include <filesystem>
#include <memory>

#include "media/output_metadata.hpp"
#include "media/video_writer.hpp"

namespace rollspin::media {

struct GifSettings {
  int width = 0, height = 0;
  int fpsNum = 25, fpsDen = 1;
  bool loop = true;
  bool alpha = false;
  // Comment extensions added when finished (output_metadata.hpp); a partial GIF has none.
  std::optional<OutputMetadata> metadata;
};

class GifWriter final : public VideoWriter {
 public:
  GifWriter(std::filesystem::path finalPath, const GifSettings& settings);
  ~GifWriter() override;

  [[nodiscard]] std::vector<long long> previewFrames(long long count) const override;
  void preview(const ImageView& frame) override;  // before the first write()
  void write(const ImageView& frame) override;
  std::filesystem::path finish() override;
  std::filesystem::path finishPartial() override;

  static constexpr long long kPaletteFrames = 60;

 private:
  struct Graphs;
  std::unique_ptr<Graphs> graphs_;
};

}  // namespace rollspin::media
