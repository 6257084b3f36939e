#include "render/vector_figure.hpp"

#include <cairo-ft.h>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <fmt/format.h>
#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <exception>
#include <map>
#include <memory>

#include "core/atomic_file.hpp"
#include "core/text.hpp"
#include "render/figure_fonts.hpp"
#include "render/font_atlas.hpp"

namespace rollspin::render {

namespace {

// The renderer's views, scaled to the raster's size. Both the GL pass and
// the placement of its image use this, so they agree to the pixel.
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};
PixelRect scaledRect(const View& v, double kx, double ky) {
  const int x0 = static_cast<int>(std::lround(v.x * kx)), y0 = static_cast<int>(std::lround(v.y * ky));
  const int x1 = static_cast<int>(std::lround((v.x + v.width) * kx));
  const int y1 = static_cast<int>(std::lround((v.y + v.height) * ky));
  return {x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)};
}

bool inLayer(const MeshItem& m, MeshLayer layer) {
  if (m.figureDisc && m.material.opacity >= 1.0f) return false;  // a vector disc (drawDisc)
  return layer == MeshLayer::Opaque ? m.material.opacity >= 1.0f : m.material.opacity < 1.0f;
}

// Linear → sRGB, exactly (the shaders use a close fit of the same curve).
double encodeSrgb(float linear) {
  const double c = std::clamp(static_cast<double>(linear), 0.0, 1.0);
  return c < 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
void setColor(cairo_t* cr, const glm::vec3& rgb, float alpha) {
  cairo_set_source_rgba(cr, encodeSrgb(rgb.r), encodeSrgb(rgb.g), encodeSrgb(rgb.b), alpha);
}

// A view's projection into figure units (= DrawList pixels), with the GL
// window depth of the line shader (its depth bias included).
struct Projected {
  bool valid = false;
  glm::dvec2 xy{0.0};
  double depth = 1.0;
};
struct ViewProjection {
  glm::dmat4 clipFromWorld{1.0};
  glm::dvec2 origin{0.0}, size{1.0};
  Projected operator()(const glm::dvec3& p, double depthBias = 0.0) const {
    const glm::dvec4 c = clipFromWorld * glm::dvec4(p, 1.0);
    Projected out;
    if (c.w <= 1e-6) return out;  // behind the camera: GL skips the segment too
    out.valid = true;
    out.xy = origin + glm::dvec2((c.x / c.w * 0.5 + 0.5) * size.x, (0.5 - c.y / c.w * 0.5) * size.y);
    out.depth = ((c.z - depthBias * c.w) / c.w) * 0.5 + 0.5;
    return out;
  }
};

// Depth-buffer look-ups in figure units.
struct DepthTest {
  const std::vector<float>* depth = nullptr;
  int width = 0, height = 0;
  double kx = 1.0, ky = 1.0;  // raster pixels per figure unit
  [[nodiscard]] bool visible(const Projected& p) const {
    if (depth == nullptr || depth->empty()) return true;
    const int x = static_cast<int>(std::floor(p.xy.x * kx)), y = static_cast<int>(std::floor(p.xy.y * ky));
    if (x < 0 || y < 0 || x >= width || y >= height) return true;  // outside: clipped by the view anyway
    // GL_LEQUAL against a 24-bit buffer: half a step of slack.
    return p.depth <= double((*depth)[static_cast<std::size_t>(y) * width + x]) + 0.5 / 16777216.0;
  }
};

// A polyline's visible pieces as one path of sub-paths. A projected straight
// segment stays straight, so only its ends and the points where it goes
// behind or comes out from an opaque mesh are needed; those are found by
// stepping about one raster pixel along it and bisecting the step.
void addVisiblePath(cairo_t* cr, const PolylineItem& p, const ViewProjection& project, const DepthTest& test) {
  const double bias = p.depthTested ? 0.0008 : 0.0;  // the line shader's bias (LinePass::draw)
  bool open = false;
  auto extend = [&](const glm::dvec2& q, bool newPiece) {
    if (newPiece || !open) cairo_move_to(cr, q.x, q.y);
    else cairo_line_to(cr, q.x, q.y);
    open = true;
  };
  for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
    const glm::dvec3 a(p.points[i]), b(p.points[i + 1]);
    const Projected pa = project(a, bias), pb = project(b, bias);
    if (!pa.valid || !pb.valid) {
      open = false;
      continue;
    }
    if (!p.depthTested) {
      if (!open) extend(pa.xy, true);
      extend(pb.xy, false);
      continue;
    }
    auto at = [&](double t) { return project(glm::mix(a, b, t), bias); };
    const double lengthPx = glm::length(glm::dvec2((pb.xy.x - pa.xy.x) * test.kx, (pb.xy.y - pa.xy.y) * test.ky));
    const int steps = std::clamp(static_cast<int>(std::ceil(lengthPx)), 1, 4096);
    bool wasVisible = test.visible(pa);
    if (wasVisible && !open) extend(pa.xy, true);
    for (int j = 1; j <= steps; ++j) {
      const double t1 = double(j) / steps;
      const bool isVisible = test.visible(at(t1));
      if (isVisible != wasVisible) {
        double lo = double(j - 1) / steps, hi = t1;  // lo has wasVisible, hi has isVisible
        for (int k = 0; k < 8; ++k) {
          const double mid = 0.5 * (lo + hi);
          (test.visible(at(mid)) == wasVisible ? lo : hi) = mid;
        }
        const glm::dvec2 edge = at(0.5 * (lo + hi)).xy;
        if (wasVisible) {
          extend(edge, false);
          open = false;
        } else {
          extend(edge, true);
        }
        wasVisible = isVisible;
      }
    }
    if (wasVisible) extend(pb.xy, false);
    else open = false;
  }
}

