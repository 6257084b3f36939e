// clipCaptionCues — what a clip's pixels say in words, as subtitle cues
// (media/subtitle_track.hpp): on frame k the text is the title shown there
// (the segment's title, else render.title) and, on a line below it, the
// storyboard segment's caption (SceneDrawer burns the same two), with the
// segment of frame k from the FrameClock that times the frames (the opening
// hold belongs to the first segment, the closing hold to the last). A cue
// covers each run of frames with one text; frames with neither are in none.
#pragma once

#include "media/subtitle_track.hpp"
#include "motion/frame_clock.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::jobs {

[[nodiscard]] media::SubtitleCues clipCaptionCues(const scene::SceneSpec& spec, const motion::FrameClock& clock);

}  // namespace rollspin::jobs
