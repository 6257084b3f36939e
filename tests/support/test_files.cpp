#include "support/test_files.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>

namespace rollspin::test {

std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string shippedScenePath(const std::string& name) { return (sourceDir() / "scenes" / (name + ".toml")).string(); }
std::string renderTestScenePath(const std::string& name) {
  return (sourceDir() / "tests/render/scenes" / (name + ".toml")).string();
}

// Named by the process id: two test programs that run at once (ctest -j)
// never share a directory.
std::filesystem::path freshTempDir(const std::string& name) {
  const std::filesystem::path dir = testTmpRoot() / (name + "." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace rollspin::test
