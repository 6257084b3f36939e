// The EGL backend: an OpenGL 4.5 core context with no window and no surface,
// on a GPU through EGL_EXT_platform_device when one is present, else on
// EGL_MESA_platform_surfaceless (Mesa's llvmpipe where no GPU is listed;
// NVIDIA's driver offers that platform on its GPU too). libEGL (glvnd)
// is opened with dlopen when a job draws, never linked; glvnd then loads the
// vendor's driver (Mesa's libEGL_mesa, NVIDIA's libEGL_nvidia) named by the
// JSON files in /usr/share/glvnd/egl_vendor.d.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <dlfcn.h>
#include <link.h>

#include <charconv>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "render/gl.hpp"
#include "render/gl_backend.hpp"

namespace rollspin::render {

namespace {

// What to try; the factory adds the other backends.
constexpr std::string_view kAdvice = "install Debian's libegl1 and libegl-mesa0 (scripts/install-deps.sh)";

// libEGL's entry points: the core ones by dlsym, the device extension's
// through eglGetProcAddress (glvnd dispatches them to the vendor).
struct EglApi {
  decltype(&eglGetProcAddress) getProcAddress = nullptr;
  decltype(&eglGetError) getError = nullptr;
  decltype(&eglQueryString) queryString = nullptr;
  decltype(&eglGetPlatformDisplay) getPlatformDisplay = nullptr;
  decltype(&eglInitialize) initialize = nullptr;
  decltype(&eglTerminate) terminate = nullptr;
  decltype(&eglBindAPI) bindApi = nullptr;
  decltype(&eglChooseConfig) chooseConfig = nullptr;
  decltype(&eglCreateContext) createContext = nullptr;
  decltype(&eglMakeCurrent) makeCurrent = nullptr;
  decltype(&eglDestroyContext) destroyContext = nullptr;
  decltype(&eglReleaseThread) releaseThread = nullptr;
  PFNEGLQUERYDEVICESEXTPROC queryDevices = nullptr;            // null without EGL_EXT_device_enumeration
  PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString = nullptr;  // null without EGL_EXT_device_query
  std::string clientExtensions;  // EGL_EXTENSIONS of EGL_NO_DISPLAY: the platforms libEGL offers
};

// Loads libEGL once; returns null and sets `why` when it cannot (a failed
// load is retried by the next caller). ROLLSPIN_EGL_LIBRARY names another
// library file (a test's missing one).
const EglApi* loadEgl(std::string& why) {
  static std::mutex mutex;
  static EglApi api;
  static bool loaded = false;
  const std::lock_guard lock(mutex);
  if (loaded) return &api;
  void* handle = openGlLibrary("ROLLSPIN_EGL_LIBRARY", {"libEGL.so.1", "libEGL.so"}, why);
  if (handle == nullptr) {
    why = "cannot load the EGL library needed to draw (" + why + ")";
    return nullptr;
  }
  why.clear();
  auto resolve = [&](auto& target, const char* name) {
    target = reinterpret_cast<std::remove_reference_t<decltype(target)>>(dlsym(handle, name));
    if (target == nullptr && why.empty()) why = std::string("libEGL has no ") + name + " (EGL 1.5 needed)";
  };
  resolve(api.getProcAddress, "eglGetProcAddress");
  resolve(api.getError, "eglGetError");
  resolve(api.queryString, "eglQueryString");
  resolve(api.getPlatformDisplay, "eglGetPlatformDisplay");
  resolve(api.initialize, "eglInitialize");
  resolve(api.terminate, "eglTerminate");
  resolve(api.bindApi, "eglBindAPI");
  resolve(api.chooseConfig, "eglChooseConfig");
  resolve(api.createContext, "eglCreateContext");
  resolve(api.makeCurrent, "eglMakeCurrent");
  resolve(api.destroyContext, "eglDestroyContext");
  resolve(api.releaseThread, "eglReleaseThread");
  if (!why.empty()) return nullptr;
  // Client extensions: null when no vendor driver is installed (glvnd found
  // no JSON file), which is the usual "EGL in a container" failure.
  const char* client = api.queryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  api.clientExtensions = client != nullptr ? client : "";
  (void)api.getError();  // a null answer sets EGL_BAD_DISPLAY; not an error here
  api.queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(api.getProcAddress("eglQueryDevicesEXT"));
  api.queryDeviceString =
      reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(api.getProcAddress("eglQueryDeviceStringEXT"));
  loaded = true;
  return &api;
}

bool hasExtension(const std::string& list, std::string_view name) {
  std::size_t at = 0;
  while ((at = list.find(name, at)) != std::string::npos) {
    const std::size_t end = at + name.size();
    if ((at == 0 || list[at - 1] == ' ') && (end == list.size() || list[end] == ' ')) return true;
    at = end;
  }
  return false;
}

// EGL's error codes by name, as the EGL specification spells them.
std::string errorName(EGLint code) {
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return fmt::format("EGL error 0x{:04x}", code);
  }
}

// One EGL device as EGL_EXT_device_enumeration lists it.
struct EglDevice {
  EGLDeviceEXT handle = EGL_NO_DEVICE_EXT;
  int index = 0;
  std::string drmPath;     // EGL_DRM_DEVICE_FILE_EXT, "" when the device has none
  std::string renderNode;  // EGL_DRM_RENDER_NODE_FILE_EXT, likewise
  std::string name;        // EGL_RENDERER_EXT (EGL_EXT_device_query_name): "NVIDIA H200", say
  bool software = false;   // EGL_MESA_device_software: Mesa's CPU rasteriser

