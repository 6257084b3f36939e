// What `rollspin info` says about video output: the FFmpeg libraries that
// MP4, WebM, MOV, GIF and `join` would load (media/av_library.hpp), with
// their versions, or why they cannot be loaded. Loads them to find out.
#pragma once

#include <string>

namespace rollspin::media {

// "libavutil 57.28.100, …, from the loader's path", or "not available: …".
[[nodiscard]] std::string videoLibrariesSummary();

}  // namespace rollspin::media
