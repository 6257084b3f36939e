#include "media/subtitle_track.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace rollspin::media {

namespace fs = std::filesystem;

void appendCue(SubtitleCues& cues, SubtitleCue cue) {
  if (cue.endFrame <= cue.firstFrame || cue.text.empty()) return;
  if (!cues.empty() && cues.back().endFrame == cue.firstFrame && cues.back().text == cue.text) {
    cues.back().endFrame = cue.endFrame;
    return;
  }
  cues.push_back(std::move(cue));
}

SubtitleCues cuesOfPart(const SubtitleCues& cues, long long first, long long last) {
  SubtitleCues out;
  for (const SubtitleCue& c : cues) {
    const long long begin = std::max(c.firstFrame, first), end = std::min(c.endFrame, last + 1);
    if (begin < end) out.push_back({begin - first, end - first, c.text});
  }
  return out;
}

long long frameMilliseconds(long long frame, int fpsNum, int fpsDen) {
  // Exact in 128 bits (10⁷ frames × 1000 × den overflows 64), rounded half up.
  __extension__ using Wide = __int128;
  const Wide scaled = static_cast<Wide>(frame) * 1000 * fpsDen;
  return static_cast<long long>((2 * scaled + fpsNum) / (2 * static_cast<Wide>(fpsNum)));
}

namespace {

std::string clockText(long long ms, char decimal) {
  return fmt::format("{:02}:{:02}:{:02}{}{:03}", ms / 3'600'000, ms / 60'000 % 60, ms / 1000 % 60, decimal, ms % 1000);
}

// A blank line ends a cue in both formats: the text's lines, blank ones left out.
std::vector<std::string> textLines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") != std::string::npos) lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

std::string webvttEscaped(const std::string& line) {
  std::string out;
  for (const char c : line) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string webvttDocument(const SubtitleCues& cues, int fpsNum, int fpsDen) {
  std::string out = "WEBVTT\n\n";
  for (const SubtitleCue& c : cues) {
    out += clockText(frameMilliseconds(c.firstFrame, fpsNum, fpsDen), '.') + " --> " +
           clockText(frameMilliseconds(c.endFrame, fpsNum, fpsDen), '.') + "\n";
    for (const std::string& line : textLines(c.text)) out += webvttEscaped(line) + "\n";
    out += "\n";
  }
  return out;
}

std::string srtDocument(const SubtitleCues& cues, int fpsNum, int fpsDen) {
  std::string out;
  for (std::size_t k = 0; k < cues.size(); ++k) {
    const SubtitleCue& c = cues[k];
    out += fmt::format("{}\n{} --> {}\n", k + 1, clockText(frameMilliseconds(c.firstFrame, fpsNum, fpsDen), ','),
                       clockText(frameMilliseconds(c.endFrame, fpsNum, fpsDen), ','));
    for (const std::string& line : textLines(c.text)) out += line + "\n";
    out += "\n";
  }
  return out;
}

SidecarFormats parseSidecarFormats(const std::string& value, const std::string& flag) {
  if (value == "vtt") return SidecarFormats::Vtt;
  if (value == "srt") return SidecarFormats::VttAndSrt;
  if (value == "none") return SidecarFormats::None;
  throw badInput({flag + " " + value}, "expected vtt (NAME.vtt beside the video), srt (NAME.vtt and NAME.srt) or none");
}

SubtitleSidecars::SubtitleSidecars(const fs::path& video, SidecarFormats formats, const SubtitleCues& cues, int fpsNum,
                                   int fpsDen) {
  std::error_code ec;
  const auto status = fs::status(video, ec);
  const bool device = !ec && fs::exists(status) && !fs::is_regular_file(status);
  if (formats == SidecarFormats::None || device || cues.empty()) return;
  auto add = [&](const char* extension, const std::string& text) {
    fs::path path = video;
    path.replace_extension(extension);
    files_.push_back(std::make_unique<AtomicFile>(path));
    files_.back()->write(text);
    // A full disk shows here, before the video is renamed into place, not
    // in commit() after it.
    if (std::fflush(files_.back()->handle()) != 0 || std::ferror(files_.back()->handle()) != 0)
      throw runtimeError({path.string()}, "write failed: {}", std::strerror(errno));
  };
  add(".vtt", webvttDocument(cues, fpsNum, fpsDen));
  if (formats == SidecarFormats::VttAndSrt) add(".srt", srtDocument(cues, fpsNum, fpsDen));
}

SubtitleSidecars::~SubtitleSidecars() = default;

void SubtitleSidecars::commit() {
  for (const auto& f : files_) f->commit();
}

std::vector<fs::path> SubtitleSidecars::paths() const {
  std::vector<fs::path> out;
  for (const auto& f : files_) out.push_back(f->finalPath());
  return out;
}

std::string cueTextOfPacket(std::string_view payload, bool movText) {
  if (!movText) return std::string(payload);
  if (payload.size() < 2) return {};
  const std::size_t length = (static_cast<unsigned char>(payload[0]) << 8) | static_cast<unsigned char>(payload[1]);
  return std::string(payload.substr(2, std::min(length, payload.size() - 2)));
}

}  // namespace rollspin::media
