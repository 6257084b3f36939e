// Streams the orientation timeline of a scene to CSV: one header row, then one
// row per sample in full precision (%.17g), written under a temporary name and
// renamed when complete. Memory does not grow with the number of samples.
//
// Columns: s, px,py,pz (contact point P), nx,ny,nz (normal n), cx,cy,cz
// (centre C = P + R n), qw,qx,qy,qz (U = qw − i q·σ, worldFromBody, not
// sign-normalised), Bx,By,Bz (field B = −ω), tx,ty,tz (tangent t),
// kappa_n, kappa_g, tau_g; a storyboard adds `segment`, the number (from 1)
// of the segment whose motion the row is in.
#pragma once

#include <filesystem>
#include <span>

#include "model/rolling_model.hpp"
#include "motion/solve_job.hpp"
#include "spin/propagator.hpp"

namespace rollspin::app {

using model::RollingModel;
using motion::SolverChoice;

[[nodiscard]] spin::SolveStats writeTimelineCsv(const std::filesystem::path& out, const RollingModel& model,
                                                const SolverChoice& choice, const spin::SampleArcLengths& sampleS);

}  // namespace rollspin::app
