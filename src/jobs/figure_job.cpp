#include "jobs/figure_job.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory_budget.hpp"
#include "core/stage_log.hpp"
#include "draw/draw_style.hpp"
#include "draw/text_blocks.hpp"
#include "jobs/job_setup.hpp"
#include "jobs/render_jobs.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"

namespace rollspin::jobs {

namespace {

constexpr int kMaxRasterSide = int(scene::kMaxImageSide);  // the renderer's limit (render.width)

// The figure's raster size: render.dpi over the physical width.
std::pair<int, int> rasterSize(const scene::SceneSpec& spec) {
  const double widthIn = spec.figure.widthMm / 25.4;
  const int width = static_cast<int>(std::lround(widthIn * spec.render.dpi));
  const int height = std::max(1, static_cast<int>(std::lround(double(width) * spec.render.height / spec.render.width)));
  return {width, height};
}

}  // namespace

std::optional<render::FigureFormat> figureFormatOf(const media::OutputFormat& format) {
  if (format.kind != media::OutputKind::Figure) return std::nullopt;
  return format.name == "pdf" ? render::FigureFormat::Pdf : render::FigureFormat::Svg;
}

void checkFigureSpec(const scene::SceneSpec& spec) {
  render::checkFigureFont(spec.figure.font, spec.where("figure.font"));
  const auto [width, height] = rasterSize(spec);
  if (width > kMaxRasterSide || height > kMaxRasterSide)
    throw badInput(spec.where(spec.locations.contains("render.dpi") ? "render.dpi" : "figure.width_mm"),
                   "render.dpi = {} over a {} mm wide figure makes a {}x{} raster; the renderer's limit is {} px",
                   spec.render.dpi, spec.figure.widthMm, width, height, kMaxRasterSide);
  // The GL passes at the raster's size (as checkFrameMemory counts a
  // still's) plus the two images and two depth buffers the figure keeps
  // (16 bytes per pixel).
  const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
  const std::uint64_t needed = rendererBytes(pixels, spec.render.msaa) + pixels * 16ULL;
  const auto available = availableMemoryBytes();
  if (available && needed > *available)
    throw badInput(spec.where(spec.locations.contains("render.dpi") ? "render.dpi" : "figure.width_mm"),
                   "a {}x{} figure raster ({} dpi over {} mm) needs about {} MiB, but only {} MiB are available", width,
                   height, spec.render.dpi, spec.figure.widthMm, needed >> 20, *available >> 20);
}

double figureTextPt(const scene::SceneSpec& spec) { return spec.figure.fontSizePt.value_or(kDefaultFigureTextPt); }

// unit: points per DrawList pixel. The body label's pixel height is its
// ascent + descent, so at the figure font's ratio it prints at the body size.
bool setsFigureKeys(const scene::SceneSpec& spec) {
  return std::any_of(spec.locations.begin(), spec.locations.end(),
                     [](const auto& entry) { return entry.first.rfind("figure.", 0) == 0; });
}

draw::FigureText fitTextToFigure(scene::SceneSpec& spec, bool say) {
  const double unit = spec.figure.widthMm / 25.4 * 72.0 / double(spec.render.width);
  const double bodyPx = figureTextPt(spec) * render::figureFontHeightPerEm(spec.figure.font) / unit;
  const double atScaleOne = draw::bodyTextPx(int(spec.render.width), int(spec.render.height), 1.0);
  spec.render.fontScale = bodyPx / atScaleOne;
  // The sizes are ascent + descent; a bold face's is up to 2 % more per em,
  // so the floor keeps that much above 6 pt.
  const draw::FigureText figureText{1.02 * kLeastFigureTextPt / figureTextPt(spec)};
  if (say && StageLog::instance().echo())
    fmt::print(stderr, "figure: {:.0f} mm wide, body text {:.1f} pt in {} ({:.1f} px of the {}x{} layout)\n",
               spec.figure.widthMm, figureTextPt(spec), spec.figure.font, bodyPx, spec.render.width,
               spec.render.height);
  // A title that would take over a fifth of the figure is left out (scene_drawer).
  if (say && StageLog::instance().echo()) {
    std::vector<std::string> titles{spec.render.title};
    for (const scene::SegmentSpec& segment : spec.segments)
      if (segment.title) titles.push_back(*segment.title);
    const float text = draw::bodyTextPx(int(spec.render.width), int(spec.render.height), spec.render.fontScale);
    for (const std::string& title : titles)
      if (!title.empty() && !draw::titleFitsFigure(title, text, float(spec.render.width), float(spec.render.height),
                                                   text * float(figureText.leastScale)))
        fmt::print(stderr,
                   "figure: the title \"{}\" would take over a fifth of the height at this size: left out "
                   "(docs/figures.md, The title)\n",
                   title);
  }
  return figureText;
}

void writeFigureStill(const scene::SceneSpec& spec, const render::DrawList& list, const std::filesystem::path& out,
                      render::FigureFormat format, const std::filesystem::path& shaderDir,
                      const media::OutputMetadata* metadata) {
  using render::MeshLayer;
  const auto [width, height] = rasterSize(spec);
  render::FigureRasters rasters;
  rasters.width = width;
  rasters.height = height;
  const bool opaque = render::hasMeshes(list, MeshLayer::Opaque);
  const bool translucent = render::hasMeshes(list, MeshLayer::Translucent);
  if (opaque || translucent) {  // GL only for the raster parts
    GlRenderer gl(spec, shaderDir);
    render::Renderer& renderer = gl.renderer;
    if (opaque)
      renderer.renderWithDepth(render::meshLayerOf(list, MeshLayer::Opaque, width, height), rasters.opaque,
                               rasters.opaqueDepth);
    if (translucent) {
      renderer.render(render::meshLayerOf(list, MeshLayer::Translucent, width, height), rasters.translucent);
      media::Image unused;
      std::vector<float> glassDepth;
      renderer.renderWithDepth(render::meshLayerOf(list, MeshLayer::TranslucentDepth, width, height), unused,
                               glassDepth);
      render::hideBehindOpaque(rasters.translucent, glassDepth, rasters.opaqueDepth);
    }
  }
  StageLog::instance().record("figure");
  render::writeFigure(out, format, list, rasters, figureStyleOf(spec, list), metadata);
}

render::FigureStyle figureStyleOf(const scene::SceneSpec& spec, const render::DrawList& list) {
  render::FigureStyle style;
  style.widthPt = spec.figure.widthMm / 25.4 * 72.0;
  style.font = spec.figure.font;
  style.bodyTextPt = figureTextPt(spec);
  // The drawing's own body text size: figure.font_size_pt is set for that one.
  style.bodyTextPx = draw::bodyTextPx(list.width, list.height, spec.render.fontScale);
  style.transparent = spec.figure.transparent;
  return style;
}

}  // namespace rollspin::jobs
