// Runs the built rollspin binary as a subprocess (no shell), capturing exit
// code, stdout and stderr: the CLI is tested the way a user meets it. The
// file helpers (support/test_files.hpp) come with it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "support/test_files.hpp"

namespace rollspin::test {

// Whether the CLI's output (or a file it wrote) holds `part`.
inline bool has(std::string_view text, std::string_view part) { return text.find(part) != std::string_view::npos; }

struct CliResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

// argv excludes the program name. cwd: working directory ("" = current).
// addressSpaceLimit: RLIMIT_AS for the child in bytes (0 = unlimited), to
// simulate a machine with little memory.
// environment: extra "NAME=value" entries for the child; each replaces an
// inherited variable of the same name.
CliResult runRollspin(const std::vector<std::string>& args, const std::filesystem::path& cwd = {},
                      std::uint64_t addressSpaceLimit = 0, const std::vector<std::string>& environment = {});

// A rollspin started without waiting for it (stderr to `errFile`), for tests
// that signal it mid-run. wait() reaps it: the exit code, or 128 + signal
// with `signalled` set when a signal ended it. The destructor kills and
// reaps a child the test left running.
class SpawnedRollspin {
 public:
  SpawnedRollspin(const std::vector<std::string>& args, const std::filesystem::path& errFile);
  ~SpawnedRollspin();
  SpawnedRollspin(const SpawnedRollspin&) = delete;
  SpawnedRollspin& operator=(const SpawnedRollspin&) = delete;
  [[nodiscard]] int pid() const { return pid_; }
  // Polls every 5 ms until `ready()` or `seconds` pass; false on time-out or
  // when the child ended first.
  template <typename Ready>
  bool waitUntil(Ready ready, double seconds = 60.0);
  int wait(bool* signalled = nullptr);

 private:
  bool running();
  int pid_ = -1;
  bool reaped_ = false;
  int status_ = 0;
};

// A malformed scene file: `timeline` on it must exit 2, name `key`, the
// file followed by `where` (":line:col:" or ":line:") and `hint`, and leave
// nothing behind. One GoogleTest expectation per check, labelled by name.
struct BadScene {
  const char* name;
  const char* toml;
  const char* key;
  const char* where;
  const char* hint;
};
void expectBadScene(const BadScene& c);
std::filesystem::path binaryPath();

void sleepMilliseconds(int ms);

template <typename Ready>
bool SpawnedRollspin::waitUntil(Ready ready, double seconds) {
  for (double waited = 0.0; waited < seconds; waited += 0.005) {
    if (ready()) return true;
    if (!running()) return false;
    sleepMilliseconds(5);
  }
  return false;
}

}  // namespace rollspin::test
