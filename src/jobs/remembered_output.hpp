// Outputs that remember how they were made (docs/remake.md): every still,
// figure and clip carries the resolved scene, a job record, the version and a
// one-sentence description (media/output_metadata.hpp, and the container tags
// of a video), so that `rollspin scene --from FILE` prints the scene and
// `rollspin render --from FILE` draws it again the same way.
//
// The job record is lines of `key: value`:
//   render: still | figure | clip      what drew it
//   scene: NAME                        the scene's name (the default output's name)
//   at: fraction=0.5                   a still's or figure's --at, when given
//   frames: FIRST:LAST                 the frames a clip holds (0-based, inclusive)
//   figure_layout: true | false        a raster still laid out for a figure's printed size
// Size, quality, transparency and frame rate are in the resolved scene
// (the flags became its keys), so the record holds only what is not a key.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "media/output_metadata.hpp"
#include "model/rolling_model.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::jobs {

struct JobRecord {
  enum class Kind { Still, Figure, Clip } kind = Kind::Still;
  std::string sceneName;
  std::optional<std::string> at;      // --at
  std::optional<std::string> frames;  // "FIRST:LAST"
  bool figureLayout = false;
};

[[nodiscard]] std::string writeJobRecord(const JobRecord& job);
// BadInput at `where` (FILE[rollspin:job]:LINE) for a line it cannot read.
[[nodiscard]] JobRecord parseJobRecord(const std::string& text, const std::string& where);

// The alt text: "A ball of radius 1 rolls once round a circle of radius 3 on
// a plane; beside it the spin on the Bloch sphere."
[[nodiscard]] std::string describeScene(const scene::SceneSpec& spec, const model::RollingModel& model);

// The metadata of a job's output: the scene as scene::writeScene writes it
// (loading it gives the same scene), the record, the version, the alt text.
[[nodiscard]] media::OutputMetadata outputMetadata(const scene::SceneSpec& spec, const model::RollingModel& model,
                                                   const JobRecord& job);

// The video container tags that carry the same (added to a clip's tags).
[[nodiscard]] std::vector<std::pair<std::string, std::string>> metadataTags(const media::OutputMetadata& m);

// What an output file remembers: its scene text and the name to load it
// under ("output/torus.png[rollspin:scene]", so that errors point into it),
// and its job. Any still, figure, GIF or video rollspin wrote, or a
// timeline's sidecar (NAME.csv → NAME.csv.json). BadInput naming the file
// and what is missing when it carries no (or broken) rollspin metadata.
struct RememberedOutput {
  media::OutputMetadata metadata;
  std::string sourceName;
  std::string sceneName;         // the job's, else the file's stem
  std::optional<JobRecord> job;  // none for a timeline, a glTF or a viewer page
};
[[nodiscard]] RememberedOutput readRememberedOutput(const std::filesystem::path& file);

}  // namespace rollspin::jobs
