// AtomicFile — write an output under a temporary name in the same directory
// and rename it over the final name only on commit(), so a failed or
// interrupted run never leaves a half-written file at the final path.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace rollspin {

class AtomicFile {
 public:
  // Opens "<dir>/.<name>.<pid>.tmp" for binary writing; throws Error
  // (Runtime) when the directory is missing or not writable.
  explicit AtomicFile(std::filesystem::path finalPath);
  ~AtomicFile();  // removes the temporary file unless committed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  [[nodiscard]] std::FILE* handle() const { return file_; }
  void write(std::string_view bytes);
  // Flushes, checks for write errors (a full disk shows up here), closes and
  // renames. Throws Error (Runtime) on any failure, leaving nothing behind.
  void commit();

  [[nodiscard]] const std::filesystem::path& finalPath() const { return finalPath_; }
  [[nodiscard]] const std::filesystem::path& tempPath() const { return tempPath_; }

 private:
  void discard();
  std::filesystem::path finalPath_;
  std::filesystem::path tempPath_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
  bool direct_ = false;  // final path is a device or pipe: no temp, no rename
};

}  // namespace rollspin
