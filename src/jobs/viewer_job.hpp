// The web viewer job: `rollspin render SCENE -o NAME.html` (the output-format
// row "html", kind Viewer) writes one self-contained page: the viewer's
// JavaScript (web/, three.js bundled by esbuild at build time and embedded
// here), the scene's meshes as the glTF exporter's GLB (base64), the
// solver's timeline (jobs/viewer_timeline.hpp: q, B and C at knots that the
// page interpolates with the solver's own derivatives), the resolved scene
// text (<script type="application/toml" id="rollspin-scene">) and the
// version (<meta name="generator">). It opens from file:// with no network.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "jobs/job_setup.hpp"

namespace rollspin::jobs {

// The page of a prepared job (job.format is the "html" row). sourceName:
// what the resolved scene's header calls the scene (its path as given).
[[nodiscard]] std::string viewerHtml(const DrawJob& job, const std::string& sourceName);

// Writes viewerHtml under a temporary name, then renames it to `out`.
void writeViewerHtml(const DrawJob& job, const std::string& sourceName, const std::filesystem::path& out);

// The embedded assets of the page (built from web/ by CMake): "viewer.js"
// (the esbuild bundle) and "page.html" (the template); empty when unknown.
[[nodiscard]] std::string_view embeddedViewerAsset(std::string_view name);

// RFC 4648 base64 of `bytes` (the GLB inside the page).
[[nodiscard]] std::string base64(std::string_view bytes);

}  // namespace rollspin::jobs
