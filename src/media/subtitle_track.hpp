// Subtitle cues — a clip's title and captions as text, timed in frames:
// cue [firstFrame, endFrame) shows from firstFrame·den/num s to
// endFrame·den/num s (the frame clock's own times, holds included), so a
// cue starts on the first frame that burns its text and ends after the last.
// The same cues become the in-band track (video_writer: mov_text in MP4 and
// MOV, webvtt in WebM) and the sidecar files NAME.vtt (WebVTT) and NAME.srt
// (SubRip), whose times are milliseconds rounded to nearest. Adjacent cues
// never share a text: appendCue merges them, which also makes a track cut
// at part boundaries (render --shard) whole again in `join`. libav-free.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rollspin {
class AtomicFile;
}

namespace rollspin::media {

struct SubtitleCue {
  long long firstFrame = 0, endFrame = 0;  // [first, end), frames of the clip (or of a part)
  std::string text;                        // lines separated by '\n'
  [[nodiscard]] bool operator==(const SubtitleCue&) const = default;
};
using SubtitleCues = std::vector<SubtitleCue>;

// Appends `cue`, or lengthens the last cue when `cue` continues it (starts
// where it ends, with the same text). Empty cues and empty texts are dropped.
void appendCue(SubtitleCues& cues, SubtitleCue cue);

// The cues that overlap frames [first, last], cut to them and moved so that
// frame `first` is frame 0: the track of a part of the clip.
[[nodiscard]] SubtitleCues cuesOfPart(const SubtitleCues& cues, long long first, long long last);

// Frame k's time in whole milliseconds, rounded to nearest: k·1000·den/num.
[[nodiscard]] long long frameMilliseconds(long long frame, int fpsNum, int fpsDen);

// "WEBVTT\n\n" and one block per cue ("00:00:01.500 --> 00:00:03.000\nText\n\n");
// & < > escaped, blank lines inside a text dropped (a blank line ends a cue).
[[nodiscard]] std::string webvttDocument(const SubtitleCues& cues, int fpsNum, int fpsDen);
// SubRip: numbered blocks, "00:00:01,500 --> 00:00:03,000".
[[nodiscard]] std::string srtDocument(const SubtitleCues& cues, int fpsNum, int fpsDen);

// Which sidecar files a clip gets: `--subtitles vtt|srt|none`; srt writes
// NAME.srt as well as NAME.vtt.
enum class SidecarFormats { Vtt, VttAndSrt, None };
// Throws Error BadInput naming `flag` for any other value.
[[nodiscard]] SidecarFormats parseSidecarFormats(const std::string& value, const std::string& flag);

// The sidecars of `video` (NAME.vtt, NAME.srt beside it), written under
// temporary names by prepare() and renamed into place by commit(), after
// the video itself is in place; destroyed uncommitted, they leave nothing.
// A clip without cues (no title, no caption) or written to a device
// (/dev/null) gets none.
class SubtitleSidecars {
 public:
  SubtitleSidecars(const std::filesystem::path& video, SidecarFormats formats, const SubtitleCues& cues, int fpsNum,
                   int fpsDen);
  ~SubtitleSidecars();
  SubtitleSidecars(const SubtitleSidecars&) = delete;
  SubtitleSidecars& operator=(const SubtitleSidecars&) = delete;
  void commit();
  [[nodiscard]] std::vector<std::filesystem::path> paths() const;

 private:
  std::vector<std::unique_ptr<AtomicFile>> files_;
};

// The text of one in-band packet: mov_text's is a 16-bit big-endian length
// and the UTF-8 text (then optional style boxes), webvtt's the text itself.
[[nodiscard]] std::string cueTextOfPacket(std::string_view payload, bool movText);

}  // namespace rollspin::media