// Convex hull (Andrew's monotone chain), counter-clockwise.
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> pts) {
  std::sort(pts.begin(), pts.end(),
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (pts.size() < 3) return pts;
  auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<glm::dvec2> hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

// An arrow as the renderer builds it (cylinder to the neck, cone to the tip;
// renderer drawablesOf), projected: its shaft's two rims and its head's rim
// with the apex, and the projected axis of each. Empty when a point is behind
// the camera.
struct ProjectedArrow {
  std::vector<glm::dvec2> shaft, head;
  glm::dvec2 origin{0.0}, neck{0.0}, tip{0.0};
};
std::optional<ProjectedArrow> projectArrow(const ArrowItem& a, const ViewProjection& project) {
  const glm::dvec3 origin(a.origin), tip(a.tip);
  const double len = glm::length(tip - origin);
  if (len <= 0.0) return std::nullopt;
  const double r = a.shaftRadius;
  const double headLength = std::min(len * 0.35, r * 6.0);
  const glm::dvec3 dir = (tip - origin) / len;
  const glm::dvec3 neck = tip - dir * headLength;
  const glm::dvec3 helper = std::abs(dir.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, dir)), v = glm::cross(dir, u);
  auto rim = [&](const glm::dvec3& centre, double radius, std::vector<glm::dvec2>& out) {
    for (int k = 0; k < 32; ++k) {
      const double phi = 2.0 * M_PI * k / 32.0;
      const Projected q = project(centre + radius * (std::cos(phi) * u + std::sin(phi) * v));
      if (!q.valid) return false;
      out.push_back(q.xy);
    }
    return true;
  };
  ProjectedArrow out;
  const Projected apex = project(tip), o = project(origin), n = project(neck);
  if (!rim(origin, r, out.shaft) || !rim(neck, r, out.shaft) || !rim(neck, r * 2.6, out.head) || !apex.valid ||
      !o.valid || !n.valid)
    return std::nullopt;
  out.head.push_back(apex.xy);
  out.origin = o.xy, out.neck = n.xy, out.tip = apex.xy;
  return out;
}

// Drawn as the outlines of its two solids: the convex hull of each one's
// projected rims, right for any viewing direction.
void drawArrow(cairo_t* cr, const ArrowItem& a, const ViewProjection& project) {
  const auto arrow = projectArrow(a, project);
  if (!arrow) return;
  setColor(cr, a.color, 1.0f);
  for (const auto* solid : {&arrow->shaft, &arrow->head}) {
    const std::vector<glm::dvec2> hull = convexHull(*solid);
    for (std::size_t k = 0; k < hull.size(); ++k) (k == 0 ? cairo_move_to : cairo_line_to)(cr, hull[k].x, hull[k].y);
    cairo_close_path(cr);
    cairo_fill(cr);
  }
}

// A mark (MeshItem::figureDisc, a unit sphere scaled and placed by
// worldFromModel) as a flat disc of its projected radius, left out where
// its point nearest the camera is behind an opaque mesh.
void drawDisc(cairo_t* cr, const MeshItem& m, const View& v, const ViewProjection& project, const DepthTest& test) {
  const glm::dmat4 worldFromModel(m.worldFromModel);
  const glm::dvec3 centre(worldFromModel[3]);
  const double radius = glm::length(glm::dvec3(worldFromModel[0]));
  const glm::dvec3 toCamera = glm::normalize(glm::dvec3(v.camera.position) - centre);
  const glm::dmat4 viewFromWorld(v.camera.viewFromWorld);
  const glm::dvec3 cameraRight(viewFromWorld[0][0], viewFromWorld[1][0], viewFromWorld[2][0]);
  const Projected c = project(centre), edge = project(centre + radius * cameraRight);
  const Projected front = project(centre + radius * toCamera);
  if (!c.valid || !edge.valid || !front.valid || !test.visible(front)) return;
  setColor(cr, m.material.color, 1.0f);
  cairo_new_sub_path(cr);
  cairo_arc(cr, c.xy.x, c.xy.y, glm::length(edge.xy - c.xy), 0.0, 2.0 * M_PI);
  cairo_fill(cr);
}

// The part of an RGBA image (straight alpha) inside `rect` that is not fully
// transparent, placed at its figure position: the image's own alpha is the
// silhouette, and what is empty is left out of the file.
void paintRaster(cairo_t* cr, const media::Image& image, const PixelRect& rect, double kx, double ky) {
  if (image.rgba.empty()) return;
  const int x0 = std::clamp(rect.x, 0, image.width), y0 = std::clamp(rect.y, 0, image.height);
  const int x1 = std::clamp(rect.x + rect.width, 0, image.width),
            y1 = std::clamp(rect.y + rect.height, 0, image.height);
  int lx = x1, ly = y1, hx = x0 - 1, hy = y0 - 1;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (image.pixel(x, y)[3] != 0) {
        lx = std::min(lx, x), hx = std::max(hx, x);
        ly = std::min(ly, y), hy = std::max(hy, y);
      }
  if (hx < lx) return;
  const int w = hx - lx + 1, h = hy - ly + 1;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < h; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* p = image.pixel(lx + x, ly + y);
      const std::uint32_t alpha = p[3];
      auto premultiply = [&](std::uint8_t c) { return (std::uint32_t(c) * alpha + 127) / 255; };
      row[x] = (alpha << 24) | (premultiply(p[0]) << 16) | (premultiply(p[1]) << 8) | premultiply(p[2]);
    }
  }
  cairo_surface_mark_dirty(surface);
  cairo_save(cr);
  cairo_translate(cr, lx / kx, ly / ky);
  cairo_scale(cr, 1.0 / kx, 1.0 / ky);
  cairo_set_source_surface(cr, surface, 0.0, 0.0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
  cairo_rectangle(cr, 0, 0, w, h);
  cairo_fill(cr);
  cairo_restore(cr);
  cairo_surface_destroy(surface);
}

