// Readback: the scene's pixels back to the CPU, composited over the views'
// backdrops (composite.hpp) and flipped top-down; the depth buffer for
// vector figures; the retained layer's edge tiles.
#include "render/readback.hpp"

#include <algorithm>
#include <bit>

#include "core/error.hpp"
#include "render/composite.hpp"

namespace rollspin::render {

// The scene's pixels of `r` (image rows, top-down) made the output's, on
// the CPU as they are read back: rows flipped top-down, the view's
// backdrop gradient put behind, values sRGB-encoded bytes as the scene's
// blending left them. llvmpipe pays about 11 ns a pixel for any full-image
// pass (a 1080p still's composite cost 21–22 ms of CPU); this loop costs a
// small fraction of that, and the read-back it rides on is paid anyway. A
// pixel belongs to the last view that holds it, as the views are drawn;
// pixels between views get no backdrop.
void Readback::pixels(const DrawList& list, media::Image& image, const PixelRect& r, GLuint sceneFbo) {
  if (r.empty()) return;
  const int width = r.x1 - r.x0, rows = r.y1 - r.y0;
  std::vector<std::uint32_t>& readRows = rows_;
  readRows.resize(static_cast<std::size_t>(width) * rows);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, sceneFbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(r.x0, list.height - r.y1, width, rows, GL_RGBA, GL_UNSIGNED_BYTE, readRows.data());
  static_assert(std::endian::native == std::endian::little, "the packed RGBA8 words assume little endian");
  const std::uint32_t opaqueAlpha = list.transparent ? 0u : 255u;
  // Each view's backdrop ends, sRGB-encoded once (not per row).
  std::vector<std::pair<glm::vec3, glm::vec3>>& ends = backdrops_;
  ends.clear();
  for (const View& v : list.views) ends.emplace_back(encodeSrgb(v.backgroundTop), encodeSrgb(v.backgroundBottom));
  std::vector<int>& cuts = cuts_;
  for (int y = r.y0; y < r.y1; ++y) {
    // GL rows count from the bottom: read row k is image row r.y1 − 1 − k.
    const std::uint32_t* in = readRows.data() + static_cast<std::size_t>(r.y1 - 1 - y) * width;
    auto* out =
        reinterpret_cast<std::uint32_t*>(image.rgba.data() + (static_cast<std::size_t>(y) * list.width + r.x0) * 4);
    // The row cut where views begin and end; each piece belongs to the
    // last view that holds it (or none).
    cuts.assign({r.x0, r.x1});
    for (const View& v : list.views)
      if (y >= v.y && y < v.y + v.height)
        for (const int x : {v.x, v.x + v.width})
          if (x > r.x0 && x < r.x1) cuts.push_back(x);
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      const int x0 = cuts[c], x1 = cuts[c + 1];
      if (x0 == x1) continue;
      std::size_t owner = list.views.size();  // none
      for (std::size_t i = 0; i < list.views.size(); ++i) {
        const View& v = list.views[i];
        if (y >= v.y && y < v.y + v.height && x0 >= v.x && x0 < v.x + v.width) owner = i;
      }
      glm::vec3 backdrop(0.0f);
      if (owner < list.views.size() && list.views[owner].background && !list.transparent) {
        // Linear in the row, sampled at the pixel centre.
        const View& v = list.views[owner];
        const auto& [top, bottom] = ends[owner];
        backdrop = top + (bottom - top) * ((float(y - v.y) + 0.5f) / float(v.height));
      }
      compositeSpan(in + (x0 - r.x0), in + (x1 - r.x0), out + (x0 - r.x0), backdrop, opaqueAlpha);
    }
    if (list.transparent) {
      // Blending left premultiplied colour over the empty background.
      for (int x = 0; x < width; ++x) {
        auto* p = reinterpret_cast<std::uint8_t*>(out + x);
        if (p[3] != 0 && p[3] != 255)
          for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(std::min(255, (p[c] * 255 + p[3] / 2) / p[3]));
      }
    }
  }
}

// Vector figures: the scene's depth after render() (one sample, at the
// pixel centres: see drawOpaqueAtCentres).
void readDepth(GLuint sceneFbo, int width, int height, std::vector<float>& depth) {
  const int w = width, h = height;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, sceneFbo);
  std::vector<float> bottomUp(static_cast<std::size_t>(w) * h);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, bottomUp.data());
  const GLenum err = glGetError();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (err != GL_NO_ERROR)
    throw runtimeError({}, "OpenGL error 0x{:x} while reading back a {}x{} depth buffer", err, w, h);
  depth.resize(bottomUp.size());
  for (int y = 0; y < h; ++y)  // GL rows count from the bottom
    std::copy_n(bottomUp.begin() + std::ptrdiff_t(h - 1 - y) * w, w, depth.begin() + std::ptrdiff_t(y) * w);
}

// The retained layer's tiles where its resolved opaque items cover pixels in
// part: read back once per layer.
std::vector<PixelRect> partlyCoveredTiles(const DrawList& list, GLuint sceneFbo) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(list.width) * list.height * 4);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, sceneFbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, list.width, list.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  TileGrid grid(list.width, list.height);
  for (int row = 0; row < list.height; ++row) {
    const int y = list.height - 1 - row;  // GL counts rows from the bottom
    const std::uint8_t* p = &rgba[static_cast<std::size_t>(row) * list.width * 4];
    for (int x = 0; x < list.width; ++x)
      if (const std::uint8_t a = p[x * 4 + 3]; a != 0 && a != 255) grid.add(PixelRect{x, y, x + 1, y + 1});
  }
  return grid.rects();
}

}  // namespace rollspin::render
