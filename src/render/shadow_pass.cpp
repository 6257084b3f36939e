#include "render/shadow_pass.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <optional>

namespace rollspin::render {

const ShadowMap& ShadowMaps::at(std::size_t n) {
  while (maps_.size() <= n) {
    ShadowMap m;
    // Depth texture with hardware comparison: sampler2DShadow does the test.
    m.texture = GlObject::generate(GlKind::Texture);
    glBindTexture(GL_TEXTURE_2D, m.texture);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT24, kShadowMapSize, kShadowMapSize);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    m.fbo = makeFramebuffer({{GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m.texture}}, kShadowMapSize, kShadowMapSize,
                            "shadow map");
    maps_.push_back(std::move(m));
  }
  return maps_[n];
}

namespace {

// A sphere (MeshItem::sphere) into the bound shadow map `map`, ray-cast
// (see shadow_sphere.frag) in the bands of its square that its circle
// reaches, one scissored triangle of impostor.vert each (see
// drawImpostorParts). It takes no shadow (shadowPass sees to it), so the
// polygon offset that triangles get (against a receiver's shadow on its
// own faces) is not needed where gl_FragDepth replaces it.
void drawShadowSphere(const Drawable& d, const View& map, const glm::mat4& lightClipFromWorld, Program& shadowSphere,
                      const VertexStreams& streams) {
  const glm::vec3 centre(d.worldFromModel[3]);
  const float radius = glm::length(glm::vec3(d.worldFromModel[0]));
  const std::optional<PixelRect> box = sphereBounds(map, centre, radius, kImpostorMarginPx);
  if (!box || box->empty()) return;
  // The light's clip space is a box, square across the light: the
  // sphere's radius across it and along it, in its coordinates (the rows
  // of the linear part hold each axis's scale).
  const glm::vec3 c(lightClipFromWorld * glm::vec4(centre, 1.0f));
  auto scaleOfRow = [&](int row) {
    return glm::length(glm::vec3(lightClipFromWorld[0][row], lightClipFromWorld[1][row], lightClipFromWorld[2][row]));
  };
  shadowSphere.use();
  shadowSphere.set("ndcDepth", 0.0f);
  shadowSphere.set("mapSize", glm::vec2(float(kShadowMapSize)));
  shadowSphere.set("sphereNdc", glm::vec4(c, radius * scaleOfRow(0)));
  shadowSphere.set("depthRadius", radius * scaleOfRow(2));
  glDisable(GL_CULL_FACE);
  glBindVertexArray(streams.empty);
  glEnable(GL_SCISSOR_TEST);
  for (const PixelRect& band : sphereBands(map, *box, centre, radius, kImpostorMarginPx, kImpostorBandRows)) {
    glScissor(band.x0, kShadowMapSize - band.y1, band.x1 - band.x0, band.y1 - band.y0);
    shadowSphere.set("ndcRect", ndcRectOf(map, band));
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace

// The light's box (shadowCenter, shadowRadius) fixes the depth range;
// across the light it is narrowed to the casters' bounding spheres plus the
// filter radius, because every pixel of a receiver inside the box pays for
// the filter, and a tighter box is a finer map.
ShadowSetup shadowPass(const View& v, const std::vector<Drawable>& items, const ShadowMap& map, GpuCaches& caches,
                       Programs& programs, const VertexStreams& streams) {
  const Light& l = v.light;
  const glm::vec3 toward = glm::normalize(l.towardLight);
  const glm::vec3 up = std::abs(toward.z) < 0.95f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
  const float r = l.shadowRadius;
  const glm::mat4 lightViewFromWorld = glm::lookAt(l.shadowCenter + toward * (2.0f * r), l.shadowCenter, up);
  glm::vec2 lo(r), hi(-r);
  for (const Drawable& d : items) {
    if (!d.material->castsShadow || d.material->opacity < 0.5f) continue;
    const glm::vec4 b = caches.mesh(d.mesh).bound;
    const glm::mat3 linear(d.worldFromModel);
    const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
    const glm::vec3 c(lightViewFromWorld * d.worldFromModel * glm::vec4(glm::vec3(b), 1.0f));
    lo = glm::min(lo, glm::vec2(c) - b.w * scale);
    hi = glm::max(hi, glm::vec2(c) + b.w * scale);
  }
  glm::vec2 centre(0.0f);
  float half = r;
  if (lo.x <= hi.x) {  // some caster: a square around them, inside the light's box
    lo = glm::max(lo, glm::vec2(-r));
    hi = glm::min(hi, glm::vec2(r));
    centre = 0.5f * (lo + hi);
    half = std::min(r, 0.5f * std::max(hi.x - lo.x, hi.y - lo.y) + l.shadowSoftness * 1.1f);
  }
  // Depth: from 2r in front of the centre to 6r behind it. A receiver past
  // the far plane is lit, and on a wall lit from above the shadow lands
  // well behind the ball along the light (the floor: about R behind).
  ShadowSetup setup;
  // The map as a view, for a sphere's bands (see drawShadowSphere).
  View mapView;
  mapView.width = mapView.height = kShadowMapSize;
  mapView.camera.viewFromWorld = lightViewFromWorld;
  mapView.camera.clipFromView =
      glm::ortho(centre.x - half, centre.x + half, centre.y - half, centre.y + half, 0.01f * r, 8.0f * r);
  const glm::mat4 lightClipFromWorld = mapView.camera.clipFromView * lightViewFromWorld;
  setup.lightClipFromWorld = lightClipFromWorld;
  // The filter radius in map uv: the light's softness (world units), and
  // at least 1.5 texels so that the edge is always filtered.
  setup.filterRadius = std::max(l.shadowSoftness / (2.0f * half), 1.5f / float(kShadowMapSize));
  glBindFramebuffer(GL_FRAMEBUFFER, map.fbo);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, kShadowMapSize, kShadowMapSize);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  Program& shadow = programs.shadow;
  for (const Drawable& d : items) {
    if (!d.material->castsShadow || d.material->opacity < 0.5f) continue;
    // A sphere that also took a shadow would need the triangles' offset.
    if (d.sphere && !d.material->receivesShadow) {
      drawShadowSphere(d, mapView, lightClipFromWorld, programs.shadowSphere, streams);
      continue;
    }
    shadow.use();
    // Closed casters draw only the faces towards the light: casters take
    // no shadow, so their far sides' depths are never needed.
    if (d.material->cull == Cull::Back) {
      glEnable(GL_CULL_FACE);
      glCullFace(GL_BACK);
    } else {
      glDisable(GL_CULL_FACE);
    }
    shadow.set("lightClipFromModel", lightClipFromWorld * d.worldFromModel);
    const GpuMesh& g = caches.mesh(d.mesh);
    glBindVertexArray(g.vao);
    glDrawElements(GL_TRIANGLES, g.indexCount, GL_UNSIGNED_INT, nullptr);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  return setup;
}

}  // namespace rollspin::render