// A cairo context on a 1x1 surface with the figure's font options, for
// measuring text where nothing is drawn (figureLayout).
struct ScratchContext {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  cairo_t* cr = cairo_create(surface);
  ScratchContext() {
    cairo_font_options_t* options = cairo_font_options_create();
    cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
    cairo_set_font_options(cr, options);
    cairo_font_options_destroy(options);
  }
  ~ScratchContext() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
  ScratchContext(const ScratchContext&) = delete;
  ScratchContext& operator=(const ScratchContext&) = delete;
};

// A label placed as the GL renderer places it (drawLabel): anchor, offset,
// alignment by the advance width, baseline 0.36 of the size below the anchor.
struct PlacedLabel {
  bool valid = false;
  glm::dvec2 anchor{0.0};  // projected, before the offset
  glm::dvec2 pen{0.0};     // the baseline's start
  double width = 0.0, em = 0.0, ascent = 0.0, descent = 0.0;
  std::vector<FigureFonts::Run> runs;
};
PlacedLabel placeLabel(cairo_t* cr, FigureFonts& fonts, const LabelItem& label, const glm::dvec2& origin,
                       const ViewProjection* project, double fontScale) {
  PlacedLabel placed;
  placed.anchor = origin + glm::dvec2(label.anchor.x, label.anchor.y);
  if (label.worldAnchored && project != nullptr) {
    const Projected q = (*project)(glm::dvec3(label.anchor));
    if (!q.valid) return placed;
    placed.anchor = q.xy;
  }
  glm::dvec2 pen = placed.anchor + glm::dvec2(label.offsetPx);
  const double px = label.sizePx * fontScale;
  placed.runs = fonts.runs(label.text, label.bold);
  placed.em = px / fonts.face(label.bold, false).heightPerEm;
  for (const auto& run : placed.runs) {
    cairo_set_font_face(cr, run.face->face);
    cairo_set_font_size(cr, placed.em);
    cairo_text_extents_t e;
    cairo_text_extents(cr, run.utf8.c_str(), &e);
    placed.width += e.x_advance;
    cairo_font_extents_t f;
    cairo_font_extents(cr, &f);
    placed.ascent = std::max(placed.ascent, f.ascent);
    placed.descent = std::max(placed.descent, f.descent);
  }
  if (label.align == Align::Center) pen.x -= 0.5 * placed.width;
  if (label.align == Align::Right) pen.x -= placed.width;
  placed.pen = pen + glm::dvec2(0.0, 0.36 * px);
  placed.valid = true;
  return placed;
}

