// The scene schema, one table per section: every key of [ball], [plate],
// [path], [solver], [timeline], [render], [figure], [labels], [animation],
// [[segment]] and a segment's camera is one KeyRow (key_row.hpp) in
// scene_tables.cpp, the only file that spells its name. The loader, `scene --print`, `rollspin keys` and
// docs/scene-reference.md all walk these tables; rule code (cross-key checks)
// names a key through the constants below.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "scene/key_row.hpp"

namespace rollspin::scene {

[[nodiscard]] const KeyTable<BallSpec>& ballKeys();
[[nodiscard]] const KeyTable<PlateSpec>& plateKeys();
[[nodiscard]] const KeyTable<PathSpec>& pathKeys();
[[nodiscard]] const KeyTable<SolverSpec>& solverKeys();
[[nodiscard]] const KeyTable<TimelineSpec>& timelineKeys();
[[nodiscard]] const KeyTable<RenderSpec>& renderKeys();
[[nodiscard]] const KeyTable<FigureSpec>& figureKeys();
[[nodiscard]] const KeyTable<LabelsSpec>& labelsKeys();
[[nodiscard]] const KeyTable<AnimationSpec>& animationKeys();
[[nodiscard]] const KeyTable<SegmentSpec>& segmentKeys();
[[nodiscard]] const KeyTable<CameraSpec>& segmentCameraKeys();

// The row of `rows` named `name`; throws std::logic_error for a name the table lacks.
template <class S>
[[nodiscard]] const KeyRow<S>& rowOf(const KeyTable<S>& rows, std::string_view name) {
  for (const KeyRow<S>& row : rows)
    if (row.name == name) return row;
  throw std::logic_error("scene key table: no key " + std::string(name));
}

// The names rule code and other tables refer to (each spelled once, in
// scene_tables.cpp).
namespace key {
extern const std::string_view kRadius, kMethod, kSteps, kTolerance;
extern const std::string_view kWidth, kHeight, kTransparent, kTitle, kTarget, kFollow, kDistance, kFormat, kBackend,
    kDevice, kMsaa;
extern const std::string_view kWidthMm, kWidthIn, kFontSizePt;
extern const std::string_view kFacts, kLabels;
extern const std::string_view kFps, kDuration, kSpeed, kHold;
extern const std::string_view kLength, kDirectionVector, kTurns, kDirection, kStartAzimuthDeg, kColatitudeDeg,
    kTubeAngleDeg, kAzimuthDeg, kColatitudeStartDeg, kColatitudeEndDeg, kPitchAngleDeg, kHeadingDeg, kStartPoint, kU,
    kV, kTStart, kTEnd, kPoints, kClosed, kInterpolation, kCornerRadius, kCurvatureStart, kCurvatureRate;
extern const std::string_view kPath, kSurface, kCamera, kCaption, kTransition, kFadeSeconds;
}  // namespace key

}  // namespace rollspin::scene
