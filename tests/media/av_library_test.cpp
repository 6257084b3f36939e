// media/av_library.hpp: FFmpeg's functions resolved with dlopen, of the major
// versions the headers were compiled against; ROLLSPIN_LIBAV_DIR named in
// messages; a library that cannot be loaded is an error naming it and the
// folder, tried again at the next call (media/video_libraries.hpp's summary).
#include "media/av_library.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <regex>
#include <string>

#include "media/video_libraries.hpp"
#include "support/test_files.hpp"

namespace rollspin::media {
namespace av_library_test {

constexpr const char* kLibavDirVariable = "ROLLSPIN_LIBAV_DIR";

// Sets (or unsets) the variable for one scope, then puts back what was there.
class LibavDirSetting {
 public:
  explicit LibavDirSetting(const char* value) {
    if (const char* old = std::getenv(kLibavDirVariable)) old_ = old;
    if (value != nullptr) setenv(kLibavDirVariable, value, 1);
    else unsetenv(kLibavDirVariable);
  }
  ~LibavDirSetting() {
    if (old_) setenv(kLibavDirVariable, old_->c_str(), 1);
    else unsetenv(kLibavDirVariable);
  }
  LibavDirSetting(const LibavDirSetting&) = delete;
  LibavDirSetting& operator=(const LibavDirSetting&) = delete;

 private:
  std::optional<std::string> old_;
};

TEST(AvLibrary, ResolvesEveryFunctionFromLibrariesOfTheHeadersMajorVersions) {
  const LibavDirSetting loaderPath(nullptr);
  for (std::size_t i = 0; i < av_library::count; ++i) EXPECT_NE(av_library::symbol(i), nullptr) << "function " << i;
  // Another major version has another ABI: the loaded ones must be the headers'.
  EXPECT_EQ(avutil_version() >> 16, unsigned{LIBAVUTIL_VERSION_MAJOR});
  EXPECT_EQ(swscale_version() >> 16, unsigned{LIBSWSCALE_VERSION_MAJOR});
  EXPECT_EQ(avcodec_version() >> 16, unsigned{LIBAVCODEC_VERSION_MAJOR});
  EXPECT_EQ(avformat_version() >> 16, unsigned{LIBAVFORMAT_VERSION_MAJOR});
  EXPECT_EQ(avfilter_version() >> 16, unsigned{LIBAVFILTER_VERSION_MAJOR});
  // A call through the table reaches the library's own function.
  EXPECT_STREQ(avcodec_get_name(AV_CODEC_ID_H264), "h264");
}

TEST(AvLibrary, SummaryNamesEachLibraryWithItsVersionAndWhereItCameFrom) {
  const LibavDirSetting loaderPath(nullptr);
  const std::string summary = videoLibrariesSummary();
  const std::regex form(R"(libavutil (\d+)\.\d+\.\d+, libswscale (\d+)\.\d+\.\d+, libavcodec (\d+)\.\d+\.\d+, )"
                        R"(libavformat (\d+)\.\d+\.\d+, libavfilter (\d+)\.\d+\.\d+, from the loader's path)");
  std::smatch m;
  ASSERT_TRUE(std::regex_match(summary, m, form)) << summary;
  EXPECT_EQ(std::stoi(m[1]), LIBAVUTIL_VERSION_MAJOR);
  EXPECT_EQ(std::stoi(m[2]), LIBSWSCALE_VERSION_MAJOR);
  EXPECT_EQ(std::stoi(m[3]), LIBAVCODEC_VERSION_MAJOR);
  EXPECT_EQ(std::stoi(m[4]), LIBAVFORMAT_VERSION_MAJOR);
  EXPECT_EQ(std::stoi(m[5]), LIBAVFILTER_VERSION_MAJOR);
}

TEST(AvLibrary, ACustomFolderIsNamedWithItsVariable) {
  {
    const LibavDirSetting custom("/opt/ffmpeg-6/lib");
    EXPECT_EQ(av_library::customDirectoryNamed(), "/opt/ffmpeg-6/lib ($ROLLSPIN_LIBAV_DIR)");
  }
  {
    const LibavDirSetting unset(nullptr);
    EXPECT_EQ(av_library::customDirectoryNamed(), "") << "unset: nothing to name";
  }
  {
    const LibavDirSetting empty("");
    EXPECT_EQ(av_library::customDirectoryNamed(), "") << "empty: the loader's path";
  }
}

// The libraries load once per process, so this runs in a fresh one (a
// "threadsafe" death test re-executes the program for this test alone):
// from an empty folder nothing loads and the summary says why; with the
// variable unset the next call loads them.
TEST(AvLibrary, AFolderWithoutTheLibrariesIsNamedAndTheNextCallTriesAgain) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const std::string empty = test::freshTempDir("av_library_empty").string();
  EXPECT_EXIT(
      {
        setenv(kLibavDirVariable, empty.c_str(), 1);
        const std::string missing = videoLibrariesSummary();
        unsetenv(kLibavDirVariable);
        const std::string loaded = videoLibrariesSummary();
        std::fprintf(stderr, "missing=[%s]\nloaded=[%s]\n", missing.c_str(), loaded.c_str());
        std::_Exit(0);
      },
      testing::ExitedWithCode(0),
      "missing=\\[not available: video output and `join` need FFmpeg's libavutil\\.so\\.[0-9]+ in "
      "[^]]*av_library_empty[^] ]* \\(\\$ROLLSPIN_LIBAV_DIR\\) \\([^]]*\\); on Debian: apt-get install libavutil[0-9]+ "
      "libswscale[0-9]+ libavcodec[0-9]+ libavformat[0-9]+ libavfilter[0-9]+\\]\n"
      "loaded=\\[libavutil [0-9.]+, .*, from the loader's path\\]");
}

}  // namespace av_library_test
}  // namespace rollspin::media