void drawLabel(cairo_t* cr, FigureFonts& fonts, const LabelItem& label, const glm::dvec2& origin,
               const ViewProjection* project, double fontScale) {
  const PlacedLabel placed = placeLabel(cr, fonts, label, origin, project, fontScale);
  if (!placed.valid) return;
  setColor(cr, glm::vec3(label.color), label.color.a);
  cairo_move_to(cr, placed.pen.x, placed.pen.y);
  for (const auto& run : placed.runs) {
    cairo_set_font_face(cr, run.face->face);
    cairo_set_font_size(cr, placed.em);
    cairo_show_text(cr, run.utf8.c_str());  // advances the current point
  }
  cairo_new_path(cr);
}

// figure.font_size_pt is the body text's em size, as LaTeX's 10pt is; the
// labels' sizePx is their ascent + descent (the GL labels' pixel height).
double labelScale(FigureFonts& fonts, const FigureStyle& style, double unit) {
  return style.bodyTextPt
             ? (*style.bodyTextPt * fonts.face(false, false).heightPerEm / unit) / std::max(1.0f, style.bodyTextPx)
             : 1.0;
}

ViewProjection projectionOf(const View& v) {
  ViewProjection project;
  project.clipFromWorld = glm::dmat4(v.camera.clipFromView * v.camera.viewFromWorld);
  project.origin = glm::dvec2(v.x, v.y);
  project.size = glm::dvec2(v.width, v.height);
  return project;
}

