// Streams the orientation timeline of a scene to a file: CSV (RFC 4180: the
// header row first, then one row per sample in full precision, %.17g), JSON,
// or numpy's .npy / .npz (timeline_files.cpp); each written under a temporary
// name and renamed when complete. CSV, JSON and .npy stream (memory does not
// grow with the number of samples); .npz holds the columns until it is written.
//
// Columns: s, px,py,pz (contact point P), nx,ny,nz (normal n), cx,cy,cz
// (centre C = P + R n), qw,qx,qy,qz (U = qw − i q·σ, worldFromBody, not
// sign-normalised), Bx,By,Bz (field B = −ω), tx,ty,tz (tangent t),
// kappa_n, kappa_g, tau_g; a storyboard adds `segment`, the number (from 1)
// of the segment whose motion the row is in, and a storyboard of several
// surfaces then `surface`, that segment's surface index (from 0).
// The method and steps, the a posteriori error estimate of U(L)
// (spin::estimateError) with its basis and cost, the scene text and the
// version go to a sidecar NAME.csv.json (NAME.npy.json, NAME.npz.json; a JSON
// timeline holds them itself); --comment-header puts the old '#' line
// ("# rollspin timeline: …") above the CSV's header row as well.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "model/rolling_model.hpp"
#include "motion/solve_job.hpp"
#include "spin/propagator.hpp"

namespace rollspin::jobs {

using model::RollingModel;
using motion::SolverChoice;

// The columns every row has, in order (the CSV header and the Python
// Timeline's names); a storyboard adds "segment".
inline constexpr std::array<std::string_view, 23> kTimelineColumns{
    "s",  "px", "py", "pz", "nx", "ny", "nz", "cx", "cy",      "cz",      "qw",   "qx",
    "qy", "qz", "Bx", "By", "Bz", "tx", "ty", "tz", "kappa_n", "kappa_g", "tau_g"};

struct TimelineRow {
  std::array<double, kTimelineColumns.size()> values{};
  std::size_t segment = 0;  // the storyboard segment (from 1) whose motion the row is in; 0: not a storyboard
  std::size_t surface = 0;  // that segment's surface (RollingModel::surfaces index)
};
using TimelineRowSink = std::function<void(std::size_t index, const TimelineRow& row)>;

// Solves along the path and hands each sample's row to `sink`, in order: the
// one sampling the CSV and the Python binding share. Throws Runtime (at
// `where`) when the solver fails; rows already handed over are then partial.
spin::SolveStats sampleTimeline(const RollingModel& model, const SolverChoice& choice,
                                const spin::SampleArcLengths& sampleS, const TimelineRowSink& sink,
                                const std::string& where);
// Whether `model` is a storyboard, i.e. rows carry a segment number.
[[nodiscard]] bool timelineHasSegments(const RollingModel& model);
// Whether rows carry a surface index: a storyboard of several surfaces.
[[nodiscard]] bool timelineHasSurfaces(const RollingModel& model);

enum class TimelineFormat { Csv, Json, Npy, Npz };
// The format of `out` by its extension (.csv, .json, .npy, .npz); any other
// is BadInput at `where` (-o), never CSV under a wrong name.
[[nodiscard]] TimelineFormat timelineFormatOf(const std::filesystem::path& out, const SourceLoc& where);

struct TimelineFileOptions {
  std::string sceneText;       // the resolved scene (scene::writeScene)
  bool commentHeader = false;  // CSV: the '#' line above the header row
};

// `solved`: the scene's solve of U(L) with its error estimate
// (motion::solveScene, whose refined step count `choice` carries).
[[nodiscard]] spin::SolveStats writeTimelineFile(const std::filesystem::path& out, const RollingModel& model,
                                                 const SolverChoice& choice, const spin::SampleArcLengths& sampleS,
                                                 const spin::SolveStats& solved, const TimelineFileOptions& options);

}  // namespace rollspin::jobs
