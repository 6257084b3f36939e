#include "core/output_path.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/temp_files.hpp"

namespace rollspin {

namespace fs = std::filesystem;

namespace {

fs::path folderOf(const fs::path& p) { return p.has_parent_path() ? p.parent_path() : fs::path("."); }

// The nearest ancestor of `p` that exists (p itself included), "." at worst.
fs::path nearestExisting(fs::path p) {
  std::error_code ec;
  while (!p.empty() && !fs::exists(p, ec)) {
    if (!p.has_parent_path() || p.parent_path() == p) return ".";
    p = p.parent_path();
  }
  return p.empty() ? fs::path(".") : p;
}

// Whether a new entry can be made in `folder`: permission bits, read-only
// mounts, ACLs and root all answer the same way to actually trying.
void requireWritableFolder(const fs::path& folder, const fs::path& output, const SourceLoc& where) {
  const fs::path probe = temporaryPathFor(folder / ("rollspin-probe-" + output.filename().string()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) {
    const int err = errno;
    throw badInput(where, "cannot write in the folder '{}': {}", folder.string(), std::strerror(err));
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

// A file where the path needs a folder: name the file.
void requireNoFileInTheWay(const fs::path& folder, const fs::path& output, const SourceLoc& where) {
  const fs::path existing = nearestExisting(folder);
  std::error_code ec;
  if (fs::is_directory(existing, ec)) return;
  throw badInput(where, "'{}' is a file, not a folder, so '{}' cannot be written", existing.string(), output.string());
}

}  // namespace

void checkOutputFile(const fs::path& file, const SourceLoc& where) {
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (fs::is_directory(status)) throw badInput(where, "'{}' is a directory; give a file name", file.string());
  if (fs::exists(status) && !fs::is_regular_file(status)) return;  // a device or pipe, written in place
  if (!file.has_filename() || file.filename() == "." || file.filename() == "..")
    throw badInput(where, "'{}' names a folder; give a file name", file.string());
  const fs::path folder = folderOf(file);
  if (!fs::is_directory(folder, ec)) {
    requireNoFileInTheWay(folder, file, where);
    throw badInput(where, "the folder '{}' does not exist (create it first)", folder.string());
  }
  requireWritableFolder(folder, file, where);
}

void checkOutputFolder(const fs::path& folder, const SourceLoc& where) {
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
    throw badInput(where, "'{}' is a file; a folder is needed here", folder.string());
  requireNoFileInTheWay(folder, folder, where);
  const fs::path existing = nearestExisting(folder);
  requireWritableFolder(existing, folder.has_filename() ? folder : folder.parent_path(), where);
}

fs::path defaultOutputFile(const std::string& name) { return fs::path("output") / name; }

void createOutputParent(const fs::path& file) {
  if (!file.has_parent_path()) return;
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  if (ec)
    throw runtimeError(SourceLoc{file.string()}, "cannot create the folder {}: {}", file.parent_path().string(),
                       ec.message());
}

}  // namespace rollspin
