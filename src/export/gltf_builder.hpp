// GltfBuilder — fills a tinygltf::Model from the project's plain data: one
// buffer (4-byte aligned views), accessors with the bounds glTF asks for,
// meshes from render::MeshData, PBR materials from render::Material and PNG
// textures from render::TextureImage. Colours stay linear RGB
// (baseColorFactor); texture texels are sRGB, as glTF's base colour is.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "export/gltf_export.hpp"
#include "render/draw_list.hpp"

namespace rollspin::gltf {

class GltfBuilder {
 public:
  GltfBuilder();

  // A buffer view of `bytes` (target 0: none, e.g. animation data or images).
  int addView(const void* data, std::size_t bytes, int target);
  [[nodiscard]] int addScalars(const std::vector<float>& values);  // with min and max
  [[nodiscard]] int addVec3(const std::vector<glm::vec3>& values, int target);
  [[nodiscard]] int addVec4(const std::vector<glm::vec4>& values);
  [[nodiscard]] int addVec2(const std::vector<glm::vec2>& values);
  [[nodiscard]] int addIndices(const std::vector<std::uint32_t>& indices);

  // A PNG of the image in the buffer, its texture with a repeating sampler.
  [[nodiscard]] int addTexture(const render::TextureImage& image, const std::string& name);
  // PBR metallic-roughness from the renderer's Blinn–Phong material: base
  // colour = colour (alpha = opacity; BLEND below 1), metallic 0, roughness
  // 1 − specular′ (1 − √(2 / (shininess + 2))) with specular′ = min(1, 2 specular)
  // (a matte material is rough, a shiny one as sharp as its Phong lobe);
  // extras.rollspin = {specular, shininess}: the renders' Blinn–Phong terms.
  [[nodiscard]] int addMaterial(const std::string& name, const render::Material& material, int texture = -1);
  // Triangles; TEXCOORD_0 only with `withUv` (a textured material).
  [[nodiscard]] int addMesh(const std::string& name, const render::MeshData& mesh, int material, bool withUv);
  [[nodiscard]] int addNode(const std::string& name, int mesh = -1);

  [[nodiscard]] tinygltf::Model& model() { return model_; }
  // The model as GLB bytes.
  [[nodiscard]] std::vector<std::uint8_t> glb();

 private:
  int addAccessor(int view, int componentType, std::size_t count, int type);
  tinygltf::Model model_;
};

// The whole export of a scene, not yet serialised (gltf_export.cpp).
[[nodiscard]] GltfBuilder buildModel(const ExportRequest& request);

}  // namespace rollspin::gltf
