#include "core/temp_files.hpp"

#include <dirent.h>
#include <execinfo.h>
#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

namespace rollspin {

namespace fs = std::filesystem;

fs::path temporaryPathFor(const fs::path& finalPath) {
  fs::path temp = finalPath;
  temp.replace_filename(fmt::format(".{}.{}.tmp", finalPath.filename().string(), ::getpid()));
  return temp;
}

namespace {

// The PID in ".<name>.<PID>.tmp", or -1 when `entry` is not in that pattern.
long temporaryOwner(const std::string& entry, const std::string& name) {
  const std::string prefix = "." + name + ".", suffix = ".tmp";
  if (entry.size() <= prefix.size() + suffix.size() || !entry.starts_with(prefix) || !entry.ends_with(suffix))
    return -1;
  const std::string digits = entry.substr(prefix.size(), entry.size() - prefix.size() - suffix.size());
  if (digits.empty() || digits.size() > 9 || digits[0] == '0') return -1;
  long pid = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') return -1;
    pid = pid * 10 + (c - '0');
  }
  return pid;
}

// A registered temporary: slots are claimed with a CAS, so registering needs
// no lock and the signal handler only reads what is fully written.
struct Slot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 live
  bool isFolder = false;
  bool createdFolder = false;  // an output folder this run made: removed only while empty
  std::array<char, PATH_MAX> temporary{};
  std::array<char, PATH_MAX> finalPath{};
};
std::array<Slot, 32> slots;

// Async-signal-safe output.
void say(const char* text) {
  const std::size_t n = std::strlen(text);
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, text, n);
}

// Removes every registered temporary and says which, after "rollspin: …"
// (async-signal-safe). A folder is only removed when empty: walking it is
// not async-signal-safe, and a staging folder with frames in it is removed by
// the next run instead. True when there was any.
bool removeRegisteredTemporaries() {
  bool any = false;
  // Files first, then folders: a folder empties as the files in it go.
  for (const bool folders : {false, true})
    for (Slot& slot : slots) {
      if (slot.state.load() != 2 || slot.isFolder != folders) continue;
      const int failed = slot.isFolder ? ::rmdir(slot.temporary.data()) : ::unlink(slot.temporary.data());
      if (failed != 0 && errno == ENOENT) continue;  // renamed into place a moment ago: complete
      if (slot.createdFolder) {
        if (failed != 0) continue;  // it holds complete outputs: kept, and not unfinished
        say(any ? "; " : ": ");
        say("removed the empty folder ");
        say(slot.finalPath.data());
        say(" it had created");
        any = true;
        continue;
      }
      say(any ? "; " : ": ");
      say(failed == 0 ? "removed the unfinished " : "could not remove the unfinished ");
      say(slot.finalPath.data());
      say(failed == 0 ? " (nothing written at that name)" : " (its temporary is removed by the next run)");
      any = true;
    }
  return any;
}

extern "C" void onTerminatingSignal(int signal) { interruptCleanupAndExit(signal); }

// "SIGSEGV", "SIGINT", …: glibc's own table (async-signal-safe).
void saySignalName(int signal) {
  say("SIG");
  const char* name = ::sigabbrev_np(signal);
  say(name != nullptr ? name : "?");
}

// A crash: say so with a backtrace, remove the temporaries, then die of the
// same signal (SA_RESETHAND restored the default action: the exit status and
// a core dump are the signal's). Async-signal-safe but for backtrace(),
// whose one allocation (loading libgcc_s) happened at install.
extern "C" void onFatalSignal(int signal) {
  static std::atomic<bool> reporting{false};
  if (!reporting.exchange(true)) {
    say("\nrollspin: fatal signal ");
    saySignalName(signal);
    say(" (a bug in rollspin or in a library it loaded); backtrace, innermost first (`addr2line -Cfpe BINARY "
        "+OFFSET` names a frame of rollspin's own):\n");
    std::array<void*, 64> frames{};
    ::backtrace_symbols_fd(frames.data(), ::backtrace(frames.data(), static_cast<int>(frames.size())), STDERR_FILENO);
    say("rollspin: crashed");
    say(removeRegisteredTemporaries() ? "\n" : ": nothing unfinished left\n");
  }
  ::raise(signal);  // delivered with the default action once this returns
}

}  // namespace

