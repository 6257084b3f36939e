#include "support/cli_runner.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <signal.h>
#include <spawn.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace rollspin::test {

void expectBadScene(const BadScene& c) {
  const auto dir = freshTempDir("bad_scene");
  const auto scene = dir / "scene.toml";
  std::ofstream(scene) << c.toml;
  const auto out = dir / "timeline.csv";
  const auto r = runRollspin({"timeline", scene.string(), "-o", out.string()});
  EXPECT_EQ(r.exitCode, 2) << c.name << "\n" << r.err;
  EXPECT_NE(r.err.find(c.key), std::string::npos) << c.name << ": key missing in\n" << r.err;
  EXPECT_NE(r.err.find(scene.string() + c.where), std::string::npos) << c.name << ": file:line:col missing in\n"
                                                                     << r.err;
  EXPECT_NE(r.err.find(c.hint), std::string::npos) << c.name << ": expectation missing in\n" << r.err;
  std::size_t files = 0;  // nothing written, no temporary left behind
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.path() != scene;
  EXPECT_EQ(files, 0u) << c.name;
  std::filesystem::remove_all(dir);
}


CliResult runRollspin(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                      std::uint64_t addressSpaceLimit, const std::vector<std::string>& environment) {
  // stdout/stderr go to files: simple, no pipe deadlocks on large output.
  const std::filesystem::path dir = freshTempDir("cli");
  const std::string outPath = (dir / "stdout").string(), errPath = (dir / "stderr").string();
  std::vector<std::string> argvStore{binaryPath().string()};
  argvStore.insert(argvStore.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argvStore) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> envStore;
  // An entry of `environment` replaces the inherited variable of that name
  // (getenv would find the inherited one first): a test that sets
  // ROLLSPIN_GL must win over the one a CI pass runs under.
  auto nameOf = [](const std::string& entry) { return entry.substr(0, entry.find('=')); };
  std::set<std::string> replaced;
  for (const auto& e : environment) replaced.insert(nameOf(e));
  // A device the caller's shell picks (ROLLSPIN_EGL_DEVICE=0 for Mesa's
  // software device, say) is not passed on: the tests name the devices they
  // mean, and the EGL pass chooses the backend, not the device.
  replaced.insert("ROLLSPIN_EGL_DEVICE");
  for (char** e = environ; *e != nullptr; ++e)
    if (!replaced.contains(nameOf(*e))) envStore.emplace_back(*e);
  envStore.insert(envStore.end(), environment.begin(), environment.end());
  std::vector<char*> envp;
  for (auto& e : envStore) envp.push_back(e.data());
  envp.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    // Child: only async-signal-safe calls until exec.
    const int out = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0) _exit(127);
    if (!cwd.empty() && chdir(cwd.c_str()) != 0) _exit(127);
    if (addressSpaceLimit > 0) {
      const rlimit limit{addressSpaceLimit, addressSpaceLimit};
      if (setrlimit(RLIMIT_AS, &limit) != 0) _exit(127);
    }
    execve(argv[0], argv.data(), envp.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  CliResult result;
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = readFile(outPath);
  result.err = readFile(errPath);
  std::filesystem::remove_all(dir);
  return result;
}

void sleepMilliseconds(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

SpawnedRollspin::SpawnedRollspin(const std::vector<std::string>& args, const std::filesystem::path& errFile) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  std::vector<std::string> store{binaryPath().string()};
  store.insert(store.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : store) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  pid_ = pid;
  if (pid_ < 0) throw std::runtime_error("posix_spawn failed");
}

SpawnedRollspin::~SpawnedRollspin() {
  if (!reaped_) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
}

bool SpawnedRollspin::running() {
  if (reaped_) return false;
  if (waitpid(pid_, &status_, WNOHANG) == pid_) reaped_ = true;
  return !reaped_;
}

int SpawnedRollspin::wait(bool* signalled) {
  if (!reaped_) {
    waitpid(pid_, &status_, 0);
    reaped_ = true;
  }
  if (signalled != nullptr) *signalled = WIFSIGNALED(status_);
  return WIFEXITED(status_) ? WEXITSTATUS(status_) : 128 + WTERMSIG(status_);
}

}  // namespace rollspin::test
