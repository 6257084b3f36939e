#include "cli/version_info.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "git_describe.hpp"  // generated at build time (git_describe.cmake)
#include "render/gl_context.hpp"

namespace rollspin::cli {

std::string versionLine() {
  const std::string describe = ROLLSPIN_GIT_DESCRIBE;
  return fmt::format("rollspin {} ({})", ROLLSPIN_VERSION,
                     describe.empty() ? "not built from a git clone" : "git " + describe);
}

std::string glBackendDescription() {
  // The backend factory is one call; a render makes the same one.
  try {
    return render::createContext(render::ContextRequest{})->describe();
  } catch (const Error& e) {
    return fmt::format("none: {}", e.message());
  }
}

}  // namespace rollspin::cli
