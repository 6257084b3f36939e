// The glTF export read back through tinygltf's loader: the named nodes and
// their tree, +Y up, the ball's translation = its centre C(s) at the keys,
// the animated rotation at random times within 1e-6 rad of the solver's q
// (the file's own float32 keys, slerped as glTF does), canonical keys (qw ≥ 0)
// with spinor_sign × key = the solver's q with its sign, the extras; and the
// .glb/.gltf writers.
#include <gtest/gtest.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>

#include "core/error.hpp"
#include "export/gltf_export.hpp"
#include "motion/frame_poses.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/surface_stretches.hpp"
#include "support/test_files.hpp"

namespace rollspin::gltf {
namespace {

using geometry::Vec3;
using spin::Su2;

struct Loaded {
  scene::SceneSpec spec;
  model::RollingModel model;
  ExportedScene exported;
  tinygltf::Model gltf;
};

Loaded exportShipped(const std::string& name, bool metadata = true) {
  Loaded out;
  out.spec = model::loadScene(test::shippedScenePath(name), {});
  out.model = model::buildSceneModel(out.spec);
  ExportRequest request{&out.spec, &out.model, nullptr, "test-version", "the scene text", metadata};
  out.exported = exportScene(request);
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  const bool ok = loader.LoadBinaryFromMemory(&out.gltf, &error, &warning, out.exported.glb.data(),
                                              unsigned(out.exported.glb.size()));
  EXPECT_TRUE(ok) << error;
  EXPECT_EQ(warning, "");
  return out;
}

int nodeNamed(const tinygltf::Model& m, const std::string& name) {
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (m.nodes[i].name == name) return int(i);
  return -1;
}

// An accessor's float data (tightly packed, as the exporter writes it).
std::vector<float> floats(const tinygltf::Model& m, int accessor) {
  const tinygltf::Accessor& a = m.accessors[std::size_t(accessor)];
  const tinygltf::BufferView& v = m.bufferViews[std::size_t(a.bufferView)];
  EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  const std::size_t n = a.count * std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(a.type)));
  std::vector<float> out(n);
  std::memcpy(out.data(), m.buffers[std::size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset,
              n * sizeof(float));
  return out;
}

// The output accessor of the channel that animates node/path.
int channelOutput(const tinygltf::Model& m, int node, const std::string& path, int* input = nullptr,
                  const std::string& interpolation = "LINEAR") {
  for (const tinygltf::Animation& a : m.animations)
    for (const tinygltf::AnimationChannel& c : a.channels)
      if (c.target_node == node && c.target_path == path) {
        const tinygltf::AnimationSampler& s = a.samplers[std::size_t(c.sampler)];
        EXPECT_EQ(s.interpolation, interpolation);
        if (input) *input = s.input;
        return s.output;
      }
  ADD_FAILURE() << "no channel " << path;
  return -1;
}

Su2 keyAt(const std::vector<float>& xyzw, std::size_t k) {
  return {xyzw[4 * k + 3], xyzw[4 * k], xyzw[4 * k + 1], xyzw[4 * k + 2]};
}

// glTF's LINEAR rotation: slerp on the shorter arc (the spec's appendix).
Su2 slerp(Su2 a, Su2 b, double x) {
  a = {a.w / a.norm(), a.x / a.norm(), a.y / a.norm(), a.z / a.norm()};
  b = {b.w / b.norm(), b.x / b.norm(), b.y / b.norm(), b.z / b.norm()};
  double d = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  if (d < 0) b = -b, d = -d;
  const double angle = std::acos(std::min(1.0, d));
  if (angle < 1e-12) return a;
  const double wa = std::sin((1 - x) * angle) / std::sin(angle), wb = std::sin(x * angle) / std::sin(angle);
  return {wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z};
}

// The solver's q at arc lengths s (sorted), one march, as a render solves.
std::vector<Su2> solverAt(const Loaded& l, const std::vector<double>& s) {
  std::vector<Su2> q(s.size());
  motion::marchScene(l.spec, l.model, s, [&](std::size_t i, double, const Su2& u) { q[i] = u; });
  return q;
}

TEST(GltfExport, NamedNodesInTheirTreeWithYUp) {
  const Loaded l = exportShipped("lollipop");
  const tinygltf::Model& m = l.gltf;
  ASSERT_EQ(m.scenes.size(), 1u);
  const int root = nodeNamed(m, "rollspin");
  ASSERT_EQ(m.scenes[0].nodes, std::vector<int>{root});
  for (const char* name : {"surface", "path", "ball", "bloch"}) {
    const auto& children = m.nodes[std::size_t(root)].children;
    EXPECT_NE(std::find(children.begin(), children.end(), nodeNamed(m, name)), children.end()) << name;
    EXPECT_GE(m.nodes[std::size_t(nodeNamed(m, name))].mesh, 0) << name;
  }
  EXPECT_EQ(m.nodes[std::size_t(nodeNamed(m, "bloch"))].children,
            (std::vector<int>{nodeNamed(m, "spin"), nodeNamed(m, "field")}));
  // The root's rotation takes the scene's +z (up) to glTF's +y.
  const auto& r = m.nodes[std::size_t(root)].rotation;
  ASSERT_EQ(r.size(), 4u);
  const Vec3 up = Su2{r[3], r[0], r[1], r[2]}.rotate(Vec3::UnitZ());
  EXPECT_NEAR((up - Vec3::UnitY()).norm(), 0.0, 1e-12);
  ASSERT_EQ(m.animations.size(), 1u);
  EXPECT_EQ(m.animations[0].name, "roll");
  EXPECT_EQ(m.images.size(), 2u);  // the checker and the tennis ball, as PNG
  for (const tinygltf::Image& image : m.images) EXPECT_EQ(image.mimeType, "image/png");
}

// Every key's translation is C(s) of its time, and its quaternion times its
// sign is the solver's q at that s, sign and all.
void expectKeysAreTheSolvers(const Loaded& l) {
  const tinygltf::Model& m = l.gltf;
  const int ball = nodeNamed(m, "ball");
  int input = -1;
  const std::vector<float> centres = floats(m, channelOutput(m, ball, "translation", &input));
  const std::vector<float> rotations = floats(m, channelOutput(m, ball, "rotation"));
  const std::vector<float> seconds = floats(m, input);
  const tinygltf::Value& extras = m.nodes[std::size_t(ball)].extras.Get("rollspin");
  const std::vector<float> arc = floats(m, extras.Get("arc_length").GetNumberAsInt());
  const std::vector<float> sign = floats(m, extras.Get("spinor_sign").GetNumberAsInt());
  ASSERT_EQ(arc.size(), seconds.size());
  ASSERT_EQ(sign.size(), seconds.size());
  const motion::FrameClock clock = motion::clipClock(l.spec, l.model);
  std::vector<double> s;
  for (const float t : seconds) s.push_back(clock.arcLengthAt(double(t) * clock.fps().value()));
  const std::vector<Su2> q = solverAt(l, s);
  const double R = l.model.ballRadius;
  for (std::size_t k = 0; k < seconds.size(); ++k) {
    EXPECT_NEAR(arc[k], s[k], 1e-6 * std::max(1.0, s[k]));
    const Vec3 c = l.model.path->at(s[k]).centre(R);
    EXPECT_NEAR((Vec3(centres[3 * k], centres[3 * k + 1], centres[3 * k + 2]) - c).norm(), 0.0,
                1e-6 * (1.0 + c.norm()));
    const Su2 key = keyAt(rotations, k);
    const Su2 signedKey{sign[k] * key.w, sign[k] * key.x, sign[k] * key.y, sign[k] * key.z};
    EXPECT_NEAR(std::abs(signedKey.w - q[k].w) + (signedKey.vec() - q[k].vec()).norm(), 0.0, 1e-6) << "key " << k;
  }
}

// glTF's slerp between the file's keys, at random times, against the solver.
void expectRotationWithinTolerance(const Loaded& l, int samples) {
  const tinygltf::Model& m = l.gltf;
  const int ball = nodeNamed(m, "ball");
  int input = -1;
  const std::vector<float> rotations = floats(m, channelOutput(m, ball, "rotation", &input));
  const std::vector<float> seconds = floats(m, input);
  const motion::FrameClock clock = motion::clipClock(l.spec, l.model);
  std::mt19937 random(20261128);
  std::uniform_real_distribution<double> uniform(seconds.front(), seconds.back());
  std::vector<double> times(static_cast<std::size_t>(samples));
  std::vector<double> s;
  for (double& t : times) t = uniform(random);
  std::sort(times.begin(), times.end());
  for (const double t : times) s.push_back(clock.arcLengthAt(t * clock.fps().value()));
  const std::vector<Su2> q = solverAt(l, s);
  double worst = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::size_t k =
        std::size_t(std::upper_bound(seconds.begin(), seconds.end(), float(times[i])) - seconds.begin());
    const std::size_t a = std::min(k, seconds.size() - 1) - 1;
    const double x = (times[i] - seconds[a]) / (double(seconds[a + 1]) - double(seconds[a]));
    worst = std::max(worst, spin::rotationDistance(
                                slerp(keyAt(rotations, a), keyAt(rotations, a + 1), std::clamp(x, 0.0, 1.0)), q[i]));
  }
  EXPECT_LE(worst, 1e-6);
  // The spin arrow turns with the ball: the same keys.
  EXPECT_EQ(floats(m, channelOutput(m, nodeNamed(m, "spin"), "rotation")), rotations);
}