int removeStaleTemporaries(const fs::path& finalPath) {
  const std::string name = finalPath.filename().string();
  if (name.empty()) return 0;
  const fs::path dir = finalPath.has_parent_path() ? finalPath.parent_path() : fs::path(".");
  // Each folder is listed once per process: a render writes thousands of
  // frames into one staging folder, and listing it per frame would be
  // quadratic. What the listing found in the temporary pattern is kept.
  static std::mutex mutex;
  static std::map<std::string, std::vector<std::string>> candidatesByFolder;
  const std::lock_guard lock(mutex);
  const std::string key = fs::absolute(dir).lexically_normal().string();
  auto found = candidatesByFolder.find(key);
  if (found == candidatesByFolder.end()) {
    std::vector<std::string> candidates;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      const std::string entryName = entry.path().filename().string();
      if (entryName.starts_with(".") && entryName.ends_with(".tmp")) candidates.push_back(entryName);
    }
    found = candidatesByFolder.emplace(key, std::move(candidates)).first;
  }
  int removed = 0;
  std::vector<std::string>& candidates = found->second;
  for (auto it = candidates.begin(); it != candidates.end();) {
    const long pid = temporaryOwner(*it, name);
    // kill(pid, 0) fails with ESRCH only when no such process exists (EPERM: it runs as someone else).
    if (pid <= 0 || pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) {
      ++it;
      continue;
    }
    const fs::path stale = dir / *it;
    std::error_code removeError;
    fs::remove_all(stale, removeError);
    if (!removeError) {
      ++removed;
      std::fprintf(stderr, "rollspin: removed %s, left behind by process %ld, which is no longer running\n",
                   stale.string().c_str(), pid);
    }
    it = candidates.erase(it);
  }
  return removed;
}

namespace {

void registerSlot(const fs::path& temporary, const fs::path& finalPath, bool isFolder, bool createdFolder) {
  const std::string t = temporary.string(), f = finalPath.string();
  if (t.size() >= PATH_MAX || f.size() >= PATH_MAX) return;
  for (Slot& slot : slots) {
    int expected = 0;
    if (!slot.state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(slot.temporary.data(), t.c_str(), t.size() + 1);
    std::memcpy(slot.finalPath.data(), f.c_str(), f.size() + 1);
    slot.isFolder = isFolder;
    slot.createdFolder = createdFolder;
    slot.state.store(2);
    return;
  }
}

}  // namespace

void registerTemporary(const fs::path& temporary, const fs::path& finalPath, bool isFolder) {
  registerSlot(temporary, finalPath, isFolder, false);
}

CreatedFolders::CreatedFolders(const fs::path& folder, std::error_code& ec) {
  // The missing ancestors, innermost first: the order they are removed in.
  for (fs::path p = folder.lexically_normal(); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    created_.push_back(p);
    if (!p.has_parent_path() || p.parent_path() == p) break;
  }
  fs::create_directories(folder, ec);
  if (ec) {
    created_.clear();
    return;
  }
  for (const fs::path& p : created_) registerSlot(p, p, true, true);
}

CreatedFolders::~CreatedFolders() {
  for (const fs::path& p : created_) unregisterTemporary(p);
  // Unkept, everything in them is this run's and was never reported written.
  std::error_code ec;
  if (!kept_ && !created_.empty()) fs::remove_all(created_.back(), ec);
}

void CreatedFolders::keep() { kept_ = true; }

void unregisterTemporary(const fs::path& temporary) {
  const std::string t = temporary.string();
  for (Slot& slot : slots)
    if (slot.state.load() == 2 && std::strcmp(slot.temporary.data(), t.c_str()) == 0) {
      slot.state.store(0);
      return;
    }
}

void installInterruptCleanup() {
  struct sigaction action {};
  action.sa_handler = onTerminatingSignal;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);  // one clean-up at a time
  sigaddset(&action.sa_mask, SIGTERM);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

std::string signalName(int signal) {
  const char* name = ::sigabbrev_np(signal);
  return std::string("SIG") + (name != nullptr ? name : "?");
}

void installCrashReport() {
#if !defined(ROLLSPIN_ADDRESS_SANITIZER)  // the sanitizers report crashes themselves, better
  std::array<void*, 1> warmUp{};
  (void)::backtrace(warmUp.data(), 1);  // loads libgcc_s now, not in the handler
  // Its own stack, so that a stack overflow can still be reported.
  static std::array<char, 64 * 1024> alternateStack;
  stack_t stack{};
  stack.ss_sp = alternateStack.data();
  stack.ss_size = alternateStack.size();
  ::sigaltstack(&stack, nullptr);
  struct sigaction action {};
  action.sa_handler = onFatalSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_ONSTACK;
  for (const int signal : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) sigaction(signal, &action, nullptr);
#endif
}

void interruptCleanupAndExit(int signal) {
  // Only async-signal-safe calls from here on: unlink, rmdir, write, _exit.
  static std::atomic<bool> running{false};
  if (running.exchange(true)) {
    for (;;) ::pause();  // another thread is cleaning up and will exit
  }
  say("\nrollspin: interrupted (");
  saySignalName(signal);
  say(")");
  say(removeRegisteredTemporaries()
          ? "; any output already reported as written is complete\n"
          : ": nothing unfinished left; any output already reported as written is complete\n");
  ::_exit(128 + signal);
}

}  // namespace rollspin
