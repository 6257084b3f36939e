// Small helpers the libav-based writers and the joiner share: FFmpeg's error
// text, and whether an output path is a device or pipe that is written in
// place (a regular file or a new name gets a temporary name and a rename).
// Internal to media/; includes the libav headers only where it is included.
#pragma once

#include "media/av_library.hpp"

#include <filesystem>
#include <string>
#include <system_error>

namespace rollspin::media::av {

inline std::string errorText(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

inline bool isDevice(const std::filesystem::path& p) {
  std::error_code ec;
  const auto status = std::filesystem::status(p, ec);
  return !ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
         !std::filesystem::is_directory(status);
}

}  // namespace rollspin::media::av
