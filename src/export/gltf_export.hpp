// glTF 2.0 export: the scene as meshes and one animation, through Debian's
// tinygltf (never a hand-written writer). The ball's orientation is the
// solver's U(s) read as the unit quaternion q = (qw, qx, qy, qz) of
// U = qw·1 − i(qx σx + qy σy + qz σz) (docs/conventions.md), keyed in the
// clip's seconds t = f / fps, where f is the fractional frame of the MP4's
// frame clock (motion::FrameClock::arcLengthAt: storyboards and holds
// included). Between keys glTF slerps; keys are placed so that
//   angle(slerp(q_i, q_{i+1}, x), q(s(t))) ≤ 1e-6 rad   for every t in a key interval
// (bisection in t until the midpoint's slerp, from the float32 keys the file
// holds, is within kMidpointTolerance of the solver's q there).
//
// What the file holds (a contract: the web viewer and `rollspin scene --from`
// rely on it; extend, never rename):
//
// Nodes (scene 0 has the one root):
//   "rollspin"  root; rotation −90° about x: the scene's +z up becomes glTF's
//               +y up (+x stays +x, scene +y becomes glTF −z). Everything
//               below is in scene coordinates, 1 unit = 1 scene unit.
//     "surface" mesh "surface": the surface the renders show (the ball view's
//               mesh: board, sphere or chart patch), checker as a texture;
//               absent when the scene has no surface to mesh.
//     "path"    mesh "path": a thin tube along the contact path P(s), lifted
//               by its radius along the surface normal.
//     "surface.k", "path.k"  (k = 1, 2, …) a storyboard on several surfaces:
//               the k-th stretch's surface and path (motion::surfaceStretches;
//               "surface" and "path" are the first), static scale 0; every
//               stretch's pair is shown by a STEP "scale" channel of "roll",
//               1 from its cut (secondsJustAfter the clip's last frame on
//               the stretch before) to the next cut; until a cut the ball is
//               keyed on the earlier stretch's path (roll_keys.cpp).
//     "ball"    mesh "ball": a sphere of radius R about the node origin,
//               textured like the renders (u = longitude, v = colatitude of
//               the body frame). translation = the ball's centre C(s),
//               rotation = q(s) (worldFromBody), both animated. extras:
//                 {"rollspin": {"arc_length": A, "spinor_sign": B,
//                               "version": "…", "scene": "…"}}
//               A, B: accessor indices (SCALAR float, one per key of "roll"):
//               s of each key, and ±1 with sign × the key's quaternion = the
//               solver's q (the keys are canonical, qw ≥ 0, as glTF readers
//               normalise them: the sign is −1 wherever the solver's qw < 0,
//               the spinor's negative sheet). "scene": the resolved
//               scene text (`rollspin scene --print`), left out with
//               --no-metadata.
//     "bloch"   mesh "bloch": the unit Bloch sphere (translucent glass),
//               translation beside the surface, uniform scale = its radius
//               in scene units (ExportedScene::blochCentre, blochRadius).
//       "spin"  mesh "spin": an arrow from the origin to X(0) (the marker's
//               body direction), rotation = q(s), animated: the arrow shows
//               X(s) = R(q(s)) X(0).
//       "field" mesh "field": an arrow from the origin along +z, rotation
//               taking +z to B(s)/|B(s)| (shortest arc), animated.
// Materials (PBR metallic-roughness, colours the renders' linear RGB):
//   "surface" (checker texture, double-sided), "path", "ball" (its texture),
//   "bloch" (alphaMode BLEND), "spin", "field"; each with extras
//   {"rollspin": {"specular", "shininess"}}, the renders' Blinn–Phong terms.
//   Textures: PNG images in the buffer.
// Animation "roll" (the motion's samplers LINEAR, one shared input of key
//   times in seconds, starting at 0): channels ball/translation,
//   ball/rotation, spin/rotation, field/rotation; on several surfaces also
//   surface*/scale and path*/scale (STEP, their own input: 0 and each cut). A key at every motion start and stop of
//   the clip, at every whole frame of a motion, at every corner and joint of
//   the path, and where the bisection puts them; the last key is the clip's
//   last frame, (frameCount − 1) / fps seconds. Times are float32: each key's
//   s and q are the solver's at the float time the file holds.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "geometry/surface.hpp"
#include "model/rolling_model.hpp"
#include "render/draw_list.hpp"
#include "scene/scene_spec.hpp"
#include "spin/su2.hpp"

namespace rollspin::gltf {

// The midpoint check of the key bisection (rad); the other half of the
// 1e-6 rad budget covers the rest of an interval and the float32 rounding.
inline constexpr double kMidpointTolerance = 0.5e-6;

// What a job has: the scene as loaded (with --set), its model, and what the
// file records beside them.
struct ExportRequest {
  const scene::SceneSpec* spec = nullptr;
  const model::RollingModel* model = nullptr;
  std::shared_ptr<const render::TextureImage> ballTexture;  // null: the tennis ball
  std::string version;                                      // extras.rollspin.version
  std::string sceneText;                                    // extras.rollspin.scene
  bool metadata = true;                                     // false: no "scene" in extras (--no-metadata)
  bool animation = true;  // false: no animation "roll" and no extras (the web viewer poses the nodes itself)
};

// The keys of animation "roll", in file order (times strictly increasing).
struct RollKeys {
  std::vector<float> seconds;       // what the file holds
  std::vector<double> arcLength;    // s(t) at each float time
  std::vector<spin::Su2> rotation;  // the solver's q at s (sign kept)
  std::vector<geometry::Vec3> centre;
  std::vector<geometry::Vec3> field;  // B/|B| at s (unit; +z where B = 0)
};

// A float32 time "at" a whole frame may round a little past it: a time
// belongs to frame ⌈t · fps − kFrameSlack⌉ (a fractional frame leads up to
// the next whole one).
inline constexpr double kFrameSlack = 1e-4;
// The first float32 second past `frame` by more than the slack: where the
// clip leaves that whole frame (a surface change's cut, its key).
[[nodiscard]] float secondsJustAfter(double frame, double fps);

// The keys for a scene: the frame clock's motion bounds, the path's corners
// and joints, then bisection. Runs the scene's solver (a march a round).
[[nodiscard]] RollKeys rollKeys(const scene::SceneSpec& spec, const model::RollingModel& model);

struct ExportedScene {
  std::vector<std::uint8_t> glb;  // the binary glTF
  RollKeys keys;
  geometry::Vec3 blochCentre = geometry::Vec3::Zero();  // scene coordinates
  double blochRadius = 1.0;
};

// Builds the whole file. Throws BadInput (at the scene's surface keys) when
// the surface cannot be meshed.
[[nodiscard]] ExportedScene exportScene(const ExportRequest& request);
// The GLB bytes alone.
[[nodiscard]] std::vector<std::uint8_t> exportGlb(const ExportRequest& request);

// Before any work: BadInput (at `-o …`) unless `output` ends in .glb or
// .gltf and can be written (checkOutputFile: its folder exists and takes a
// new file), with NAME.bin beside a .gltf.
void checkGltfOutput(const std::filesystem::path& output);

// Writes `output`: NAME.glb (one file), or NAME.gltf with its buffer in
// NAME.bin beside it; each through a temporary name and a rename, removed on
// failure or Ctrl-C. Throws BadInput (at `-o …`) for any other extension.
void writeGltf(const ExportRequest& request, const std::filesystem::path& output);

}  // namespace rollspin::gltf