TEST(GltfExport, KeysAreTheSolversOnACircle) {
  const Loaded l = exportShipped("lollipop");
  expectKeysAreTheSolvers(l);
  expectRotationWithinTolerance(l, 400);
}

// The lollipop's spinor turns by more than 2π: its qw changes sign. The keys
// are canonical (qw ≥ 0, as readers normalise them) and spinor_sign carries
// the sheet, both +1 and −1 (expectKeysAreTheSolvers: sign × key = q).
TEST(GltfExport, KeysAreCanonicalAndTheSignCarriesTheSheet) {
  const Loaded l = exportShipped("lollipop");
  const tinygltf::Model& m = l.gltf;
  const int ball = nodeNamed(m, "ball");
  const std::vector<float> rotations = floats(m, channelOutput(m, ball, "rotation"));
  const tinygltf::Value& extras = m.nodes[std::size_t(ball)].extras.Get("rollspin");
  const std::vector<float> sign = floats(m, extras.Get("spinor_sign").GetNumberAsInt());
  for (std::size_t k = 0; k < sign.size(); ++k) {
    EXPECT_GE(keyAt(rotations, k).w, 0.0) << "key " << k;
    EXPECT_EQ(sign[k], l.exported.keys.rotation[k].w < 0.0 ? -1.0f : 1.0f) << "key " << k;
  }
  EXPECT_GT(std::count(sign.begin(), sign.end(), -1.0f), 0);
  EXPECT_GT(std::count(sign.begin(), sign.end(), 1.0f), 0);
  EXPECT_EQ(std::count(sign.begin(), sign.end(), -1.0f) + std::count(sign.begin(), sign.end(), 1.0f),
            long(sign.size()));
}

