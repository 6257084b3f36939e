// `rollspin info`: which GL backends load on this machine, and the context
// the renderer would get (backend, GL_VENDOR, GL_RENDERER, GL_VERSION, the
// EGL device), so a user sees at once whether a GPU would do the work; then
// the FFmpeg libraries video output would load.
#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "media/video_libraries.hpp"
#include "render/gl_context.hpp"

namespace rollspin::cli {

namespace {

struct InfoOptions {
  std::string backend, device;
};

int runInfo(const InfoOptions& o, const CLI::App& command) {
  render::ContextRequest request;
  if (command.count("--backend") > 0) request = {o.backend, SourceLoc{"--backend"}, {}, {}};
  if (command.count("--device") > 0) {
    request.device = o.device;
    request.deviceWhere = SourceLoc{"--device"};
  }
  auto listBackends = [] {
    fmt::print("GL backends (ROLLSPIN_GL or render.backend chooses; \"auto\" by default):\n");
    for (const auto& line : render::probeBackends()) fmt::print("  {}\n", line);
    std::fflush(stdout);
  };
  std::unique_ptr<render::GlContext> context;
  try {
    context = render::createContext(request);
  } catch (const Error& e) {
    // A context that cannot be had (exit 1): show what each backend found
    // first. A bad name or device (exit 2) needs no survey.
    if (e.kind() == ErrorKind::Runtime) listBackends();
    throw;
  }
  listBackends();
  fmt::print("\nthe context a render gets here:\n{}", render::describeContext(context->info()));
  fmt::print("\nvideo (MP4, WebM, MOV, GIF, join): {}\n", media::videoLibrariesSummary());
  return 0;
}

}  // namespace

void registerInfoCommand(CLI::App& cli, CommandHandler& handler) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* info = cli.add_subcommand("info", "Show the GL backends and the OpenGL context a render would get");
  std::string names;
  for (const auto& name : render::backendNames()) names += (names.empty() ? "" : ", ") + name;
  info->add_option("--backend", options->backend, "GL backend to try (" + names + "; default: ROLLSPIN_GL, else auto)");
  info->add_option("--device", options->device, "EGL device: an index or a DRM path (default: ROLLSPIN_EGL_DEVICE)");
  info->callback([options, info, &handler] { handler = [options, info] { return runInfo(*options, *info); }; });
}

}  // namespace rollspin::cli