bool overlap(const View& a, const View& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

// cairo writes through this into the AtomicFile; an exception cannot cross
// cairo's C frames, so it is kept and rethrown after.
struct StreamSink {
  AtomicFile* file = nullptr;
  std::exception_ptr error;
  std::string* bytes = nullptr;  // when set, collected here instead (metadata is added to them)
};
cairo_status_t writeToSink(void* closure, const unsigned char* data, unsigned int length) {
  auto* sink = static_cast<StreamSink*>(closure);
  try {
    const std::string_view piece(reinterpret_cast<const char*>(data), length);
    if (sink->bytes) sink->bytes->append(piece);
    else sink->file->write(piece);
    return CAIRO_STATUS_SUCCESS;
  } catch (...) {
    sink->error = std::current_exception();
    return CAIRO_STATUS_WRITE_ERROR;
  }
}

}  // namespace

bool hasMeshes(const DrawList& list, MeshLayer layer) {
  return std::any_of(list.meshes.begin(), list.meshes.end(),
                     [&](const MeshItem& m) { return m.mesh && inLayer(m, layer); });
}

DrawList meshLayerOf(const DrawList& list, MeshLayer layer, int width, int height) {
  DrawList out;
  out.width = width;
  out.height = height;
  out.transparent = true;
  // A depth pass needs no anti-aliasing: one sample is the depth at the pixel.
  out.msaaSamples = layer == MeshLayer::TranslucentDepth ? 1 : list.msaaSamples;
  const double kx = double(width) / list.width, ky = double(height) / list.height;
  for (const View& v : list.views) {
    View scaled = v;
    const PixelRect r = scaledRect(v, kx, ky);
    scaled.x = r.x, scaled.y = r.y, scaled.width = r.width, scaled.height = r.height;
    scaled.background = false;                                    // the page shows through
    scaled.frame = false;                                         // drawn as a vector
    if (layer != MeshLayer::Opaque) scaled.light.shadow = false;  // glass takes no shadow
    out.views.push_back(scaled);
  }
  for (const MeshItem& m : list.meshes) {
    if (!m.mesh || !inLayer(m, layer)) continue;
    out.meshes.push_back(m);
    if (layer == MeshLayer::TranslucentDepth) out.meshes.back().material.opacity = 1.0f;
  }
  return out;
}

void hideBehindOpaque(media::Image& translucent, const std::vector<float>& translucentDepth,
                      const std::vector<float>& opaqueDepth) {
  const std::size_t n = static_cast<std::size_t>(translucent.width) * translucent.height;
  if (translucentDepth.size() != n || opaqueDepth.size() != n) return;
  for (std::size_t i = 0; i < n; ++i)
    if (opaqueDepth[i] < translucentDepth[i]) translucent.rgba[4 * i + 3] = 0;
}


namespace {

// The page, widthPt × heightPt, written through `sink`: PDF (its creator,
// and a fixed creation date for reproducible builds instead of cairo's
// clock) or SVG in points.
cairo_surface_t* figurePage(FigureFormat format, StreamSink& sink, double widthPt, double heightPt) {
  cairo_surface_t* surface = format == FigureFormat::Pdf
                                 ? cairo_pdf_surface_create_for_stream(writeToSink, &sink, widthPt, heightPt)
                                 : cairo_svg_surface_create_for_stream(writeToSink, &sink, widthPt, heightPt);
  if (format == FigureFormat::Pdf) cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "rollspin");
  if (const auto epoch = media::sourceDateEpoch(); epoch && format == FigureFormat::Pdf) {
    const std::time_t t = static_cast<std::time_t>(*epoch);
    std::tm utc{};
    gmtime_r(&t, &utc);
    const std::string date = fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}", utc.tm_year + 1900, utc.tm_mon + 1,
                                         utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec);
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, date.c_str());
  }
  if (format == FigureFormat::Svg) cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PT);
  return surface;
}

