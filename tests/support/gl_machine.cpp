#include "support/gl_machine.hpp"

#include <regex>

#include "support/cli_runner.hpp"

namespace rollspin::test {

EglDevicesHere parseEglDevices(const std::string& infoOut) {
  EglDevicesHere here;
  std::smatch m;
  // The survey line: "  egl: available, hardware — EGL devices 0: /dev/dri/renderD128 (hardware), …"
  static const std::regex eglLine(R"(^\s*egl: (available, hardware|available, software|unavailable)\b(.*)$)",
                                  std::regex::multiline);
  if (!std::regex_search(infoOut, m, eglLine)) return here;
  here.hardware = m[1] == "available, hardware";
  const std::string devices = m[2];
  static const std::regex software(R"((\d+): Mesa's software device)");
  if (std::regex_search(devices, m, software)) here.softwareIndex = std::stoi(m[1]);
  return here;
}

const EglDevicesHere& eglDevicesHere() {
  static const EglDevicesHere here = [] {
    // The child must not inherit a choice of backend or device: the survey
    // lists what is there, whatever the caller asked for.
    const CliResult r = runRollspin({"info"}, {}, 0, {"ROLLSPIN_GL=", "ROLLSPIN_EGL_DEVICE="});
    return parseEglDevices(r.out);
  }();
  return here;
}

}  // namespace rollspin::test
