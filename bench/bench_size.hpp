// ROLLSPIN_BENCH_SIZE=WxH: another frame size for every benchmark of a
// program (3840x2160 for 4K); 1920x1080 by default. The benchmarks keep
// their 1080p names. Read once: every benchmark asks for it.
#pragma once

#include <cstdio>
#include <cstdlib>

namespace rollspin::bench {

// The source tree's scenes/ (generated into bench_paths.cpp by bench/CMakeLists.txt).
extern const char* const kSceneDir;

struct FrameSize {
  int width = 1920;
  int height = 1080;
};

// Exits with status 2 and a message naming `program` when the variable is
// not WIDTHxHEIGHT, each 1..8192.
inline const FrameSize& benchFrameSize(const char* program) {
  static const FrameSize size = [program] {
    FrameSize parsed;
    const char* text = std::getenv("ROLLSPIN_BENCH_SIZE");
    char rest = 0;
    if (text != nullptr && *text != '\0' &&
        (std::sscanf(text, "%dx%d%c", &parsed.width, &parsed.height, &rest) != 2 || parsed.width < 1 ||
         parsed.height < 1 || parsed.width > 8192 || parsed.height > 8192)) {
      std::fprintf(stderr, "%s: ROLLSPIN_BENCH_SIZE=%s is not WIDTHxHEIGHT, each 1..8192 (3840x2160, say)\n", program,
                   text);
      std::exit(2);
    }
    return parsed;
  }();
  return size;
}

}  // namespace rollspin::bench