// Figure units are the DrawList's pixels, `unit` points each; text as
// outlines, not hinted glyph positions (it scales with the figure); round
// joins and caps.
void setFigurePen(cairo_t* cr, double unit) {
  cairo_scale(cr, unit, unit);
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr, options);
  cairo_font_options_destroy(options);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
}

// Clips to view i's rectangle, less any later view drawn over it (an inset
// clears its rectangle in the GL image too).
void clipToUncoveredView(cairo_t* cr, const DrawList& list, std::size_t i) {
  const View& v = list.views[i];
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_rectangle(cr, v.x, v.y, v.width, v.height);
  for (std::size_t j = i + 1; j < list.views.size(); ++j) {
    const View& w = list.views[j];
    if (!overlap(v, w)) continue;
    const int x0 = std::max(v.x, w.x), y0 = std::max(v.y, w.y);
    const int x1 = std::min(v.x + v.width, w.x + w.width), y1 = std::min(v.y + v.height, w.y + w.height);
    cairo_rectangle(cr, x0, y0, x1 - x0, y1 - y0);
  }
  cairo_clip(cr);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
}

// The composite pass's gradient, interpolated between sRGB-encoded ends.
void paintBackdrop(cairo_t* cr, const View& v) {
  cairo_pattern_t* g = cairo_pattern_create_linear(0.0, v.y, 0.0, v.y + v.height);
  cairo_pattern_add_color_stop_rgb(g, 0.0, encodeSrgb(v.backgroundTop.r), encodeSrgb(v.backgroundTop.g),
                                   encodeSrgb(v.backgroundTop.b));
  cairo_pattern_add_color_stop_rgb(g, 1.0, encodeSrgb(v.backgroundBottom.r), encodeSrgb(v.backgroundBottom.g),
                                   encodeSrgb(v.backgroundBottom.b));
  cairo_set_source(cr, g);
  cairo_paint(cr);
  cairo_pattern_destroy(g);
}

// The view's polylines that are (depthTested) or are not depth-tested, cut
// where a mesh is in front.
void strokeViewLines(cairo_t* cr, const DrawList& list, int index, bool depthTested, const ViewProjection& project,
                     const DepthTest& depth) {
  for (const PolylineItem& p : list.polylines) {
    if (p.view != index || p.depthTested != depthTested || p.points.size() < 2) continue;
    addVisiblePath(cr, p, project, depth);
    setColor(cr, glm::vec3(p.color), p.color.a);
    cairo_set_line_width(cr, p.widthPx);
    cairo_stroke(cr);
  }
}