TEST(GltfExport, KeysFollowAStoryboardWithHoldsAndCorners) {
  const Loaded l = exportShipped("storyboard");
  expectKeysAreTheSolvers(l);
  expectRotationWithinTolerance(l, 400);
  // A key at every corner and joint of the path.
  std::vector<double> corners = l.model.path->breakpoints();
  for (const model::SegmentSpan& span : l.model.segments) corners.insert(corners.end(), {span.start, span.end});
  ASSERT_FALSE(corners.empty());
  for (const double c : corners) {
    double nearest = 1e300;
    for (const double s : l.exported.keys.arcLength) nearest = std::min(nearest, std::abs(s - c));
    EXPECT_LE(nearest, 1e-5) << "corner at s = " << c;
  }
}

// A storyboard on two surfaces (the torus, then the floor): one surface and
// one path node each, the second at scale 0 at rest, and a STEP scale
// channel per node that swaps them at the clip's cut, the first frame of the
// floor's first segment (as the renders cut).
TEST(GltfExport, EachSurfaceIsShownDuringItsOwnSegments) {
  const Loaded l = exportShipped("torus-to-floor");
  const tinygltf::Model& m = l.gltf;
  const std::vector<motion::SurfaceStretch> stretches = motion::surfaceStretches(l.spec, l.model);
  ASSERT_EQ(stretches.size(), 2u);
  const motion::FrameClock clock = motion::clipClock(l.spec, l.model);
  const double fps = clock.fps().value();
  long long cut = 0;
  while (clock.place(cut).segment < stretches[1].firstSegment) ++cut;
  ASSERT_GT(cut, 0);
  // The cut: just after the whole frame before the floor's first frame.
  const double cutSeconds = secondsJustAfter(double(cut - 1), fps);
  EXPECT_GT(cutSeconds * fps, double(cut - 1));
  EXPECT_LT(cutSeconds * fps, double(cut - 1) + 1e-3);
  for (const char* base : {"surface", "path"}) {
    for (const int k : {0, 1}) {
      const std::string name = k == 0 ? std::string(base) : std::string(base) + ".1";
      const int node = nodeNamed(m, name);
      ASSERT_GE(node, 0) << name;
      EXPECT_GE(m.nodes[std::size_t(node)].mesh, 0) << name;
      EXPECT_EQ(m.nodes[std::size_t(node)].scale, k == 0 ? std::vector<double>{} : std::vector<double>(3, 0.0)) << name;
      int input = -1;
      const int output = channelOutput(m, node, "scale", &input, "STEP");
      const std::vector<float> times = floats(m, input), scales = floats(m, output);
      ASSERT_EQ(times.size(), 2u) << name;
      EXPECT_EQ(times[0], 0.0f);
      EXPECT_EQ(times[1], float(cutSeconds)) << name;
      ASSERT_EQ(scales.size(), 6u) << name;
      for (int key = 0; key < 2; ++key)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(scales[std::size_t(3 * key + c)], key == k ? 1.0f : 0.0f) << name;
    }
  }
  // The cut shows the floor's stretch and the frame before it the torus's.
  EXPECT_GE(clock.arcLength(cut), stretches[1].start);
  EXPECT_LT(clock.place(cut - 1).segment, stretches[1].firstSegment);
  // Until the cut the ball is keyed on the torus, the hold at the join too
  // (a hair before it), not at the floor's start where the path jumps; from
  // the cut on, on the floor.
  const RollKeys& keys = l.exported.keys;
  const Vec3 floorStart = l.model.path->at(stretches[1].start).centre(l.model.ballRadius);
  std::size_t held = 0;
  for (std::size_t k = 0; k < keys.seconds.size(); ++k)
    if (double(keys.seconds[k]) < cutSeconds) {
      EXPECT_LT(keys.arcLength[k], stretches[1].start) << "key " << k << " at " << keys.seconds[k] << " s";
      EXPECT_GT((keys.centre[k] - floorStart).norm(), l.model.ballRadius) << "key " << k;
      held += keys.arcLength[k] > stretches[1].start - 1e-6 ? 1 : 0;
    }
  EXPECT_GE(held, 2u) << "the hold's two ends";
  const auto first = std::find(keys.seconds.begin(), keys.seconds.end(), float(cutSeconds));
  ASSERT_NE(first, keys.seconds.end()) << "a key at the cut";
  EXPECT_GE(keys.arcLength[std::size_t(first - keys.seconds.begin())], stretches[1].start);
  // The floor lies in z = 0, the torus round it: different meshes.
  EXPECT_NE(m.nodes[std::size_t(nodeNamed(m, "surface"))].mesh, m.nodes[std::size_t(nodeNamed(m, "surface.1"))].mesh);
}

