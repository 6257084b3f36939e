#include "export/gltf_builder.hpp"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "core/error.hpp"

namespace rollspin::gltf {

GltfBuilder::GltfBuilder() {
  model_.asset.version = "2.0";
  model_.asset.generator = "rollspin (tinygltf)";
  model_.buffers.emplace_back();
}

int GltfBuilder::addView(const void* data, std::size_t bytes, int target) {
  std::vector<unsigned char>& buffer = model_.buffers[0].data;
  buffer.resize((buffer.size() + 3) / 4 * 4, 0);  // every view starts 4-byte aligned
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), p, p + bytes);
  model_.bufferViews.push_back(view);
  return int(model_.bufferViews.size() - 1);
}

int GltfBuilder::addAccessor(int view, int componentType, std::size_t count, int type) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.byteOffset = 0;
  accessor.componentType = componentType;
  accessor.count = count;
  accessor.type = type;
  model_.accessors.push_back(accessor);
  return int(model_.accessors.size() - 1);
}

int GltfBuilder::addScalars(const std::vector<float>& values) {
  const int view = addView(values.data(), values.size() * sizeof(float), 0);
  const int a = addAccessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, values.size(), TINYGLTF_TYPE_SCALAR);
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  model_.accessors[std::size_t(a)].minValues = {double(*lo)};
  model_.accessors[std::size_t(a)].maxValues = {double(*hi)};
  return a;
}

int GltfBuilder::addVec3(const std::vector<glm::vec3>& values, int target) {
  const int view = addView(values.data(), values.size() * sizeof(glm::vec3), target);
  const int a = addAccessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, values.size(), TINYGLTF_TYPE_VEC3);
  // Bounds on every VEC3 (glTF requires them on POSITION; harmless elsewhere).
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::vec3& v : values) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  model_.accessors[std::size_t(a)].minValues = {lo.x, lo.y, lo.z};
  model_.accessors[std::size_t(a)].maxValues = {hi.x, hi.y, hi.z};
  return a;
}

int GltfBuilder::addVec4(const std::vector<glm::vec4>& values) {
  const int view = addView(values.data(), values.size() * sizeof(glm::vec4), 0);
  return addAccessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, values.size(), TINYGLTF_TYPE_VEC4);
}

int GltfBuilder::addVec2(const std::vector<glm::vec2>& values) {
  const int view = addView(values.data(), values.size() * sizeof(glm::vec2), TINYGLTF_TARGET_ARRAY_BUFFER);
  return addAccessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, values.size(), TINYGLTF_TYPE_VEC2);
}

int GltfBuilder::addIndices(const std::vector<std::uint32_t>& indices) {
  // 16-bit indices where every vertex fits (half the bytes; core glTF).
  if (std::all_of(indices.begin(), indices.end(), [](std::uint32_t i) { return i <= 0xFFFFu; })) {
    const std::vector<std::uint16_t> narrow(indices.begin(), indices.end());
    const int view =
        addView(narrow.data(), narrow.size() * sizeof(std::uint16_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    return addAccessor(view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, indices.size(), TINYGLTF_TYPE_SCALAR);
  }
  const int view =
      addView(indices.data(), indices.size() * sizeof(std::uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  return addAccessor(view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, indices.size(), TINYGLTF_TYPE_SCALAR);
}

int GltfBuilder::addTexture(const render::TextureImage& image, const std::string& name) {
  std::vector<unsigned char> png;
  const int ok = stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        out->insert(out->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
      },
      &png, image.width, image.height, 4, image.rgba.data(), image.width * 4);
  if (ok == 0) throw runtimeError({name}, "could not encode the {}x{} texture as PNG", image.width, image.height);
  tinygltf::Image gltfImage;
  gltfImage.name = name;
  gltfImage.mimeType = "image/png";
  gltfImage.bufferView = addView(png.data(), png.size(), 0);
  model_.images.push_back(gltfImage);
  tinygltf::Sampler sampler;  // repeating (a checker's cells), mipmapped
  sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
  model_.samplers.push_back(sampler);
  tinygltf::Texture texture;
  texture.name = name;
  texture.source = int(model_.images.size() - 1);
  texture.sampler = int(model_.samplers.size() - 1);
  model_.textures.push_back(texture);
  return int(model_.textures.size() - 1);
}

int GltfBuilder::addMaterial(const std::string& name, const render::Material& m, int texture) {
  tinygltf::Material material;
  material.name = name;
  const glm::vec3 colour = texture >= 0 ? glm::vec3(1.0f) : m.color;
  material.pbrMetallicRoughness.baseColorFactor = {colour.r, colour.g, colour.b, m.opacity};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  const double sharpness = std::min(1.0, 2.0 * double(m.specular));
  material.pbrMetallicRoughness.roughnessFactor =
      1.0 - sharpness * (1.0 - std::sqrt(2.0 / (double(m.shininess) + 2.0)));
  if (texture >= 0) material.pbrMetallicRoughness.baseColorTexture.index = texture;
  if (m.opacity < 1.0f) material.alphaMode = "BLEND";
  material.doubleSided = m.cull == render::Cull::None;
  // The renders' own Blinn–Phong terms, for a reader that shades as they do
  // (the web viewer: cheaper than PBR on a software renderer, and the same look).
  tinygltf::Value::Object phong;
  phong["specular"] = tinygltf::Value(double(m.specular));
  phong["shininess"] = tinygltf::Value(double(m.shininess));
  tinygltf::Value::Object extras;
  extras["rollspin"] = tinygltf::Value(phong);
  material.extras = tinygltf::Value(extras);
  model_.materials.push_back(material);
  return int(model_.materials.size() - 1);
}

int GltfBuilder::addMesh(const std::string& name, const render::MeshData& mesh, int material, bool withUv) {
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec2> uvs;
  for (const render::Vertex& v : mesh.vertices) {
    positions.push_back(v.position);
    // glTF asks for unit normals; a degenerate one (a chart's singular
    // point) points along +z rather than nowhere.
    const float length = glm::length(v.normal);
    normals.push_back(length > 1e-12f ? v.normal / length : glm::vec3(0.0f, 0.0f, 1.0f));
    uvs.push_back(v.uv);
  }
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = material;
  primitive.attributes["POSITION"] = addVec3(positions, TINYGLTF_TARGET_ARRAY_BUFFER);
  primitive.attributes["NORMAL"] = addVec3(normals, TINYGLTF_TARGET_ARRAY_BUFFER);
  if (withUv) primitive.attributes["TEXCOORD_0"] = addVec2(uvs);
  primitive.indices = addIndices(mesh.indices);
  tinygltf::Mesh gltfMesh;
  gltfMesh.name = name;
  gltfMesh.primitives.push_back(primitive);
  model_.meshes.push_back(gltfMesh);
  return int(model_.meshes.size() - 1);
}

int GltfBuilder::addNode(const std::string& name, int mesh) {
  tinygltf::Node node;
  node.name = name;
  node.mesh = mesh;
  model_.nodes.push_back(node);
  return int(model_.nodes.size() - 1);
}

std::vector<std::uint8_t> GltfBuilder::glb() {
  std::ostringstream stream;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model_, stream, false, true))
    throw runtimeError({"glTF"}, "tinygltf could not write the binary glTF");
  const std::string bytes = stream.str();
  return {bytes.begin(), bytes.end()};
}

}  // namespace rollspin::gltf
