// The GL context backends (name → availability probe → constructor) and the
// one factory that chooses among them. A new backend is its own file
// defining a GlBackend, one line here, and one in CMakeLists.txt.
#include <array>
#include <cstdio>
#include <cstdlib>

#include "core/error.hpp"
#include "core/stage_log.hpp"
#include "render/gl_backend.hpp"
#include "render/gl_context.hpp"

namespace rollspin::render {

extern const GlBackend kOsMesaBackend;  // osmesa_context.cpp
extern const GlBackend kEglBackend;     // egl_context.cpp

namespace {

// The table. Its order is auto's preference among software backends: OSMesa
// first (the references were made with it), EGL's surfaceless platform after
// it. A backend whose probe finds a hardware device comes before both.
const std::array<const GlBackend*, 2> kBackends{&kOsMesaBackend, &kEglBackend};

constexpr const char* kBackendVariable = "ROLLSPIN_GL";
constexpr const char* kDeviceVariable = "ROLLSPIN_EGL_DEVICE";

const GlBackend* findBackend(std::string_view name) {
  for (const GlBackend* b : kBackends)
    if (b->name == name) return b;
  return nullptr;
}

std::string quotedChoices() {
  std::string out;
  for (const auto& name : backendNames()) out += (out.empty() ? "" : " | ") + ("\"" + name + "\"");
  return out;
}

// The request with the environment's defaults filled in and checked.
struct Choice {
  std::string backend;  // "auto" or a table name
  SourceLoc where;      // where the name came from ("" for the default)
  std::optional<DeviceChoice> device;
  std::vector<std::string> notes;
};

Choice resolve(const ContextRequest& request) {
  Choice c;
  const char* fromEnv = std::getenv(kBackendVariable);
  if (request.backend) {
    c.backend = *request.backend;
    c.where = request.backendWhere;
  } else if (fromEnv != nullptr && *fromEnv != '\0') {
    c.backend = fromEnv;
    c.where = SourceLoc{kBackendVariable};
  } else {
    c.backend = "auto";
  }
  if (c.backend != "auto" && findBackend(c.backend) == nullptr)
    throw badInput(c.where, "unknown GL backend \"{}\"; expected {}", c.backend, quotedChoices());

  const char* deviceEnv = std::getenv(kDeviceVariable);
  const bool deviceFromRequest = request.device.has_value();
  if (deviceFromRequest) c.device = DeviceChoice{*request.device, request.deviceWhere};
  else if (deviceEnv != nullptr && *deviceEnv != '\0') c.device = DeviceChoice{deviceEnv, SourceLoc{kDeviceVariable}};
  if (c.device && c.backend != "auto" && !findBackend(c.backend)->takesDevice) {
    // Asked for in the same place as the backend: contradictory. From the
    // environment (set for other runs): ignored, and said so.
    if (deviceFromRequest)
      throw badInput(c.device->where,
                     "a device (\"{}\") applies to the egl backend, but the backend is \"{}\"{}; "
                     "remove the device or choose render.backend = \"egl\"",
                     c.device->text, c.backend, c.where.empty() ? "" : " (" + c.where.str() + ")");
    c.notes.push_back(
        fmt::format("{}={} ignored: the {} backend takes no device", kDeviceVariable, c.device->text, c.backend));
    c.device.reset();
  }
  return c;
}

// "ROLLSPIN_GL=egl": what else to try when `failed` cannot be had.
std::string otherBackends(std::string_view failed) {
  std::string out;
  for (const GlBackend* b : kBackends)
    if (b->name != failed) out += (out.empty() ? "" : " or ") + fmt::format("{}={}", kBackendVariable, b->name);
  return out.empty() ? "" : "; or try " + out + " (render.backend in the scene)";
}

// A backend's Runtime failure with the other backends added as what to try.
Error withAlternatives(const Error& e, std::string_view backend) {
  if (e.kind() != ErrorKind::Runtime) return e;
  return Error(ErrorKind::Runtime, e.where(), e.message() + otherBackends(backend));
}

std::unique_ptr<GlContext> createNamed(const GlBackend& backend, const Choice& c) {
  try {
    return backend.create(c.device);
  } catch (const Error& e) {
    // A device asked for by name: the other backends cannot honour it.
    if (c.device) throw;
    throw withAlternatives(e, backend.name);
  }
}

// auto: a hardware device wins; else the table's order among software
// backends; a backend that loads but cannot make a context is passed over
// (and the reason kept for --verbose and the final message).
std::unique_ptr<GlContext> createAuto(Choice& c) {
  if (c.device) {
    // A device was asked for: only a backend that takes devices can honour it.
    for (const GlBackend* b : kBackends) {
      if (!b->takesDevice) continue;
      c.notes.push_back(fmt::format("auto chose {}: a device was requested ({})", b->name, c.device->where.str()));
      return createNamed(*b, c);
    }
  }
  std::vector<std::pair<const GlBackend*, BackendProbe>> probes;
  for (const GlBackend* b : kBackends) probes.emplace_back(b, b->probe());
  std::vector<std::string> failures;
  for (const auto reach : {BackendProbe::Reach::Hardware, BackendProbe::Reach::Software}) {
    for (const auto& [backend, probe] : probes) {
      if (probe.reach != reach) continue;
      try {
        auto context = backend->create(std::nullopt);
        c.notes.push_back(fmt::format("auto chose {} ({}: {})", backend->name,
                                      reach == BackendProbe::Reach::Hardware ? "hardware" : "software", probe.detail));
        return context;
      } catch (const Error& e) {
        if (e.kind() != ErrorKind::Runtime) throw;
        failures.push_back(fmt::format("{}: {}", backend->name, e.message()));
        c.notes.push_back(fmt::format("auto passed over {}: {}", backend->name, e.message()));
      }
    }
  }
  // A backend that did not even load says what to install; one that failed
  // to make a context already did.
  for (const auto& [backend, probe] : probes)
    if (probe.reach == BackendProbe::Reach::None)
      failures.push_back(fmt::format("{}: {}; {}", backend->name, probe.detail, backend->advice));
  std::string reasons;
  for (const auto& f : failures) reasons += (reasons.empty() ? "" : " | ") + f;
  throw runtimeError({},
                     "no GL backend could make an OpenGL 4.5 core context (render.backend = \"auto\"): {} "
                     "(docs/gl-backends.md explains each message)",
                     reasons);
}

}  // namespace

std::vector<std::string> backendNames() {
  std::vector<std::string> names{"auto"};
  for (const GlBackend* b : kBackends) names.emplace_back(b->name);
  return names;
}

bool backendTakesDevice(std::string_view name) {
  const GlBackend* b = findBackend(name);
  return name == "auto" || (b != nullptr && b->takesDevice);
}

std::unique_ptr<GlContext> createContext(const ContextRequest& request) {
  Choice c = resolve(request);
  StageLog::instance().record("gl-context");
  std::unique_ptr<GlContext> context = c.backend == "auto" ? createAuto(c) : createNamed(*findBackend(c.backend), c);
  auto& notes = context->info_.notes;
  notes.insert(notes.begin(), c.notes.begin(), c.notes.end());
  if (StageLog::instance().echo()) {
    const std::string text = describeContext(context->info());
    std::size_t start = 0;
    while (start < text.size()) {
      const std::size_t end = text.find('\n', start);
      std::fprintf(stderr, "rollspin: gl: %s\n", text.substr(start, end - start).c_str());
      start = end == std::string::npos ? text.size() : end + 1;
    }
  }
  return context;
}

std::vector<std::string> probeBackends() {
  std::vector<std::string> lines;
  for (const GlBackend* b : kBackends) {
    const BackendProbe p = b->probe();
    const char* reach = p.reach == BackendProbe::Reach::Hardware   ? "available, hardware"
                        : p.reach == BackendProbe::Reach::Software ? "available, software"
                                                                   : "unavailable";
    lines.push_back(fmt::format("{}: {} — {}\n    {}", b->name, reach, p.detail, b->summary));
  }
  return lines;
}

std::string GlContext::describe() const {
  const ContextInfo& i = info_;
  return fmt::format("{}{}: {} on {}", i.backend, i.platform.empty() ? "" : " (" + i.platform + ")", i.version,
                     i.renderer);
}

std::string describeContext(const ContextInfo& i) {
  std::string out = fmt::format("backend     {}{}\n", i.backend, i.platform.empty() ? "" : " (" + i.platform + ")");
  out += fmt::format("GL_VENDOR   {}\nGL_RENDERER {}{}\nGL_VERSION  {}\n", i.vendor, i.renderer,
                     i.software ? " (software: the CPU renders)" : "", i.version);
  out += fmt::format("device      {}\n", !i.device.empty()             ? i.device
                                         : i.platform == "surfaceless" ? "none (EGL surfaceless platform)"
                                                                       : "none");
  for (const auto& note : i.notes) out += "note        " + note + "\n";
  return out;
}

}  // namespace rollspin::render
