#include "media/container_tags.hpp"

#include "media/av_library.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace rollspin::media {

namespace {

constexpr const char* kScene = "rollspin_scene_sha256";
constexpr const char* kVersion = "rollspin_version";
constexpr const char* kEncoder = "rollspin_encoder";
constexpr const char* kFrames = "rollspin_frames";
constexpr const char* kClipFrames = "rollspin_clip_frames";

bool parseCount(const std::string& text, long long& out) {
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return !text.empty() && ec == std::errc() && ptr == text.data() + text.size() && out >= 0;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> containerMetadata(const ContainerTags& t) {
  return {{kScene, t.sceneSha256},
          {kVersion, t.version},
          {kEncoder, t.encoderSettings},
          {kFrames, fmt::format("{}-{}", t.firstFrame, t.lastFrame)},
          {kClipFrames, std::to_string(t.clipFrames)}};
}

std::optional<ContainerTags> parseContainerTags(const std::map<std::string, std::string>& metadata,
                                                std::string* error) {
  auto fail = [&](std::string why) -> std::optional<ContainerTags> {
    if (error != nullptr) *error = std::move(why);
    return std::nullopt;
  };
  for (const char* key : {kScene, kVersion, kEncoder, kFrames, kClipFrames})
    if (!metadata.contains(key)) return fail(fmt::format("it has no '{}' tag: not a part rendered by rollspin", key));
  ContainerTags t;
  t.sceneSha256 = metadata.at(kScene);
  t.version = metadata.at(kVersion);
  t.encoderSettings = metadata.at(kEncoder);
  const std::string& frames = metadata.at(kFrames);
  const auto dash = frames.find('-');
  if (dash == std::string::npos || !parseCount(frames.substr(0, dash), t.firstFrame) ||
      !parseCount(frames.substr(dash + 1), t.lastFrame) || t.lastFrame < t.firstFrame)
    return fail(fmt::format("its '{}' tag is '{}', expected FIRST-LAST", kFrames, frames));
  if (!parseCount(metadata.at(kClipFrames), t.clipFrames) || t.lastFrame >= t.clipFrames)
    return fail(fmt::format("its '{}' tag is '{}', expected a count above {}", kClipFrames, metadata.at(kClipFrames),
                            t.lastFrame));
  return t;
}

void applyContainerTags(AVFormatContext* format, const ContainerTags& tags, AVDictionary** muxerOptions) {
  for (const auto& [key, value] : containerMetadata(tags))
    av_dict_set(&format->metadata, key.c_str(), value.c_str(), 0);
  allowCustomContainerKeys(format, muxerOptions);
}

void allowCustomContainerKeys(AVFormatContext* format, AVDictionary** muxerOptions) {
  // The MP4/MOV muxer writes arbitrary keys only as QuickTime 'mdta' keys
  // (read back by libavformat and ffprobe); Matroska writes any tag anyway.
  if (format->priv_data != nullptr && av_opt_find(format->priv_data, "movflags", nullptr, 0, 0) != nullptr)
    av_dict_set(muxerOptions, "movflags", "+use_metadata_tags", AV_DICT_APPEND);
}

std::optional<FramesRetag> retagPartial(AVFormatContext* format, long long framesWritten) {
  std::map<std::string, std::string> metadata;
  for (const AVDictionaryEntry* e = nullptr;
       (e = av_dict_get(format->metadata, "", e, AV_DICT_IGNORE_SUFFIX)) != nullptr;)
    metadata[e->key] = e->value;
  std::optional<ContainerTags> tags = parseContainerTags(metadata);
  if (!tags || framesWritten <= 0) return std::nullopt;
  FramesRetag retag{metadata.at(kFrames), {}};
  tags->lastFrame = std::min(tags->lastFrame, tags->firstFrame + framesWritten - 1);
  retag.after = fmt::format("{}-{}", tags->firstFrame, tags->lastFrame);
  av_dict_set(&format->metadata, kFrames, retag.after.c_str(), 0);
  return retag;
}

bool patchMatroskaFramesTag(const std::filesystem::path& path, const std::string& oldValue, const std::string& value) {
  if (value.size() > oldValue.size()) return false;
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  if (!file) return false;
  // The tags sit near the start (written with the header): SimpleTag's
  // TagName element (0x45A3, size, name), then TagString (0x4487, size, value).
  std::string head(std::size_t{1} << 20, '\0');  // the header's tags come long before 1 MiB
  file.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(file.gcount()));
  // libavformat's Matroska muxer writes tag names in upper case.
  std::string name = kFrames;
  for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  std::size_t found = std::string::npos;
  for (std::size_t at = head.find(name); at != std::string::npos; at = head.find(name, at + 1)) {
    const std::size_t tagString = at + name.size();
    // TagString's id, a one-byte size (0x80 | n) and the value itself.
    if (tagString + 3 + oldValue.size() > head.size() || head.compare(tagString, 2, "\x44\x87") != 0 ||
        static_cast<unsigned char>(head[tagString + 2]) != (0x80 | oldValue.size()) ||
        head.compare(tagString + 3, oldValue.size(), oldValue) != 0)
      continue;
    if (found != std::string::npos) return false;  // twice: which one is unclear
    found = tagString + 3;
  }
  if (found == std::string::npos) return false;
  std::string padded = value;
  padded.resize(oldValue.size(), '\0');
  file.clear();
  file.seekp(static_cast<std::streamoff>(found));
  file.write(padded.data(), static_cast<std::streamsize>(padded.size()));
  file.flush();
  return static_cast<bool>(file);
}

std::string sha256Hex(const std::string& text) {
  AVHashContext* raw = nullptr;
  if (av_hash_alloc(&raw, "SHA256") < 0 || raw == nullptr) throw std::bad_alloc();
  const std::unique_ptr<AVHashContext, void (*)(AVHashContext*)> hash(raw, [](AVHashContext* h) { av_hash_freep(&h); });
  av_hash_init(hash.get());
  av_hash_update(hash.get(), reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  char hex[2 * AV_HASH_MAX_SIZE + 1] = {};
  av_hash_final_hex(hash.get(), reinterpret_cast<std::uint8_t*>(hex), sizeof hex);
  return hex;
}

}  // namespace rollspin::media