// The closest point to p on the triangle abc (Ericson, Real-Time Collision
// Detection, 5.1.5): its distance.
double distanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
  const double denominator = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denominator) + ac * (vc * denominator))).norm();
}

// The exported surface's triangles, in the scene's frame (the surface node
// carries no transform of its own; the root's turns z-up to y-up).
std::vector<std::array<Vec3, 3>> surfaceTriangles(const tinygltf::Model& m) {
  const tinygltf::Node& node = m.nodes[std::size_t(nodeNamed(m, "surface"))];
  EXPECT_TRUE(node.rotation.empty() && node.translation.empty() && node.matrix.empty());
  const tinygltf::Primitive& primitive = m.meshes[std::size_t(node.mesh)].primitives.at(0);
  const std::vector<float> xyz = floats(m, primitive.attributes.at("POSITION"));
  const tinygltf::Accessor& a = m.accessors[std::size_t(primitive.indices)];
  const tinygltf::BufferView& v = m.bufferViews[std::size_t(a.bufferView)];
  const unsigned char* bytes = m.buffers[std::size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset;
  const auto index = [&](std::size_t k) -> std::size_t {
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
      std::uint16_t i;
      std::memcpy(&i, bytes + 2 * k, 2);
      return i;
    }
    std::uint32_t i;
    std::memcpy(&i, bytes + 4 * k, 4);
    return i;
  };
  const auto vertex = [&](std::size_t i) { return Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); };
  std::vector<std::array<Vec3, 3>> out;
  for (std::size_t k = 0; k + 2 < a.count; k += 3)
    out.push_back({vertex(index(k)), vertex(index(k + 1)), vertex(index(k + 2))});
  return out;
}

