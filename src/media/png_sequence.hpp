// PngSequenceWriter — an animation as a folder of PNG frames,
// FOLDER/frame_00000.png, frame_00001.png, … numbered by the frame's index in
// the whole clip (so the parts of a split render land side by side). Each
// file is written through AtomicFile: an interrupted run leaves complete
// frames only. Existing frames with other numbers are left alone.
#pragma once

#include <filesystem>

#include "media/frame_sink.hpp"
#include "media/image_io.hpp"

namespace rollspin::media {

class PngSequenceWriter final : public FrameSink {
 public:
  // Creates the folder (and its parents); throws Error (Runtime) when it
  // cannot, or when the path is an existing file.
  PngSequenceWriter(std::filesystem::path folder, long long firstIndex, PngChannels channels);

  void write(const ImageView& frame) override;
  std::filesystem::path finish() override { return folder_; }
  // The frames written so far stay where they are: each one is complete.
  std::filesystem::path finishPartial() override { return written_ > 0 ? folder_ : std::filesystem::path{}; }
  [[nodiscard]] long long framesWritten() const override { return written_; }

  // FOLDER/frame_%05d.png
  [[nodiscard]] static std::filesystem::path framePath(const std::filesystem::path& folder, long long index);

 private:
  std::filesystem::path folder_;
  long long next_;
  PngChannels channels_;
  long long written_ = 0;
};

}  // namespace rollspin::media
