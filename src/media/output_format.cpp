#include "media/output_format.hpp"

#include <fmt/format.h>

#include <cctype>
#include <system_error>

#include "core/text.hpp"

namespace rollspin::media {

namespace fs = std::filesystem;

namespace {

std::string quoted(std::string_view name) { return fmt::format("\"{}\"", name); }

}  // namespace

std::string OutputFormat::defaultExtension() const { return std::string(extensions.substr(0, extensions.find(' '))); }

bool OutputFormat::hasExtension(std::string_view ext) const {
  std::string_view rest = extensions;
  while (!rest.empty()) {
    const auto space = rest.find(' ');
    if (rest.substr(0, space) == ext) return true;
    rest = space == std::string_view::npos ? std::string_view{} : rest.substr(space + 1);
  }
  return false;
}

const OutputFormat* findOutputFormat(std::string_view name, OutputUse use) {
  for (const OutputFormat& f : kOutputFormats)
    if (f.name == name && f.use() == use) return &f;
  return nullptr;
}

bool isOutputFormatName(std::string_view name) {
  for (const OutputFormat& f : kOutputFormats)
    if (f.name == name) return true;
  return false;
}

std::string outputFormatNames() {
  std::string out;
  for (std::size_t i = 0; i < kOutputFormats.size(); ++i) {
    bool seen = false;
    for (std::size_t j = 0; j < i; ++j) seen = seen || kOutputFormats[j].name == kOutputFormats[i].name;
    if (!seen) out += (out.empty() ? "" : ", ") + quoted(kOutputFormats[i].name);
  }
  return out;
}

std::string describeFormats(OutputUse use) {
  std::string out;
  for (const OutputFormat& f : kOutputFormats) {
    if (f.use() != use) continue;
    std::string where;
    for (char c : f.extensions) where += c == ' ' ? std::string(", ") : std::string(1, c);
    if (f.isFolder()) where = "a folder of frames";
    out += fmt::format("{}{} ({})", out.empty() ? "" : ", ", f.name, where);
  }
  return out;
}

const OutputFormat& chooseFormat(const std::optional<std::string>& requested, const SourceLoc& requestedAt,
                                 const fs::path& output, OutputUse use) {
  const std::string ext = asciiLowercase(output.extension().string());
  const SourceLoc outputAt{"-o " + output.string()};
  std::error_code ec;  // a path through a file is simply not a folder
  const bool isDirectory = !output.empty() && fs::is_directory(output, ec);
  const bool animation = use == OutputUse::Animation;
  const char* job = animation ? "an animation" : "a still (--still)";

  if (requested) {
    const OutputFormat* f = findOutputFormat(*requested, use);
    // render.format describes the clip: a still of the same scene keeps
    // choosing by its own -o. A clip cannot be a still format.
    if (f == nullptr && animation)
      throw badInput(requestedAt,
                     "render.format = \"{}\" is a still format (pass --still for one image); {} is "
                     "written as {}",
                     *requested, job, describeFormats(use));
    if (f != nullptr) {
      if (f->isFolder() && !ext.empty() && !isDirectory)
        throw badInput(requestedAt, "render.format = \"{}\" writes a folder of frames, but -o names {}", f->name,
                       output.string());
      if (!f->isFolder() && isDirectory)
        throw badInput(outputAt, "render.format = \"{}\" needs a file name, but {} is a folder", f->name,
                       output.string());
      if (!f->isFolder() && !ext.empty() && !f->hasExtension(ext))
        throw badInput(requestedAt, "render.format = \"{}\" writes {} files, but -o names {}", f->name, f->extensions,
                       output.string());
      return *f;
    }
  }

  const auto rowFor = [&](OutputUse u) -> const OutputFormat* {
    for (const OutputFormat& f : kOutputFormats)
      if (f.use() == u && !f.isFolder() && f.hasExtension(ext)) return &f;
    return nullptr;
  };
  if (output.empty()) return *findOutputFormat(animation ? "mp4" : "png", use);
  // A folder named like a video file (out.mp4/) is still meant as that file:
  // the job's output check then refuses it before any work.
  if (animation && (ext.empty() || (isDirectory && rowFor(use) == nullptr))) return *findOutputFormat("png", use);
  if (!animation && ext.empty()) return *findOutputFormat("png", use);
  if (const OutputFormat* f = rowFor(use)) return *f;
  if (const OutputFormat* other = rowFor(animation ? OutputUse::Still : OutputUse::Animation)) {
    if (animation && other->name == "png")
      throw badInput(outputAt,
                     "an animation's PNG frames go to a folder (e.g. -o output/frames/); for one image "
                     "pass --still");
    if (animation)
      throw badInput(outputAt, "{} is a still format (pass --still for one image); {} is written as {}", ext, job,
                     describeFormats(use));
    throw badInput(outputAt, "{} is an animation format (drop --still for a clip); {} is written as {}", ext, job,
                   describeFormats(use));
  }
  throw badInput(outputAt, "unknown {} format '{}': {} is written as {}", animation ? "video" : "image", ext, job,
                 describeFormats(use));
}

}  // namespace rollspin::media