  // "0: NVIDIA H200 at /dev/dri/renderD128 (hardware)"; a VM or container
  // may pass the GPU in without its /dev/dri nodes, so the name comes first.
  [[nodiscard]] std::string describe() const {
    const std::string& node = !renderNode.empty() ? renderNode : drmPath;
    std::string what = std::to_string(index) + ": ";
    if (!name.empty()) {
      what += node.empty() ? name + ", no DRM node" : name + " at " + node;
    } else if (!node.empty()) {
      what += node;
    } else {
      what += software ? "Mesa's software device" : "a device with no DRM node";
    }
    return what + (software ? " (software)" : " (hardware)");
  }
};

// The devices EGL lists, or why it lists none (said in every message that
// names the devices, so a user sees at once where a GPU was lost).
struct EglDevices {
  std::vector<EglDevice> list;
  std::string whyNone;
};

EglDevices listDevices(const EglApi& api) {
  EglDevices devices;
  // EGL_EXT_device_base is the older name for enumeration + query together
  // (NVIDIA's drivers list it); either one makes eglQueryDevicesEXT usable.
  const bool enumerable = hasExtension(api.clientExtensions, "EGL_EXT_device_enumeration") ||
                          hasExtension(api.clientExtensions, "EGL_EXT_device_base");
  if (api.queryDevices == nullptr || !enumerable) {
    devices.whyNone = "libEGL lists neither EGL_EXT_device_enumeration nor EGL_EXT_device_base";
    return devices;
  }
  std::vector<EGLDeviceEXT> handles(32);
  EGLint count = 0;
  if (!api.queryDevices(static_cast<EGLint>(handles.size()), handles.data(), &count)) {
    devices.whyNone = "eglQueryDevicesEXT failed: " + errorName(api.getError());
    return devices;
  }
  if (count == 0) devices.whyNone = "eglQueryDevicesEXT lists none";
  for (EGLint i = 0; i < count; ++i) {
    EglDevice d;
    d.handle = handles[static_cast<std::size_t>(i)];
    d.index = i;
    if (api.queryDeviceString != nullptr) {
      const char* ext = api.queryDeviceString(d.handle, EGL_EXTENSIONS);
      const std::string extensions = ext != nullptr ? ext : "";
      d.software = hasExtension(extensions, "EGL_MESA_device_software");
      auto query = [&](EGLint name) {
        const char* s = api.queryDeviceString(d.handle, name);
        return std::string(s != nullptr ? s : "");
      };
      if (hasExtension(extensions, "EGL_EXT_device_drm")) d.drmPath = query(EGL_DRM_DEVICE_FILE_EXT);
      if (hasExtension(extensions, "EGL_EXT_device_drm_render_node"))
        d.renderNode = query(EGL_DRM_RENDER_NODE_FILE_EXT);
      if (hasExtension(extensions, "EGL_EXT_device_query_name")) d.name = query(EGL_RENDERER_EXT);
      (void)api.getError();  // a string the device lacks is not an error here
    }
    devices.list.push_back(std::move(d));
  }
  return devices;
}

std::string describeDevices(const EglDevices& devices) {
  if (devices.list.empty()) return "no EGL devices (" + devices.whyNone + ")";
  std::string out = "EGL devices ";
  for (std::size_t i = 0; i < devices.list.size(); ++i) out += (i ? "; " : "") + devices.list[i].describe();
  return out;
}

const EglDevice* firstHardware(const EglDevices& devices) {
  for (const auto& d : devices.list)
    if (!d.software) return &d;
  return nullptr;
}

// "no vendor": glvnd's libEGL loaded, but no driver registered with it.
std::string noDriverReason() {
  return "libEGL found no EGL driver (eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS) lists no platforms: glvnd "
         "read no vendor file from /usr/share/glvnd/egl_vendor.d or __EGL_VENDOR_LIBRARY_FILENAMES); install "
         "libegl-mesa0, or with an NVIDIA GPU in a container make its 10_nvidia.json visible";
}

// The device the user asked for: an index into the list, or a DRM path
// (the card node or the render node). BadInput when the text is neither,
// Runtime when no such device is here.
const EglDevice& requestedDevice(const DeviceChoice& choice, const EglDevices& devices) {
  const std::string& text = choice.text;
  const bool isIndex = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  if (!isIndex && (text.empty() || text[0] != '/'))
    throw badInput(choice.where,
                   "expected an EGL device index (0, 1, …) or a DRM device path such as "
                   "/dev/dri/renderD128, got \"{}\"",
                   text);
  for (const auto& d : devices.list) {
    if (isIndex ? std::to_string(d.index) == text : (d.drmPath == text || d.renderNode == text)) return d;
  }
  throw runtimeError(choice.where, "no EGL device {} here ({}); choose one of those, or leave the device unset", text,
                     describeDevices(devices));
}

// A sanitizer build keeps the DRI driver Mesa loaded (swrast_dri.so, or a
// vendor's) mapped for the life of the process: libEGL_mesa dlcloses it at
// eglTerminate, before LeakSanitizer's exit-time check, and the allocations
// the driver keeps until exit would then come from an "<unknown module>"
// that no suppression (tests/lsan.supp) can name. (Preloading the driver
// into every process of the sanitizer pass did the same, at a tenth of a
// second for each of its processes, GL or not: ffprobe, pdftotext too.)
void keepDriversMappedForLeakCheck() {
#if defined(ROLLSPIN_ADDRESS_SANITIZER)
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) {
        const std::string_view name = info->dlpi_name != nullptr ? info->dlpi_name : "";
        if (name.find("/dri/") != std::string_view::npos && name.ends_with("_dri.so"))
          // RTLD_NOLOAD: only an object already loaded; NODELETE: never unmapped.
          dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
#endif
}

// EGLDisplays are per process and per (platform, device): one
// eglInitialize per display while any context uses it, eglTerminate after
// the last one, so that two contexts never pull the display from each other.
std::mutex displayMutex;
std::map<EGLDisplay, int> displayUsers;

class EglContext final : public GlContext {
 public:
  // `device` null: the surfaceless platform.
  EglContext(const EglApi& api, const EglDevice* device, bool requested) : api_(api) {
    const std::string where = device != nullptr ? "EGL device " + device->describe() : "the surfaceless platform";
    info_.backend = "egl";
    info_.platform = device != nullptr ? "device" : "surfaceless";
    info_.device = device != nullptr ? device->describe() : "";
    display_ = device != nullptr ? api_.getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device->handle, nullptr)
                                 : api_.getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY) fail(fmt::format("eglGetPlatformDisplay for {}", where), "");
    {
      const std::lock_guard lock(displayMutex);
      EGLint major = 0;
      EGLint minor = 0;
      if (displayUsers[display_] == 0 && !api_.initialize(display_, &major, &minor)) {
        displayUsers.erase(display_);
        fail(fmt::format("eglInitialize on {}", where),
             device != nullptr ? "the vendor's driver could not open the device: in a container, is /dev/dri (or "
                                 "/dev/nvidia*) passed in and readable?"
                               : "Mesa could not load its driver (swrast_dri.so from libgl1-mesa-dri)");
      }
      ++displayUsers[display_];
      keepDriversMappedForLeakCheck();
    }
    try {
      makeContext(where);
    } catch (...) {
      releaseDisplay();
      throw;
    }
    readGlStrings(info_);
    // A device asked for by name or picked as hardware, but the CPU renders:
    // say so instead of silently being slow.
    if (device != nullptr && info_.software)
      info_.notes.push_back(
          fmt::format("{} EGL device {} renders in software (GL_RENDERER {}): no GPU is doing the "
                      "work",
                      requested ? "the requested" : "the", device->describe(), info_.renderer));
  }
  ~EglContext() override {
    api_.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    api_.destroyContext(display_, context_);
    releaseDisplay();
    api_.releaseThread();
  }
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

 private:
  void makeContext(const std::string& where) {
    const char* ext = api_.queryString(display_, EGL_EXTENSIONS);
    const std::string extensions = ext != nullptr ? ext : "";
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context"))
      throw runtimeError({}, "EGL on {} lacks EGL_KHR_surfaceless_context (a context with no surface)", where);
    if (!api_.bindApi(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)", "this EGL driver offers no desktop OpenGL");
    // No config is needed for a context that never draws to a surface; a
    // driver without EGL_KHR_no_config_context gets any OpenGL config.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(extensions, "EGL_KHR_no_config_context") &&
        !hasExtension(extensions, "EGL_MESA_configless_context")) {
      const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
      EGLint found = 0;
      if (!api_.chooseConfig(display_, wanted, &config, 1, &found) || found < 1)
        fail("eglChooseConfig (an OpenGL config)", "the driver offers no desktop OpenGL config");
    }
    // EGL 1.5 / EGL_KHR_create_context attributes (the same values).
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = api_.createContext(display_, config, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT)
      fail(fmt::format("eglCreateContext (OpenGL 4.5 core) on {}", where),
           "the driver offers no OpenGL 4.5 core profile");
    if (!api_.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      const EGLint code = api_.getError();
      api_.destroyContext(display_, context_);
      fail("eglMakeCurrent with EGL_NO_SURFACE", "", code);
    }
    try {
      loadGlFunctions(api_.getProcAddress, "libEGL");
    } catch (...) {
      api_.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      api_.destroyContext(display_, context_);
      throw;
    }
  }

  // "eglInitialize on the surfaceless platform failed: EGL_NOT_INITIALIZED
  // (hint); try …" — exit 1.
  [[noreturn]] void fail(const std::string& call, const std::string& hint, EGLint code = 0) const {
    if (code == 0) code = api_.getError();
    throw runtimeError({}, "{} failed: {}{}; {}", call, errorName(code), hint.empty() ? "" : " (" + hint + ")",
                       kAdvice);
  }

  void releaseDisplay() {
    const std::lock_guard lock(displayMutex);
    if (--displayUsers[display_] == 0) {
      displayUsers.erase(display_);
      api_.terminate(display_);
    }
  }

  const EglApi& api_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