// Where the ball rolls, the exported surface keeps within 1 % of R of the
// true one (the thinning's fine tolerance, twice: a row's and a column's
// sag), so the ball neither sinks nor floats there; away from the path the
// grid is thinner than the renders' (berry: a whole sphere, of which the
// path touches a band).
TEST(GltfExport, TheBallTouchesTheExportedSurfaceWhereItRolls) {
  // (Not sphere-inside: its view cuts the sphere open where the path runs,
  // to show the ball inside. height-bumps twists: thinned along rows and
  // columns alone its quads cut the bumps by 6 % of R.)
  for (const std::string name :
       {"berry", "torus", "sphere-outside", "saddle-geodesic", "paraboloid-story", "height-bumps"}) {
    const Loaded l = exportShipped(name);
    const std::vector<std::array<Vec3, 3>> triangles = surfaceTriangles(l.gltf);
    const geometry::ContactPath& path = *l.model.path;
    const double R = l.model.ballRadius;
    double worst = 0.0;
    for (int k = 0; k <= 120; ++k) {
      const Vec3 p = path.point(path.length() * k / 120.0);
      double nearest = 1e300;
      for (const auto& t : triangles) nearest = std::min(nearest, distanceToTriangle(p, t[0], t[1], t[2]));
      worst = std::max(worst, nearest);
    }
    EXPECT_LE(worst, 0.01 * R + 1e-5 * (1.0 + path.point(0.0).norm())) << name;
    if (name == "berry") {
      EXPECT_LT(triangles.size(), 16384u) << "the sphere away from the path";
    }
  }
}

TEST(GltfExport, ExtrasCarryVersionAndSceneUnlessNoMetadata) {
  const tinygltf::Model with = exportShipped("penny").gltf;
  const tinygltf::Value& extras = with.nodes[std::size_t(nodeNamed(with, "ball"))].extras.Get("rollspin");
  EXPECT_EQ(extras.Get("version").Get<std::string>(), "test-version");
  EXPECT_EQ(extras.Get("scene").Get<std::string>(), "the scene text");
  const tinygltf::Model without = exportShipped("penny", false).gltf;
  EXPECT_FALSE(without.nodes[std::size_t(nodeNamed(without, "ball"))].extras.Get("rollspin").Has("scene"));
}

TEST(GltfExport, WritesGlbOrGltfWithItsBinAndRefusesOtherNames) {
  const std::filesystem::path dir = test::freshTempDir("gltf_export_writers");
  scene::SceneSpec spec = model::loadScene(test::shippedScenePath("penny"), {});
  const model::RollingModel model = model::buildSceneModel(spec);
  const ExportRequest request{&spec, &model, nullptr, "v", "", false};
  writeGltf(request, dir / "a.glb");
  writeGltf(request, dir / "b.gltf");
  tinygltf::TinyGLTF loader;
  tinygltf::Model glb, gltf;
  std::string error, warning;
  EXPECT_TRUE(loader.LoadBinaryFromFile(&glb, &error, &warning, (dir / "a.glb").string())) << error;
  EXPECT_TRUE(loader.LoadASCIIFromFile(&gltf, &error, &warning, (dir / "b.gltf").string())) << error;
  EXPECT_EQ(gltf.buffers.at(0).uri, "b.bin");
  EXPECT_EQ(gltf.buffers.at(0).data, glb.buffers.at(0).data);
  EXPECT_THROW(writeGltf(request, dir / "c.obj"), Error);
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"a.glb", "b.bin", "b.gltf"})) << "no temporary left";
}

}  // namespace
}  // namespace rollspin::gltf
