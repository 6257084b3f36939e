#include "jobs/export_job.hpp"

#include "export/gltf_export.hpp"
#include "jobs/render_jobs.hpp"
#include "jobs/scene_print.hpp"
#include "model/rolling_model.hpp"

namespace rollspin::jobs {

void checkExportOutput(const std::filesystem::path& output) { gltf::checkGltfOutput(output); }

std::filesystem::path exportGltf(const ExportJob& job) {
  const scene::SceneSpec& spec = *job.spec;
  const model::RollingModel model = model::buildSceneModel(spec);
  std::filesystem::path out = job.output;
  if (out.empty()) {
    std::filesystem::create_directories("output");
    out = std::filesystem::path("output") / (spec.name + ".glb");
  }
  gltf::ExportRequest request;
  request.spec = &spec;
  request.model = &model;
  request.ballTexture = loadBallTexture(spec);
  request.version = ROLLSPIN_VERSION;
  request.metadata = job.metadata;
  if (request.metadata) request.sceneText = resolvedSceneText(job.sceneSource, spec);
  gltf::writeGltf(request, out);
  return out;
}

}  // namespace rollspin::jobs
