// What the EGL backend finds on the machine running the tests, read from
// `rollspin info` the way a user reads it: a hardware device (a GPU) or not,
// and the index of Mesa's software device. Tests whose expectations differ
// on a GPU machine (the platform --verbose names; failures that only Mesa's
// variables can provoke) ask here instead of assuming llvmpipe.
#pragma once

#include <optional>
#include <string>

namespace rollspin::test {

struct EglDevicesHere {
  bool hardware = false;             // "egl: available, hardware": auto and ROLLSPIN_GL=egl take a GPU
  std::optional<int> softwareIndex;  // "N: Mesa's software device" in the EGL device list
};

// Reads the backend survey that `rollspin info` prints first.
EglDevicesHere parseEglDevices(const std::string& infoOut);

// `rollspin info` run once (without the caller's ROLLSPIN_* variables), parsed.
const EglDevicesHere& eglDevicesHere();

}  // namespace rollspin::test
