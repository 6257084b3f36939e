// Writing a glTF export: .glb through AtomicFile; .gltf and its .bin
// written by tinygltf into a private temporary folder beside them, then each
// renamed into place (the .bin first, so a .gltf never names a missing one).
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <system_error>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_path.hpp"
#include "core/temp_files.hpp"
#include "export/gltf_builder.hpp"
#include "export/gltf_export.hpp"

namespace rollspin::gltf {

namespace {

std::string lowerExtension(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void writeGlb(const ExportRequest& request, const std::filesystem::path& output) {
  const std::vector<std::uint8_t> bytes = exportGlb(request);
  AtomicFile file(output);
  file.write(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  file.commit();
}

// A temporary folder that removes itself (and what tinygltf wrote into it)
// unless emptied by the renames; registered for Ctrl-C.
struct TemporaryFolder {
  explicit TemporaryFolder(std::filesystem::path p) : path(std::move(p)) {
    std::error_code ec;
    std::filesystem::create_directory(path, ec);
    if (ec) throw runtimeError({path.string()}, "could not create a temporary folder: {}", ec.message());
    registerTemporary(path, path, true);
  }
  ~TemporaryFolder() {
    unregisterTemporary(path);
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  std::filesystem::path path;
};

void writeGltfAndBin(const ExportRequest& request, const std::filesystem::path& output) {
  GltfBuilder builder = buildModel(request);
  const std::filesystem::path bin = std::filesystem::path(output).replace_extension(".bin");
  builder.model().buffers[0].uri = bin.filename().string();
  const TemporaryFolder folder(temporaryPathFor(output));
  const std::filesystem::path staged = folder.path / output.filename();
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToFile(&builder.model(), staged.string(), false, false, true, false))
    throw runtimeError({output.string()}, "tinygltf could not write {} and its buffer", output.string());
  std::error_code ec;
  for (const auto& [from, to] : {std::pair{folder.path / bin.filename(), bin}, std::pair{staged, output}}) {
    std::filesystem::rename(from, to, ec);
    if (ec) throw runtimeError({to.string()}, "could not rename the finished file into place: {}", ec.message());
  }
}

}  // namespace

void checkGltfOutput(const std::filesystem::path& output) {
  const SourceLoc where{"-o " + output.string()};
  const std::string ext = lowerExtension(output);
  if (ext != ".glb" && ext != ".gltf")
    throw badInput(where, "expected a .glb or .gltf file name (got {})",
                   ext.empty() ? "no extension" : "'" + ext + "'");
  checkOutputFile(output, where);
  if (ext == ".gltf") checkOutputFile(std::filesystem::path(output).replace_extension(".bin"), where);
}

void writeGltf(const ExportRequest& request, const std::filesystem::path& output) {
  checkGltfOutput(output);
  if (lowerExtension(output) == ".glb") writeGlb(request, output);
  else writeGltfAndBin(request, output);
}

}  // namespace rollspin::gltf
