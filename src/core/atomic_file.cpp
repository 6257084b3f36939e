#include "core/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.hpp"
#include "core/temp_files.hpp"

namespace rollspin {

AtomicFile::AtomicFile(std::filesystem::path finalPath) : finalPath_(std::move(finalPath)) {
  const auto dir = finalPath_.has_parent_path() ? finalPath_.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (std::filesystem::is_directory(finalPath_, ec)) {
    throw runtimeError({finalPath_.string()}, "the output '{}' is a directory; give a file name", finalPath_.string());
  }
  if (!std::filesystem::is_directory(dir, ec)) {
    throw runtimeError({finalPath_.string()}, "output directory '{}' does not exist", dir.string());
  }
  // A device or pipe (/dev/null, /dev/full, a FIFO) is written in place:
  // renaming over it would replace the device node, and there is nothing
  // half-written to hide there.
  const auto status = std::filesystem::status(finalPath_, ec);
  direct_ = std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
  if (!direct_) removeStaleTemporaries(finalPath_);
  tempPath_ = direct_ ? finalPath_ : temporaryPathFor(finalPath_);
  file_ = std::fopen(tempPath_.c_str(), "wb");
  if (file_ == nullptr) {
    throw runtimeError({finalPath_.string()}, "cannot write in '{}': {}", dir.string(), std::strerror(errno));
  }
  if (!direct_) registerTemporary(tempPath_, finalPath_);
}

AtomicFile::~AtomicFile() {
  if (!committed_) discard();
}

void AtomicFile::discard() {
  if (file_ != nullptr) {
    std::fclose(file_);
    file_ = nullptr;
  }
  if (!direct_) {
    std::error_code ec;
    std::filesystem::remove(tempPath_, ec);
    unregisterTemporary(tempPath_);
  }
}

void AtomicFile::write(std::string_view bytes) {
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) {
    const int err = errno;
    discard();
    throw runtimeError({finalPath_.string()}, "write failed: {}", std::strerror(err));
  }
}

void AtomicFile::commit() {
  // fflush + ferror catch ENOSPC (e.g. /dev/full) before the rename.
  const bool flushed = std::fflush(file_) == 0 && std::ferror(file_) == 0;
  const int err = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) {
    discard();
    throw runtimeError({finalPath_.string()}, "write failed: {}", std::strerror(err ? err : EIO));
  }
  if (direct_) {
    committed_ = true;
    return;
  }
  std::error_code ec;
  std::filesystem::rename(tempPath_, finalPath_, ec);
  if (ec) {
    discard();
    throw runtimeError({finalPath_.string()}, "cannot rename temporary file into place: {}", ec.message());
  }
  unregisterTemporary(tempPath_);
  committed_ = true;
}

}  // namespace rollspin
