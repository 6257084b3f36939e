#include "media/av_library.hpp"

#include <dlfcn.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "media/video_libraries.hpp"

namespace rollspin::media::av_library {

namespace {

namespace fs = std::filesystem;

constexpr const char* kNames[] = {
#define ROLLSPIN_AV_NAME(name) #name,
    ROLLSPIN_AV_FUNCTIONS(ROLLSPIN_AV_NAME)
#undef ROLLSPIN_AV_NAME
};
static_assert(std::size(kNames) == count);

// The libraries and their major versions, as the headers were compiled
// against them: a library of another major version has another ABI.
struct Library {
  const char* name;
  int major;
  [[nodiscard]] std::string soname() const { return fmt::format("{}.so.{}", name, major); }
  [[nodiscard]] std::string debianPackage() const { return fmt::format("{}{}", name, major); }
};
constexpr Library kLibraries[] = {{"libavutil", LIBAVUTIL_VERSION_MAJOR},
                                  {"libswscale", LIBSWSCALE_VERSION_MAJOR},
                                  {"libavcodec", LIBAVCODEC_VERSION_MAJOR},
                                  {"libavformat", LIBAVFORMAT_VERSION_MAJOR},
                                  {"libavfilter", LIBAVFILTER_VERSION_MAJOR}};

struct Table {
  std::array<void*, count> functions{};
};

constexpr const char* kOverrideVariable = "ROLLSPIN_LIBAV_DIR";

std::string customDirectory() {
  const char* custom = std::getenv(kOverrideVariable);
  return custom != nullptr ? custom : "";
}

Table load() {
  const std::string directory = customDirectory();
  std::vector<void*> handles;
  for (const Library& library : kLibraries) {
    const std::string path = directory.empty() ? library.soname() : (fs::path(directory) / library.soname()).string();
    // RTLD_NODELETE: the libraries stay for the rest of the process (codec
    // threads may outlive a writer), and LeakSanitizer can still name them.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (handle == nullptr) {
      const char* why = dlerror();
      std::string packages;
      for (const Library& l : kLibraries) packages += fmt::format(" {}", l.debianPackage());
      throw runtimeError({}, "video output and `join` need FFmpeg's {}{} ({}); on Debian: apt-get install{}",
                         library.soname(), directory.empty() ? "" : " in " + customDirectoryNamed(),
                         why != nullptr ? why : "not found", packages);
    }
    handles.push_back(handle);
  }
  Table table;
  for (std::size_t i = 0; i < count; ++i) {
    for (void* handle : handles)
      if ((table.functions[i] = dlsym(handle, kNames[i])) != nullptr) break;
    if (table.functions[i] == nullptr)
      throw runtimeError({}, "FFmpeg's libraries loaded, but none provides {} (another FFmpeg version?)", kNames[i]);
  }
  return table;
}

}  // namespace

std::string customDirectoryNamed() {
  const std::string directory = customDirectory();
  return directory.empty() ? "" : fmt::format("{} (${})", directory, kOverrideVariable);
}

void* symbol(std::size_t index) {
  // Thread-safe; a load that throws is tried again at the next call.
  static const Table table = load();
  return table.functions[index];
}

}  // namespace rollspin::media::av_library

namespace rollspin::media {

std::string videoLibrariesSummary() {
  try {
    std::string versions;
    auto add = [&](const char* name, unsigned version) {
      versions += fmt::format("{}{} {}.{}.{}", versions.empty() ? "" : ", ", name, version >> 16, (version >> 8) & 0xff,
                              version & 0xff);
    };
    add("libavutil", avutil_version());
    add("libswscale", swscale_version());
    add("libavcodec", avcodec_version());
    add("libavformat", avformat_version());
    add("libavfilter", avfilter_version());
    const std::string directory = av_library::customDirectoryNamed();
    return versions + ", from " + (directory.empty() ? "the loader's path" : directory);
  } catch (const Error& e) {
    return fmt::format("not available: {}", e.message());
  }
}

}  // namespace rollspin::media
