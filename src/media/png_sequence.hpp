// PngSequenceWriter — an animation as a folder of PNG frames,
// FOLDER/frame_00000.png, frame_00001.png, … numbered by the frame's index in
// the whole clip (so the parts of a split render land side by side).
// Frames are written into a hidden staging folder beside it
// (.FOLDER.PID.tmp/) and moved into FOLDER/ when the render completes, so
// FOLDER/ never mixes a finished render's frames with a half-done one:
//   finish(), whole clip: the frames replace FOLDER's; frame_NNNNN.png files
//     of an earlier, longer render (our exact naming, index ≥ the new count)
//     are removed, so `ffmpeg -i frame_%05d.png` cannot pick up stale frames;
//     any other file is left alone.
//   finish(), part of a clip (--frames A:B): only frames A … B are replaced;
//     every other frame stays (that is how a render is split across machines).
//   finishPartial() (interrupted): the complete frames so far go to
//     FOLDER.partial/ (its older frame_NNNNN.png files are removed first);
//     FOLDER/ is untouched. Nothing when no frame was written.
//   destroyed unfinished (an error): the staging folder is removed.
#pragma once

#include <filesystem>

#include "media/frame_sink.hpp"
#include "media/image_io.hpp"

namespace rollspin::media {

enum class PngSequenceScope { WholeClip, Part };

class PngSequenceWriter final : public FrameSink {
 public:
  // Creates the staging folder (and FOLDER's parents); throws Error (Runtime)
  // when it cannot, or when FOLDER is an existing file.
  PngSequenceWriter(std::filesystem::path folder, long long firstIndex, PngChannels channels, PngSequenceScope scope);
  ~PngSequenceWriter() override;
  PngSequenceWriter(const PngSequenceWriter&) = delete;
  PngSequenceWriter& operator=(const PngSequenceWriter&) = delete;

  void write(const ImageView& frame) override;
  std::filesystem::path finish() override;
  std::filesystem::path finishPartial() override;
  [[nodiscard]] long long framesWritten() const override { return written_; }

  // FOLDER/frame_%05d.png
  [[nodiscard]] static std::filesystem::path framePath(const std::filesystem::path& folder, long long index);
  // The index of a file name this writer produces ("frame_00042.png" → 42),
  // or -1 for any other name ("frame_42.png", "frame_00042.png.bak", …).
  [[nodiscard]] static long long frameIndex(const std::string& fileName);

 private:
  // Moves the staged frames into `target` (created), after removing there
  // our frames that `stale` says are outdated.
  template <typename Stale>
  void moveFramesInto(const std::filesystem::path& target, Stale stale);

  std::filesystem::path folder_, staging_;
  long long first_;
  PngChannels channels_;
  PngSequenceScope scope_;
  long long written_ = 0;
};

}  // namespace rollspin::media