// The view's frame, mitred.
void strokeViewFrame(cairo_t* cr, const View& v) {
  const double t = std::max(1.0, v.height / 300.0);
  setColor(cr, glm::vec3(0.35f, 0.38f, 0.42f), 1.0f);
  cairo_set_line_width(cr, t);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_rectangle(cr, v.x + 0.5 * t, v.y + 0.5 * t, v.width - t, v.height - t);
  cairo_stroke(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
}

// What a view of the figure is drawn with: the rasters and their scale
// from the list's pixels, the fonts and the labels' scale, the opaque
// depth, the style.
struct FigureView {
  const FigureRasters& rasters;
  double kx, ky;
  FigureFonts& fonts;
  double fontScale;
  const DepthTest& depth;
  const FigureStyle& style;
};

// View i in the GL renderer's order: opaque meshes (image, then the
// marks), depth-tested lines (cut where a mesh is in front), the arrows,
// translucent meshes over them, then the lines that ignore depth, the
// labels and the frame.
void drawFigureView(cairo_t* cr, const DrawList& list, std::size_t i, const FigureView& with) {
  const View& v = list.views[i];
  const int index = static_cast<int>(i);
  cairo_save(cr);
  clipToUncoveredView(cr, list, i);
  if (!with.style.transparent && v.background) paintBackdrop(cr, v);
  const ViewProjection project = projectionOf(v);
  const PixelRect rasterRect = scaledRect(v, with.kx, with.ky);
  paintRaster(cr, with.rasters.opaque, rasterRect, with.kx, with.ky);
  // Marks are opaque meshes too: under the lines, as GL draws them.
  for (const MeshItem& m : list.meshes)
    if (m.view == index && m.mesh && m.figureDisc && m.material.opacity >= 1.0f)
      drawDisc(cr, m, v, project, with.depth);
  strokeViewLines(cr, list, index, true, project, with.depth);
  for (const ArrowItem& a : list.arrows)
    if (a.view == index) drawArrow(cr, a, project);
  paintRaster(cr, with.rasters.translucent, rasterRect, with.kx, with.ky);
  strokeViewLines(cr, list, index, false, project, with.depth);
  for (const LabelItem& l : list.labels)
    if (l.view == index) drawLabel(cr, with.fonts, l, project.origin, &project, with.fontScale);
  if (v.frame) strokeViewFrame(cr, v);
  cairo_restore(cr);
}

}  // namespace

void writeFigure(const std::filesystem::path& out, FigureFormat format, const DrawList& list,
                 const FigureRasters& rasters, const FigureStyle& style, const media::OutputMetadata* metadata) {
  // Figure units are the DrawList's pixels, scaled onto the physical page.
  const double unit = style.widthPt / list.width;
  const double heightPt = unit * list.height;
  const double kx = rasters.width > 0 ? double(rasters.width) / list.width : 1.0;
  const double ky = rasters.height > 0 ? double(rasters.height) / list.height : 1.0;

  AtomicFile file(out);
  std::string bytes;
  StreamSink sink{&file, nullptr, metadata ? &bytes : nullptr};
  cairo_surface_t* surface = figurePage(format, sink, style.widthPt, heightPt);
  cairo_t* cr = cairo_create(surface);
  setFigurePen(cr, unit);

  FigureFonts fonts(style.font);
  const double fontScale = labelScale(fonts, style, unit);
  const DepthTest depth{&rasters.opaqueDepth, rasters.width, rasters.height, kx, ky};
  const FigureView with{rasters, kx, ky, fonts, fontScale, depth, style};
  for (std::size_t i = 0; i < list.views.size(); ++i) drawFigureView(cr, list, i, with);
  // Image-level labels (the title) over everything.
  for (const LabelItem& l : list.labels)
    if (l.view < 0) drawLabel(cr, fonts, l, glm::dvec2(0.0), nullptr, fontScale);

  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (sink.error) std::rethrow_exception(sink.error);
  if (status != CAIRO_STATUS_SUCCESS)
    throw runtimeError({out.string()}, "cairo could not write the figure: {}", cairo_status_to_string(status));
  if (metadata)
    file.write(format == FigureFormat::Pdf ? media::withPdfMetadata(bytes, *metadata)
                                           : media::withSvgMetadata(bytes, *metadata));
  file.commit();
}


namespace {

double distanceToSegment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 d = b - a;
  const double t = glm::clamp(glm::dot(p - a, d) / std::max(glm::dot(d, d), 1e-12), 0.0, 1.0);
  return glm::length(p - (a + t * d));
}

// A solid's points as a segment along its axis a → b, as wide as its widest
// point is from the axis.
FigureLayout::Segment alongAxis(const glm::dvec2& a, const glm::dvec2& b, const std::vector<glm::dvec2>& points,
                                double unit) {
  double half = 0.0;
  for (const glm::dvec2& p : points) half = std::max(half, distanceToSegment(p, a, b));
  return {a * unit, b * unit, half * unit};
}

}  // namespace

