// FrameSink — where an animation's frames go: one ImageView at a time, in
// order, never knowing where the pixels came from. Implementations: an MP4
// file (mp4_writer.hpp) and a folder of PNG frames (png_sequence.hpp).
// A sink is either finished (the output is complete at its final name),
// finished early (what was written so far, as a valid output under a name
// that says so), or destroyed unfinished (it removes what it started).
#pragma once

#include <filesystem>

#include "media/image_view.hpp"

namespace rollspin::media {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Appends one frame; throws Error (Runtime) when it cannot be written.
  virtual void write(const ImageView& frame) = 0;
  // Completes the output at its final name and returns that name.
  virtual std::filesystem::path finish() = 0;
  // Completes the frames written so far as a shorter, valid output under a
  // name saying it is partial, and returns that name; returns an empty path
  // (and leaves nothing) when no frame was written.
  virtual std::filesystem::path finishPartial() = 0;
  [[nodiscard]] virtual long long framesWritten() const = 0;
};

}  // namespace rollspin::media
