// Temporary output files: the one naming pattern (".NAME.PID.tmp" beside the
// final NAME), a registry of the ones this process has open so a SIGINT,
// SIGTERM or crash can remove them before the process ends, and removal of stale ones
// left by a process that died hard (kill -9, a second Ctrl-C).
#pragma once

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace rollspin {

// "<dir>/.<name>.<pid>.tmp" for the final path "<dir>/<name>".
[[nodiscard]] std::filesystem::path temporaryPathFor(const std::filesystem::path& finalPath);

// Removes "<dir>/.<name>.<PID>.tmp" (files or folders) whose PID is not a
// running process; only names in exactly this pattern are touched. Returns
// how many were removed; each one is named on stderr.
int removeStaleTemporaries(const std::filesystem::path& finalPath);

// While registered, a SIGINT/SIGTERM that ends the process (see
// installInterruptCleanup) removes `temporary` first. Registration is
// lock-free and safe from any thread; paths longer than PATH_MAX are not
// registered (the next run's stale clean-up still removes them).
void registerTemporary(const std::filesystem::path& temporary, const std::filesystem::path& finalPath,
                       bool isFolder = false);
void unregisterTemporary(const std::filesystem::path& temporary);

// An output folder made for a command (`report -o DIR`), with the parents it
// had to make: until keep(), a failure (the destructor) removes them with
// what the run wrote into them, and a SIGINT/SIGTERM removes each one that
// is empty by then (the handler may not walk a folder), so an interrupted or
// failed run leaves no empty folder it created. Folders that existed before
// are never touched.
class CreatedFolders {
 public:
  CreatedFolders(const std::filesystem::path& folder, std::error_code& ec);  // ec: as create_directories
  ~CreatedFolders();
  CreatedFolders(const CreatedFolders&) = delete;
  CreatedFolders& operator=(const CreatedFolders&) = delete;
  void keep();  // the command succeeded: its folders stay

 private:
  std::vector<std::filesystem::path> created_;  // innermost first
  bool kept_ = false;
};

// Installs the process-wide SIGINT/SIGTERM handler used by every writing
// command: remove the registered temporaries (a folder is emptied of files
// only: its remains are stale next time), say on stderr what was removed and
// that finished outputs are complete, and exit with 128 + signal. Commands
// that can stop cleanly (an animation) install their own handler on top and
// call interruptCleanupAndExit on a second signal.
void installInterruptCleanup();
[[noreturn]] void interruptCleanupAndExit(int signal);

// Installs the handler for crashes (SIGSEGV, SIGBUS, SIGILL, SIGFPE,
// SIGABRT: glibc's heap checks abort): say on stderr which signal, with a
// backtrace (library frames named, rollspin's as +OFFSET for addr2line),
// remove the registered temporaries, then die of the same signal, so the
// exit status and any core dump are as without it. Not under the
// sanitizers, which report crashes themselves.
void installCrashReport();

// "SIGINT", "SIGSEGV", …: a signal's name from glibc's table, the one the
// handlers above print ("SIG?" for a number it does not know).
[[nodiscard]] std::string signalName(int signal);

}  // namespace rollspin
