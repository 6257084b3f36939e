#include "media/container_tags.hpp"

#include "media/av_library.hpp"

#include <fmt/format.h>

#include <charconv>
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
  for (const auto& [key, value] : containerMetadata(tags)) av_dict_set(&format->metadata, key.c_str(), value.c_str(), 0);
  allowCustomContainerKeys(format, muxerOptions);
}

void allowCustomContainerKeys(AVFormatContext* format, AVDictionary** muxerOptions) {
  // The MP4/MOV muxer writes arbitrary keys only as QuickTime 'mdta' keys
  // (read back by libavformat and ffprobe); Matroska writes any tag anyway.
  if (format->priv_data != nullptr && av_opt_find(format->priv_data, "movflags", nullptr, 0, 0) != nullptr)
    av_dict_set(muxerOptions, "movflags", "+use_metadata_tags", AV_DICT_APPEND);
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