BackendProbe probe() {
  std::string why;
  const EglApi* api = loadEgl(why);
  if (api == nullptr) return {BackendProbe::Reach::None, why};
  if (api->clientExtensions.empty()) return {BackendProbe::Reach::None, noDriverReason()};
  const auto devices = listDevices(*api);
  if (firstHardware(devices) != nullptr) return {BackendProbe::Reach::Hardware, describeDevices(devices)};
  if (hasExtension(api->clientExtensions, "EGL_MESA_platform_surfaceless"))
    return {BackendProbe::Reach::Software, "surfaceless platform (software); " + describeDevices(devices)};
  if (!devices.list.empty()) return {BackendProbe::Reach::Software, describeDevices(devices)};
  return {BackendProbe::Reach::None,
          "EGL offers no device (EGL_EXT_platform_device) and no surfaceless platform (EGL_MESA_platform_surfaceless)"};
}

std::unique_ptr<GlContext> create(const std::optional<DeviceChoice>& choice) {
  std::string why;
  const EglApi* api = loadEgl(why);
  if (api == nullptr) throw runtimeError({}, "{}; {}", why, kAdvice);
  if (api->clientExtensions.empty()) throw runtimeError({}, "{}", noDriverReason());
  const auto devices = listDevices(*api);
  const bool platformDevice = hasExtension(api->clientExtensions, "EGL_EXT_platform_device");
  if (choice) {
    const EglDevice& device = requestedDevice(*choice, devices);
    if (!platformDevice)
      throw runtimeError(choice->where,
                         "this libEGL lacks EGL_EXT_platform_device: it cannot render on a chosen "
                         "device; leave the device unset");
    return std::make_unique<EglContext>(*api, &device, true);
  }
  // A GPU when there is one; else the surfaceless platform; else whatever
  // device there is (a driver with devices but no surfaceless platform).
  if (const EglDevice* gpu = firstHardware(devices); gpu != nullptr && platformDevice)
    return std::make_unique<EglContext>(*api, gpu, false);
  if (hasExtension(api->clientExtensions, "EGL_MESA_platform_surfaceless"))
    return std::make_unique<EglContext>(*api, nullptr, false);
  if (!devices.list.empty() && platformDevice) return std::make_unique<EglContext>(*api, &devices.list.front(), false);
  throw runtimeError({},
                     "EGL offers no device (EGL_EXT_platform_device) and no surfaceless platform "
                     "(EGL_MESA_platform_surfaceless), {}; {}",
                     describeDevices(devices), kAdvice);
}

}  // namespace

extern const GlBackend kEglBackend{
    "egl",  "EGL: a GPU through EGL_EXT_platform_device, else Mesa's surfaceless platform (llvmpipe)",
    true,   kAdvice,
    &probe, &create};

}  // namespace rollspin::render
