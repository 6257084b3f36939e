#include "media/png_sequence.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <system_error>

#include "core/error.hpp"
#include "core/temp_files.hpp"
#include "media/sink_factory.hpp"

namespace rollspin::media {

namespace fs = std::filesystem;

namespace {

// "frames/", "./frames" and "." name a folder whose own name we need (for
// the staging and .partial siblings).
fs::path namedFolder(const fs::path& folder) {
  fs::path p = folder.lexically_normal();
  if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();
  if (p.empty() || p.filename() == "." || p.filename() == "..") {
    p = fs::absolute(p).lexically_normal();
    if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();
  }
  return p;
}

}  // namespace

PngSequenceWriter::PngSequenceWriter(fs::path folder, long long firstIndex, PngChannels channels,
                                     PngSequenceScope scope)
    : folder_(namedFolder(folder)), first_(firstIndex), channels_(channels), scope_(scope) {
  const SourceLoc where{folder_.string()};
  std::error_code ec;
  if (fs::exists(folder_, ec) && !fs::is_directory(folder_, ec))
    throw runtimeError(where, "a PNG sequence needs a folder, but this is a file");
  if (!folder_.has_filename()) throw runtimeError(where, "a PNG sequence needs a named folder, not the root");
  removeStaleTemporaries(folder_);  // frames of a run that died hard
  staging_ = temporaryPathFor(folder_);
  fs::create_directories(staging_, ec);
  registerTemporary(staging_, folder_, true);
  if (ec) throw runtimeError(where, "cannot create the frame folder: {}", ec.message());
}

PngSequenceWriter::~PngSequenceWriter() {
  std::error_code ec;
  if (!staging_.empty()) fs::remove_all(staging_, ec);  // ours alone: a unique hidden name
  if (!staging_.empty()) unregisterTemporary(staging_);
}

fs::path PngSequenceWriter::framePath(const fs::path& folder, long long index) {
  return folder / fmt::format("frame_{:05d}.png", index);
}

long long PngSequenceWriter::frameIndex(const std::string& name) {
  constexpr std::string_view prefix = "frame_", suffix = ".png";
  if (name.size() <= prefix.size() + suffix.size() || !name.starts_with(prefix) || !name.ends_with(suffix)) return -1;
  const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  if (digits.size() > 12) return -1;
  long long index = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') return -1;
    index = index * 10 + (c - '0');
  }
  // Exactly what framePath writes: "frame_7.png" or "frame_000007.png" are not ours.
  return fmt::format("{:05d}", index) == digits ? index : -1;
}

void PngSequenceWriter::write(const ImageView& frame) {
  writePng(framePath(staging_, first_ + written_), frame, channels_);
  ++written_;
}

template <typename Stale>
void PngSequenceWriter::moveFramesInto(const fs::path& target, Stale stale) {
  const SourceLoc where{target.string()};
  std::error_code ec;
  if (fs::exists(target, ec) && !fs::is_directory(target, ec))
    throw runtimeError(where, "cannot move the frames here: it is a file");
  fs::create_directories(target, ec);
  if (ec) throw runtimeError(where, "cannot create the frame folder: {}", ec.message());
  std::vector<fs::path> outdated;
  for (const auto& entry : fs::directory_iterator(target, ec)) {
    const long long index = frameIndex(entry.path().filename().string());
    if (index >= 0 && stale(index) && entry.is_regular_file(ec)) outdated.push_back(entry.path());
  }
  if (ec) throw runtimeError(where, "cannot list the frame folder: {}", ec.message());
  for (const auto& p : outdated) {
    fs::remove(p, ec);
    if (ec) throw runtimeError(SourceLoc{p.string()}, "cannot remove a stale frame: {}", ec.message());
  }
  for (long long k = first_; k < first_ + written_; ++k) {
    fs::rename(framePath(staging_, k), framePath(target, k), ec);
    if (ec)
      throw runtimeError(SourceLoc{framePath(target, k).string()}, "cannot move the frame into place: {}",
                         ec.message());
  }
  fs::remove_all(staging_, ec);
  unregisterTemporary(staging_);
  staging_.clear();
}

fs::path PngSequenceWriter::finish() {
  const long long end = first_ + written_;
  if (scope_ == PngSequenceScope::WholeClip) moveFramesInto(folder_, [end](long long index) { return index >= end; });
  else moveFramesInto(folder_, [](long long) { return false; });
  return folder_;
}

fs::path PngSequenceWriter::finishPartial() {
  if (written_ == 0) return {};  // the destructor removes the empty staging folder
  fs::path partial = folder_;
  partial += ".partial";
  // An older interrupted render's frames would mix with these: all ours go.
  moveFramesInto(partial, [](long long) { return true; });
  return partial;
}

std::unique_ptr<FrameSink> openPngFolderSink(const SinkOptions& o) {
  return std::make_unique<PngSequenceWriter>(o.path, o.firstIndex, o.alpha ? PngChannels::Rgba : PngChannels::Rgb,
                                             o.wholeClip ? PngSequenceScope::WholeClip : PngSequenceScope::Part);
}

}  // namespace rollspin::media