FigureLayout figureLayout(const DrawList& list, const FigureStyle& style) {
  const double unit = style.widthPt / list.width;  // page points per DrawList pixel
  FigureLayout layout;
  layout.widthPt = style.widthPt;
  layout.heightPt = unit * list.height;
  for (const std::string& text : list.leftOut) layout.leftOut.push_back({text, std::nullopt, std::nullopt});
  FigureFonts fonts(style.font);
  const double fontScale = labelScale(fonts, style, unit);
  ScratchContext scratch;
  auto box = [&](glm::dvec2 lo, glm::dvec2 hi) {
    return FigureBox{lo.x * unit, lo.y * unit, hi.x * unit, hi.y * unit};
  };
  auto addText = [&](const LabelItem& l, const ViewProjection* project, const glm::dvec2& origin) {
    const PlacedLabel placed = placeLabel(scratch.cr, fonts, l, origin, project, fontScale);
    if (!placed.valid || l.text.empty()) return;
    FigureLayout::Text t;
    t.text = l.text;
    t.box = box(placed.pen - glm::dvec2(0.0, placed.ascent), placed.pen + glm::dvec2(placed.width, placed.descent));
    t.anchor = placed.anchor * unit;
    t.free = l.worldAnchored;
    t.view = l.view;
    t.sizePt = placed.em * unit;
    layout.texts.push_back(t);
  };
  for (std::size_t i = 0; i < list.views.size(); ++i) {
    const View& v = list.views[i];
    const int index = static_cast<int>(i);
    const ViewProjection project = projectionOf(v);
    layout.views.push_back(box({v.x, v.y}, {v.x + v.width, v.y + v.height}));
    // A view that draws nothing but text (the title's band) is its text's plate.
    const bool textOnly =
        std::none_of(list.meshes.begin(), list.meshes.end(), [&](const MeshItem& m) { return m.view == index; }) &&
        std::none_of(list.arrows.begin(), list.arrows.end(), [&](const ArrowItem& a) { return a.view == index; }) &&
        std::none_of(list.polylines.begin(), list.polylines.end(),
                     [&](const PolylineItem& p) { return p.view == index; });
    if (textOnly) layout.plates.push_back(layout.views.back());
    for (const MeshItem& m : list.meshes) {
      if (m.view != index || !m.textPlate || !m.mesh) continue;
      glm::dvec2 lo(1e300), hi(-1e300);
      for (const Vertex& vertex : m.mesh->vertices) {
        const Projected q = project(glm::dvec3(m.worldFromModel * glm::vec4(vertex.position, 1.0f)));
        lo = glm::min(lo, q.xy), hi = glm::max(hi, q.xy);
      }
      layout.plates.push_back(box(lo, hi));
    }
    for (const ArrowItem& a : list.arrows) {
      if (a.view != index) continue;
      if (const auto arrow = projectArrow(a, project)) {
        layout.arrows.push_back(alongAxis(arrow->origin, arrow->neck, arrow->shaft, unit));
        layout.arrows.push_back(alongAxis(arrow->neck, arrow->tip, arrow->head, unit));
      }
    }
    for (const PolylineItem& p : list.polylines) {
      if (p.view != index || !p.labelsKeepOff) continue;
      for (std::size_t k = 0; k + 1 < p.points.size(); ++k) {
        const Projected a = project(glm::dvec3(p.points[k])), b = project(glm::dvec3(p.points[k + 1]));
        if (a.valid && b.valid) layout.paths.push_back({a.xy * unit, b.xy * unit, 0.5 * p.widthPx * unit});
      }
    }
    for (const LabelItem& l : list.labels)
      if (l.view == index) addText(l, &project, project.origin);
  }
  for (const LabelItem& l : list.labels)
    if (l.view < 0) addText(l, nullptr, glm::dvec2(0.0));
  return layout;
}

}  // namespace rollspin::render
