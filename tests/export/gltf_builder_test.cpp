// export/gltf_builder: a tinygltf::Model filled from plain data, checked
// piece by piece against what the header promises (no scene, no solver):
// buffer views 4-byte aligned, accessors with their bounds, 16-bit indices
// where every vertex fits, unit normals, UVs only when asked, the
// roughness of the Blinn–Phong lobe in closed form, BLEND below full
// opacity, and a GLB that tinygltf reads back with its texture texel for
// texel.
#include "export/gltf_builder.hpp"

#include <gtest/gtest.h>

#include <tiny_gltf.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace rollspin::gltf::gltf_builder_tests {
namespace {

// The bytes an accessor's view holds, as T (tightly packed, as the builder writes them).
template <typename T>
std::vector<T> viewContents(const tinygltf::Model& m, int accessor) {
  const tinygltf::Accessor& a = m.accessors.at(std::size_t(accessor));
  const tinygltf::BufferView& v = m.bufferViews.at(std::size_t(a.bufferView));
  const std::vector<unsigned char>& data = m.buffers.at(std::size_t(v.buffer)).data;
  EXPECT_LE(v.byteOffset + v.byteLength, data.size());
  std::vector<T> out(v.byteLength / sizeof(T));
  std::memcpy(out.data(), data.data() + v.byteOffset, out.size() * sizeof(T));
  return out;
}

TEST(GltfBuilder, StartsAGltfTwoModelWithOneBuffer) {
  GltfBuilder b;
  EXPECT_EQ(b.model().asset.version, "2.0");
  EXPECT_EQ(b.model().buffers.size(), 1u);
}

TEST(GltfBuilder, EveryViewStartsFourByteAligned) {
  GltfBuilder b;
  const unsigned char three[3] = {1, 2, 3}, five[5] = {4, 5, 6, 7, 8}, two[2] = {9, 10};
  const int v0 = b.addView(three, 3, 0), v1 = b.addView(five, 5, TINYGLTF_TARGET_ARRAY_BUFFER),
            v2 = b.addView(two, 2, 0);
  const tinygltf::Model& m = b.model();
  ASSERT_EQ(m.bufferViews.size(), 3u);
  EXPECT_EQ(m.bufferViews[std::size_t(v0)].byteOffset, 0u);
  EXPECT_EQ(m.bufferViews[std::size_t(v1)].byteOffset, 4u);   // 3 rounded up
  EXPECT_EQ(m.bufferViews[std::size_t(v2)].byteOffset, 12u);  // 4 + 5 rounded up
  EXPECT_EQ(m.bufferViews[std::size_t(v1)].byteLength, 5u);
  EXPECT_EQ(m.bufferViews[std::size_t(v1)].target, TINYGLTF_TARGET_ARRAY_BUFFER);
  const std::vector<unsigned char> expected{1, 2, 3, 0, 4, 5, 6, 7, 8, 0, 0, 0, 9, 10};
  EXPECT_EQ(m.buffers[0].data, expected) << "padding is zeros, the data as given";
}

TEST(GltfBuilder, AccessorsCarryTheirValuesAndPerComponentBounds) {
  GltfBuilder b;
  const std::vector<float> scalars{3.0f, -1.5f, 2.0f};
  const int s = b.addScalars(scalars);
  // Each bound from a different point.
  const std::vector<glm::vec3> points{{1.0f, -2.0f, 5.0f}, {-4.0f, 7.0f, 0.5f}, {0.0f, 0.0f, -3.0f}};
  const int p = b.addVec3(points, TINYGLTF_TARGET_ARRAY_BUFFER);
  const int q = b.addVec4({{1.0f, 2.0f, 3.0f, 4.0f}});
  const int r = b.addVec2({{0.25f, 0.75f}, {1.0f, 0.0f}});
  const tinygltf::Model& m = b.model();

  const tinygltf::Accessor& sa = m.accessors[std::size_t(s)];
  EXPECT_EQ(sa.type, TINYGLTF_TYPE_SCALAR);
  EXPECT_EQ(sa.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(sa.count, 3u);
  EXPECT_EQ(sa.minValues, std::vector<double>{-1.5});
  EXPECT_EQ(sa.maxValues, std::vector<double>{3.0});
  EXPECT_EQ(viewContents<float>(m, s), scalars);

  const tinygltf::Accessor& pa = m.accessors[std::size_t(p)];
  EXPECT_EQ(pa.type, TINYGLTF_TYPE_VEC3);
  EXPECT_EQ(pa.count, 3u);
  EXPECT_EQ(pa.minValues, (std::vector<double>{-4.0, -2.0, -3.0}));
  EXPECT_EQ(pa.maxValues, (std::vector<double>{1.0, 7.0, 5.0}));
  EXPECT_EQ(viewContents<float>(m, p), (std::vector<float>{1, -2, 5, -4, 7, 0.5f, 0, 0, -3}));

  EXPECT_EQ(m.accessors[std::size_t(q)].type, TINYGLTF_TYPE_VEC4);
  EXPECT_EQ(m.accessors[std::size_t(q)].count, 1u);
  EXPECT_EQ(viewContents<float>(m, q), (std::vector<float>{1, 2, 3, 4}));
  EXPECT_EQ(m.accessors[std::size_t(r)].type, TINYGLTF_TYPE_VEC2);
  EXPECT_EQ(m.accessors[std::size_t(r)].count, 2u);
  EXPECT_EQ(viewContents<float>(m, r), (std::vector<float>{0.25f, 0.75f, 1.0f, 0.0f}));
}

TEST(GltfBuilder, IndicesAreSixteenBitWhereEveryVertexFits) {
  GltfBuilder b;
  const int narrow = b.addIndices({0, 1, 65535});
  const int wide = b.addIndices({0, 1, 65536});
  const tinygltf::Model& m = b.model();
  const tinygltf::Accessor& n = m.accessors[std::size_t(narrow)];
  EXPECT_EQ(n.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  EXPECT_EQ(n.count, 3u);
  EXPECT_EQ(m.bufferViews[std::size_t(n.bufferView)].byteLength, 6u) << "half the bytes";
  EXPECT_EQ(m.bufferViews[std::size_t(n.bufferView)].target, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  EXPECT_EQ(viewContents<std::uint16_t>(m, narrow), (std::vector<std::uint16_t>{0, 1, 65535}));
  const tinygltf::Accessor& w = m.accessors[std::size_t(wide)];
  EXPECT_EQ(w.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  EXPECT_EQ(w.count, 3u);
  EXPECT_EQ(viewContents<std::uint32_t>(m, wide), (std::vector<std::uint32_t>{0, 1, 65536}));
}

// Roughness 1 − s′(1 − √(2 / (shininess + 2))), s′ = min(1, 2 specular).
TEST(GltfBuilder, AMaterialsRoughnessFollowsItsPhongLobe) {
  GltfBuilder b;
  render::Material matte;
  matte.specular = 0.0f;
  render::Material shiny;  // s′ = 1, √(2/50) = 0.2
  shiny.specular = 0.5f;
  shiny.shininess = 48.0f;
  render::Material half;  // s′ = 0.5: 1 − 0.5 × 0.8
  half.specular = 0.25f;
  half.shininess = 48.0f;
  render::Material clamped;  // s′ = min(1, 1.6) = 1, √(2/200)= 0.1
  clamped.specular = 0.8f;
  clamped.shininess = 198.0f;
  const tinygltf::Model& m = b.model();
  const auto roughness = [&](const render::Material& material) {
    return m.materials[std::size_t(b.addMaterial("x", material))].pbrMetallicRoughness.roughnessFactor;
  };
  EXPECT_NEAR(roughness(matte), 1.0, 1e-12);
  EXPECT_NEAR(roughness(shiny), 0.2, 1e-7);
  EXPECT_NEAR(roughness(half), 0.6, 1e-7);
  EXPECT_NEAR(roughness(clamped), 0.1, 1e-7);
}

TEST(GltfBuilder, AMaterialKeepsItsColourOpacityAndPhongTerms) {
  GltfBuilder b;
  render::Material glass;
  glass.color = {0.1f, 0.2f, 0.3f};
  glass.opacity = 0.4f;
  glass.specular = 0.3f;
  glass.shininess = 20.0f;
  glass.cull = render::Cull::None;
  render::Material solid;
  solid.color = {1.0f, 0.5f, 0.0f};
  const int g = b.addMaterial("glass", glass), s = b.addMaterial("solid", solid);
  const tinygltf::Material& gm = b.model().materials[std::size_t(g)];
  const tinygltf::Material& sm = b.model().materials[std::size_t(s)];
  EXPECT_EQ(gm.name, "glass");
  EXPECT_EQ(gm.pbrMetallicRoughness.baseColorFactor, (std::vector<double>{0.1f, 0.2f, 0.3f, 0.4f}));
  EXPECT_EQ(gm.pbrMetallicRoughness.metallicFactor, 0.0);
  EXPECT_EQ(gm.alphaMode, "BLEND");
  EXPECT_TRUE(gm.doubleSided) << "no culling: both sides";
  EXPECT_EQ(gm.pbrMetallicRoughness.baseColorTexture.index, -1);
  ASSERT_TRUE(gm.extras.Has("rollspin"));
  EXPECT_EQ(gm.extras.Get("rollspin").Get("specular").GetNumberAsDouble(), double(0.3f));
  EXPECT_EQ(gm.extras.Get("rollspin").Get("shininess").GetNumberAsDouble(), 20.0);
  EXPECT_EQ(sm.alphaMode, "OPAQUE");
  EXPECT_FALSE(sm.doubleSided);
  EXPECT_EQ(sm.pbrMetallicRoughness.baseColorFactor, (std::vector<double>{1.0, 0.5, 0.0, 1.0}));
  // With a texture the texels give the colour: the factor is white.
  render::TextureImage image{1, 1, {10, 20, 30, 255}};
  const int t = b.addTexture(image, "ball");
  const tinygltf::Material& tm = b.model().materials[std::size_t(b.addMaterial("ball", solid, t))];
  EXPECT_EQ(tm.pbrMetallicRoughness.baseColorFactor, (std::vector<double>{1.0, 1.0, 1.0, 1.0}));
  EXPECT_EQ(tm.pbrMetallicRoughness.baseColorTexture.index, t);
}

TEST(GltfBuilder, AMeshHasUnitNormalsAndUvsOnlyWhenAsked) {
  GltfBuilder b;
  render::MeshData mesh;
  mesh.vertices = {{{0, 0, 0}, {0, 0, 2}, {0, 0}}, {{1, 0, 0}, {3, 4, 0}, {1, 0}}, {{0, 1, 0}, {0, 0, 0}, {0, 1}}};
  mesh.indices = {0, 1, 2};
  const int material = b.addMaterial("m", render::Material{});
  const int plain = b.addMesh("plain", mesh, material, false);
  const int textured = b.addMesh("textured", mesh, material, true);
  const tinygltf::Model& m = b.model();
  const tinygltf::Primitive& p = m.meshes[std::size_t(plain)].primitives.at(0);
  EXPECT_EQ(m.meshes[std::size_t(plain)].name, "plain");
  EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
  EXPECT_EQ(p.material, material);
  EXPECT_FALSE(p.attributes.contains("TEXCOORD_0"));
  // Unit normals; the degenerate one (a chart's singular point) along +z.
  EXPECT_EQ(viewContents<float>(m, p.attributes.at("NORMAL")), (std::vector<float>{0, 0, 1, 0.6f, 0.8f, 0, 0, 0, 1}));
  EXPECT_EQ(viewContents<float>(m, p.attributes.at("POSITION")), (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(m.accessors[std::size_t(p.attributes.at("POSITION"))].maxValues, (std::vector<double>{1, 1, 0}));
  EXPECT_EQ(viewContents<std::uint16_t>(m, p.indices), (std::vector<std::uint16_t>{0, 1, 2}));
  const tinygltf::Primitive& t = m.meshes[std::size_t(textured)].primitives.at(0);
  ASSERT_TRUE(t.attributes.contains("TEXCOORD_0"));
  EXPECT_EQ(viewContents<float>(m, t.attributes.at("TEXCOORD_0")), (std::vector<float>{0, 0, 1, 0, 0, 1}));
  const int node = b.addNode("surface", textured);
  EXPECT_EQ(m.nodes[std::size_t(node)].mesh, textured);
  EXPECT_EQ(m.nodes[std::size_t(b.addNode("group"))].mesh, -1);
}

TEST(GltfBuilder, AGlbReadsBackWithItsMeshAndTextureTexelForTexel) {
  GltfBuilder b;
  // 3 × 2 texels, top row first, each different, one half transparent.
  render::TextureImage image{3, 2, {}};
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 4; ++c) image.rgba.push_back(std::uint8_t(c == 3 ? (i == 4 ? 128 : 255) : 40 * i + 10 * c));
  const int texture = b.addTexture(image, "checker");
  render::MeshData mesh;
  mesh.vertices = {{{0, 0, 0}, {0, 0, 1}, {0, 0}}, {{1, 0, 0}, {0, 0, 1}, {1, 0}}, {{0, 1, 0}, {0, 0, 1}, {0, 1}}};
  mesh.indices = {0, 1, 2};
  const int node = b.addNode("plate", b.addMesh("plate", mesh, b.addMaterial("plate", {}, texture), true));
  tinygltf::Scene scene;
  scene.nodes = {node};
  b.model().scenes.push_back(scene);
  b.model().defaultScene = 0;
  const std::vector<std::uint8_t> glb = b.glb();
  ASSERT_GE(glb.size(), 12u);
  EXPECT_EQ(std::string(glb.begin(), glb.begin() + 4), "glTF");

  tinygltf::Model back;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&back, &error, &warning, glb.data(), unsigned(glb.size()))) << error;
  EXPECT_EQ(warning, "");
  ASSERT_EQ(back.images.size(), 1u);
  const tinygltf::Image& decoded = back.images[0];
  EXPECT_EQ(decoded.mimeType, "image/png");
  EXPECT_EQ(decoded.name, "checker");
  EXPECT_EQ(decoded.width, 3);
  EXPECT_EQ(decoded.height, 2);
  EXPECT_EQ(decoded.component, 4);
  EXPECT_EQ(decoded.image, image.rgba) << "PNG is lossless";
  ASSERT_EQ(back.samplers.size(), 1u);
  EXPECT_EQ(back.samplers[0].wrapS, TINYGLTF_TEXTURE_WRAP_REPEAT);
  EXPECT_EQ(back.samplers[0].wrapT, TINYGLTF_TEXTURE_WRAP_REPEAT);
  EXPECT_EQ(back.samplers[0].minFilter, TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR);
  EXPECT_EQ(back.textures.at(0).source, 0);
  ASSERT_EQ(back.nodes.size(), 1u);
  EXPECT_EQ(back.nodes[0].name, "plate");
  const tinygltf::Primitive& p = back.meshes.at(std::size_t(back.nodes[0].mesh)).primitives.at(0);
  EXPECT_EQ(viewContents<float>(back, p.attributes.at("POSITION")), (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(back.materials.at(std::size_t(p.material)).pbrMetallicRoughness.baseColorTexture.index, 0);
}

}  // namespace
}  // namespace rollspin::gltf::gltf_builder_tests
