#include "jobs/clip_captions.hpp"

#include <algorithm>

namespace rollspin::jobs {

namespace {

// The words on a frame of segment `index` (a scene without segments: the title alone).
std::string frameText(const scene::SceneSpec& spec, std::size_t index) {
  const scene::SegmentSpec* segment =
      spec.segments.empty() ? nullptr : &spec.segments[std::min(index, spec.segments.size() - 1)];
  const std::string& title = segment != nullptr && segment->title ? *segment->title : spec.render.title;
  const std::string caption = segment != nullptr ? segment->caption : std::string();
  if (title.empty() || caption.empty()) return title + caption;
  return title + "\n" + caption;
}

}  // namespace

media::SubtitleCues clipCaptionCues(const scene::SceneSpec& spec, const motion::FrameClock& clock) {
  media::SubtitleCues cues;
  const long long frames = clock.frameCount();
  long long first = 0;
  std::size_t segment = frames > 0 ? clock.place(0).segment : 0;
  // The text changes only where the segment does: one cue per run of frames.
  for (long long k = 1; k <= frames; ++k) {
    const std::size_t next = k < frames ? clock.place(k).segment : segment + 1;
    if (next == segment) continue;
    media::appendCue(cues, {first, k, frameText(spec, segment)});
    first = k;
    segment = next;
  }
  return cues;
}

}  // namespace rollspin::jobs
