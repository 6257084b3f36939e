#include "draw/clip_layout.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>

#include "render/font_atlas.hpp"

namespace rollspin::draw {

Occupancy::Occupancy(int width, int height)
    : width_(std::max(width, 1)),
      height_(std::max(height, 1)),
      // About 160 cells across the view's height: fine enough for text rows.
      cell_(std::max(1.0f, float(std::max(height, 1)) / 160.0f)) {
  cellsX_ = int(std::ceil(float(width_) / cell_));
  cellsY_ = int(std::ceil(float(height_) / cell_));
  cells_.assign(std::size_t(cellsX_) * std::size_t(cellsY_), 0);
}

void Occupancy::mark(int cx, int cy) {
  if (cx >= 0 && cy >= 0 && cx < cellsX_ && cy < cellsY_)
    cells_[std::size_t(cy) * std::size_t(cellsX_) + std::size_t(cx)] = 1;
}

void Occupancy::disc(glm::vec2 c, float r) {
  const int x0 = int(std::floor((c.x - r) / cell_)), x1 = int(std::floor((c.x + r) / cell_));
  const int y0 = int(std::floor((c.y - r) / cell_)), y1 = int(std::floor((c.y + r) / cell_));
  if (x1 < 0 || y1 < 0 || x0 >= cellsX_ || y0 >= cellsY_) return;
  const int xMin = std::max(x0, 0), xMax = std::min(x1, cellsX_ - 1);
  const float r2 = r * r;
  for (int y = std::max(y0, 0); y <= std::min(y1, cellsY_ - 1); ++y) {
    // A cell is marked when its nearest point to the centre lies within r.
    const float ny = std::clamp(c.y, float(y) * cell_, float(y + 1) * cell_);
    const float dy2 = (ny - c.y) * (ny - c.y);
    if (dy2 > r2) continue;
    auto inside = [&](int x) {
      const float nx = std::clamp(c.x, float(x) * cell_, float(x + 1) * cell_);
      return (nx - c.x) * (nx - c.x) + dy2 <= r2;
    };
    // The marked cells of a row are one run (the distance grows away from
    // the centre's cell): its ends from the chord's half-width, then moved
    // to where the test itself flips, so the run is exactly the cells the
    // test accepts, found in a few tests rather than one per cell (a disc
    // as wide as the ball spans hundreds of cells, and the layout marks
    // thousands of them for every window it tries).
    const float half = std::sqrt(std::max(0.0f, r2 - dy2));
    int lo = std::clamp(int(std::ceil((c.x - half) / cell_)) - 1, xMin, xMax);
    int hi = std::clamp(int(std::floor((c.x + half) / cell_)), xMin, xMax);
    if (lo > hi) std::swap(lo, hi);
    while (lo > xMin && inside(lo - 1)) --lo;
    while (lo <= hi && !inside(lo)) ++lo;
    while (hi < xMax && inside(hi + 1)) ++hi;
    while (hi >= lo && !inside(hi)) --hi;
    if (lo > hi) {
      // The estimate missed a run of a cell or two (rounding at a chord
      // shorter than a cell): test the row's cells one by one.
      for (int x = xMin; x <= xMax; ++x)
        if (inside(x)) mark(x, y);
      continue;
    }
    std::fill_n(cells_.begin() + std::ptrdiff_t(std::size_t(y) * std::size_t(cellsX_) + std::size_t(lo)), hi - lo + 1,
                static_cast<unsigned char>(1));
  }
}

void Occupancy::rect(glm::vec2 lo, glm::vec2 hi) {
  for (int y = std::max(0, int(std::floor(lo.y / cell_))); y <= std::min(cellsY_ - 1, int(std::floor(hi.y / cell_)));
       ++y)
    for (int x = std::max(0, int(std::floor(lo.x / cell_))); x <= std::min(cellsX_ - 1, int(std::floor(hi.x / cell_)));
         ++x)
      mark(x, y);
}

void Occupancy::segment(glm::vec2 a, glm::vec2 b, float halfWidth) {
  const float length = glm::length(b - a);
  const int steps = std::max(1, int(std::ceil(length / (0.5f * cell_))));
  if (steps > 100000) return;  // a segment from behind the camera: not drawn either
  for (int i = 0; i <= steps; ++i) disc(a + (b - a) * (float(i) / float(steps)), halfWidth);
}

std::pair<glm::vec2, glm::vec2> Occupancy::bounds() const {
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int y = 0; y < cellsY_; ++y)
    for (int x = 0; x < cellsX_; ++x)
      if (cells_[std::size_t(y) * std::size_t(cellsX_) + std::size_t(x)] != 0) {
        lo = glm::min(lo, glm::vec2(float(x), float(y)) * cell_);
        hi = glm::max(hi, glm::vec2(float(x + 1), float(y + 1)) * cell_);
      }
  return {lo, hi};
}

bool Occupancy::anyIn(glm::vec2 lo, glm::vec2 hi) const {
  const int x0 = std::max(0, int(std::floor(lo.x / cell_))), x1 = std::min(cellsX_ - 1, int(std::floor(hi.x / cell_)));
  const int y0 = std::max(0, int(std::floor(lo.y / cell_))), y1 = std::min(cellsY_ - 1, int(std::floor(hi.y / cell_)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      if (cells_[std::size_t(y) * std::size_t(cellsX_) + std::size_t(x)] != 0) return true;
  return false;
}

// Measured at 64 px once per weight; advances scale with the size (the
// atlas is not hinted), plus 2 % for rounding at small sizes. The advances
// alone: a 64 px atlas's glyphs would be rasterised only to be measured.
float textWidthPx(const std::string& text, float sizePx, bool bold) {
  static std::once_flag once[2];
  static std::unique_ptr<render::FontAdvances> advances[2];
  const int k = bold ? 1 : 0;
  std::call_once(once[k],
                 [&] { advances[k] = std::make_unique<render::FontAdvances>(render::defaultFontFile(bold), 64.0f); });
  return advances[k]->width(text) * sizePx / 64.0f * 1.02f;
}

std::vector<std::string> wrapText(const std::string& text, float sizePx, bool bold, float maxWidth, bool balanced) {
  std::vector<std::string> words;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t space = std::min(text.find(' ', start), text.size());
    if (space > start) words.push_back(text.substr(start, space - start));
    start = space + 1;
  }
  if (words.size() < 2) return {text};
  // Greedy: each line takes words while they fit.
  auto greedy = [&](float width) {
    std::vector<std::string> lines{words.front()};
    for (std::size_t k = 1; k < words.size(); ++k) {
      const std::string longer = lines.back() + " " + words[k];
      if (textWidthPx(longer, sizePx, bold) <= width) lines.back() = longer;
      else lines.push_back(words[k]);
    }
    return lines;
  };
  std::vector<std::string> lines = greedy(maxWidth);
  if (!balanced || lines.size() < 2) return lines;
  // The narrowest width that keeps the count: lines of even length.
  float lo = 0.0f, hi = maxWidth;
  for (int i = 0; i < 12; ++i) {
    const float mid = 0.5f * (lo + hi);
    (greedy(mid).size() > lines.size() ? lo : hi) = mid;
  }
  return greedy(hi);
}

void wrapToWidth(TextBlock& block, float maxWidth, float minSizePx) {
  if (block.lines.empty()) return;
  const float room = maxWidth - 2.0f * kBlockPad * block.lines.front().sizePx;
  // A running value is measured with every digit an 8 and one more digit.
  auto widest = [](const TextLine& l) {
    if (!l.live) return textWidthPx(l.text, l.sizePx, l.bold);
    std::string t = l.text;
    for (char& c : t)
      if (c >= '0' && c <= '9') c = '8';
    return textWidthPx(t + "8", l.sizePx, l.bold);
  };
  std::vector<TextLine> lines;
  std::size_t keep = block.keep;
  for (std::size_t i = 0; i < block.lines.size(); ++i) {
    const TextLine& line = block.lines[i];
    if (widest(line) <= room) {
      lines.push_back(line);
      continue;
    }
    // A view's heading is a name of two words ("rolling ball"): broken in
    // two it reads as two lines of text, so it shrinks to fit (to the least
    // size) rather than wrap. Longer bold lines (captions) wrap.
    if (line.bold && std::count(line.text.begin(), line.text.end(), ' ') <= 1 &&
        line.sizePx * room / widest(line) >= minSizePx) {
      TextLine smaller = line;
      smaller.sizePx = line.sizePx * room / widest(line);
      lines.push_back(smaller);
      continue;
    }
    // The slack a running value needs comes off the room it breaks in.
    const float slack = widest(line) - textWidthPx(line.text, line.sizePx, line.bold);
    const std::vector<std::string> parts = wrapText(line.text, line.sizePx, line.bold, room - slack, block.centred);
    for (const std::string& part : parts) {
      TextLine piece = line;
      piece.continued = &part != &parts.front();
      piece.text = part;
      // One word wider than the view: the last resort is a smaller size.
      const float width = widest(piece);
      if (width > room) piece.sizePx = std::max(std::min(piece.sizePx, minSizePx), piece.sizePx * room / width);
      lines.push_back(piece);
    }
    if (i < block.keep) keep += parts.size() - 1;
  }
  block.keep = keep;
  block.lines = std::move(lines);
}

glm::vec2 blockSize(const TextBlock& block) {
  if (block.lines.empty()) return glm::vec2(0.0f);
  const float pad = kBlockPad * block.lines.front().sizePx;
  float width = 0.0f, height = 0.0f;
  for (const TextLine& l : block.lines) {
    width = std::max(width, textWidthPx(l.text, l.sizePx, l.bold));
    height += kLineStep * l.sizePx;
  }
  return glm::max(block.minSize,
                  glm::vec2(width + 2.0f * pad, height + 2.0f * pad - 0.25f * block.lines.back().sizePx));
}

std::vector<std::string> wholeLines(const TextBlock& block) {
  std::vector<std::string> whole;
  for (const TextLine& line : block.lines)
    if (line.continued && !whole.empty()) whole.back() += " " + line.text;
    else whole.push_back(line.text);
  return whole;
}

namespace {

struct Rect {
  glm::vec2 lo, hi;
  [[nodiscard]] bool overlaps(const Rect& o) const {
    return lo.x < o.hi.x && o.lo.x < hi.x && lo.y < o.hi.y && o.lo.y < hi.y;
  }
};

glm::vec2 slotOrigin(Slot slot, glm::vec2 size, int w, int h, float margin) {
  const float W = float(w), H = float(h);
  switch (slot) {
    case Slot::TopLeft: return {margin, margin};
    case Slot::TopRight: return {W - margin - size.x, margin};
    case Slot::BottomLeft: return {margin, H - margin - size.y};
    case Slot::BottomRight: return {W - margin - size.x, H - margin - size.y};
    case Slot::TopCentre: return {0.5f * (W - size.x), margin};
    case Slot::BottomCentre: return {0.5f * (W - size.x), H - margin - size.y};
  }
  return {margin, margin};
}

}  // namespace

namespace {

bool isTop(Slot s) { return s == Slot::TopLeft || s == Slot::TopRight || s == Slot::TopCentre; }
bool isCentre(Slot s) { return s == Slot::TopCentre || s == Slot::BottomCentre; }
bool isLeft(Slot s) { return s == Slot::TopLeft || s == Slot::BottomLeft; }

// The slot's corner, moved down (top slots) or up (bottom slots) past the
// blocks already placed there, so that blocks stack instead of overlapping.
Rect stackedRect(Slot slot, glm::vec2 size, int w, int h, float margin, const std::vector<Rect>& placed) {
  Rect r{slotOrigin(slot, size, w, h, margin), slotOrigin(slot, size, w, h, margin) + size};
  for (bool moved = true; moved;) {
    moved = false;
    for (const Rect& p : placed)
      if (p.overlaps(r)) {
        const float dy = isTop(slot) ? p.hi.y + 0.5f * margin - r.lo.y : p.lo.y - 0.5f * margin - r.hi.y;
        r.lo.y += dy;
        r.hi.y += dy;
        moved = true;
      }
  }
  return r;
}

bool sameWindow(const NdcWindow& a, const NdcWindow& b) {
  return a.x0 == b.x0 && a.x1 == b.x1 && a.y0 == b.y0 && a.y1 == b.y1;
}

}  // namespace

namespace {

// No room even with the narrowest window: a block drops its last line
// (down to what it keeps; the lowest givesWay first, among equals the one
// that failed, `failed`); a broken line goes whole (its pieces are
// continued lines). False where no block has a line to drop.
bool dropLastLine(std::vector<TextBlock>& blocks, std::vector<glm::vec2>& sizes, std::size_t failed) {
  std::size_t i = blocks.size();
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    if (blocks[k].lines.empty() || blocks[k].lines.size() <= blocks[k].keep) continue;
    if (i == blocks.size() || blocks[k].givesWay < blocks[i].givesWay ||
        (blocks[k].givesWay == blocks[i].givesWay && k == failed))
      i = k;
  }
  if (i == blocks.size()) return false;
  TextBlock& b = blocks[i];
  float step = 0.0f;
  for (bool piece = true; piece && !b.lines.empty();) {
    piece = b.lines.back().continued;
    step += kLineStep * b.lines.back().sizePx;
    b.lines.pop_back();
  }
  sizes[i] = b.lines.empty() ? glm::vec2(0.0f) : glm::vec2(sizes[i].x, sizes[i].y - step);
  return true;
}

// The first block that found no free slot (index < 0: none), where it was
// put instead (on its first slot), and the rectangles placed before it.
struct FailedBlock {
  int index = -1;
  Rect rect{};
  std::vector<Rect> placedBefore;
};

// Puts each block on the first of its slots where it fits the view and
// keeps half an em clear of what the occupancy marks (with fixedWindow, any
// corner: a camera the scene fixes cannot make room); a block that finds
// none lies on its first slot. Sets layout.origins and layout.found.
FailedBlock placeBlocks(int w, int h, const std::vector<TextBlock>& blocks, const std::vector<glm::vec2>& sizes,
                        const Occupancy& occupancy, bool fixedWindow, ViewLayout& layout) {
  layout.origins.assign(blocks.size(), glm::vec2(0.0f));
  layout.found.assign(blocks.size(), true);
  std::vector<Rect> placed;
  FailedBlock failed;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (blocks[i].lines.empty()) continue;
    const float margin = 0.5f * blocks[i].lines.front().sizePx;
    bool found = false;
    std::vector<Slot> slots = blocks[i].slots;
    if (fixedWindow)
      for (const Slot extra : {Slot::TopLeft, Slot::TopRight, Slot::BottomLeft, Slot::BottomRight})
        if (std::find(slots.begin(), slots.end(), extra) == slots.end()) slots.push_back(extra);
    for (const Slot slot : slots) {
      const Rect r = stackedRect(slot, sizes[i], w, h, margin, placed);
      if (r.lo.x < 0.0f || r.lo.y < 0.0f || r.hi.x > float(w) || r.hi.y > float(h)) continue;
      if (occupancy.anyIn(r.lo - glm::vec2(margin), r.hi + glm::vec2(margin))) continue;
      layout.origins[i] = r.lo;
      placed.push_back(r);
      found = true;
      break;
    }
    if (!found) {
      layout.found[i] = false;
      const Rect r = stackedRect(blocks[i].slots.front(), sizes[i], w, h, margin, placed);
      layout.origins[i] = r.lo;
      if (failed.index < 0) failed = {int(i), r, placed};
      placed.push_back(r);
    }
  }
  return failed;
}

// What layOutBlocks needs to narrow the window for text.
struct WindowLimits {
  const std::function<Occupancy(const NdcWindow&)>& occupancyFor;
  double minWindow;
  const SubjectShare& subject;
};

// The window narrowed to leave the failed block's column or band free,
// whichever costs the subject less (its scale is limited by the window's
// width over its projected width, or height over height); the other if
// that one is not usable: the same window, under minWindow, or (a figure's
// subject keeps its share of the view: its text gives way first) leaving
// the subject under its least share (SubjectShare). A side already given
// to text grows (the block stacks there) before a new one is taken. None
// where neither is usable.
std::optional<NdcWindow> windowClearOf(int w, int h, const TextBlock& block, glm::vec2 size, FailedBlock failed,
                                       const NdcWindow& window, const Occupancy& occupancy,
                                       const WindowLimits& limits) {
  auto sideTaken = [&](Slot sl) {
    if (isTop(sl) && window.y1 < 1.0) return true;
    if (!isTop(sl) && window.y0 > -1.0) return true;
    if (!isCentre(sl) && isLeft(sl) && window.x0 > -1.0) return true;
    return !isCentre(sl) && !isLeft(sl) && window.x1 < 1.0;
  };
  Slot slot = block.slots.front();
  for (const Slot sl : block.slots)
    if (sideTaken(sl)) {
      slot = sl;
      failed.rect = stackedRect(sl, size, w, h, 0.5f * block.lines.front().sizePx, failed.placedBefore);
      break;
    }
  const Rect& failedRect = failed.rect;
  const float margin = block.lines.front().sizePx;
  // (The fit pads the ball by R; perspective and the gap want a little more.)
  const double column =
      (isLeft(slot) ? double(failedRect.hi.x + 2.0f * margin) : double(w - failedRect.lo.x + 2.0f * margin)) / w + 0.02;
  const double band =
      (isTop(slot) ? double(failedRect.hi.y + 2.0f * margin) : double(h - failedRect.lo.y + 2.0f * margin)) / h + 0.02;
  auto narrowed = [&](bool byColumn) {
    NdcWindow win = window;
    if (byColumn) {
      if (isLeft(slot)) win.x0 = std::max(win.x0, -1.0 + 2.0 * column);
      else win.x1 = std::min(win.x1, 1.0 - 2.0 * column);
    } else if (isTop(slot)) {
      win.y1 = std::min(win.y1, 1.0 - 2.0 * band);
    } else {
      win.y0 = std::max(win.y0, -1.0 + 2.0 * band);
    }
    return win;
  };
  auto subjectShare = [&](const NdcWindow& win) {
    const auto [lo, hi] = limits.subject.boundsFor ? limits.subject.boundsFor(win) : limits.occupancyFor(win).bounds();
    return hi.x > lo.x ? double(std::max(hi.x - lo.x, hi.y - lo.y)) / double(std::min(w, h)) : 1.0;
  };
  auto usable = [&](const NdcWindow& win) {
    return !sameWindow(win, window) && win.x1 - win.x0 >= limits.minWindow && win.y1 - win.y0 >= limits.minWindow &&
           (limits.subject.least <= 0.0 || subjectShare(win) >= limits.subject.least);
  };
  const auto [subjectLo, subjectHi] = occupancy.bounds();
  const double subjectAspect =
      subjectHi.x > subjectLo.x ? double(subjectHi.x - subjectLo.x) / double(subjectHi.y - subjectLo.y) : 1.0;
  auto scaleLeft = [&](const NdcWindow& win) {
    return std::min((win.x1 - win.x0) * w / subjectAspect, (win.y1 - win.y0) * double(h));
  };
  const bool columnAllowed = !isCentre(slot) && !block.bandOnly;
  const bool columnFirst = columnAllowed && scaleLeft(narrowed(true)) >= scaleLeft(narrowed(false));
  NdcWindow next = narrowed(columnFirst);
  if (!usable(next) && columnAllowed) next = narrowed(!columnFirst);
  if (!usable(next)) return std::nullopt;
  return next;
}

// One pass of layoutView with a given least window; `clear` says whether
// every block found room (else the last failed one sits on its first slot).
// Each attempt places the blocks; where one finds no room, the window is
// narrowed for it (windowClearOf), else a line is dropped (dropLastLine)
// and the layout starts again from the widest window.
ViewLayout layOutBlocks(int w, int h, const std::vector<TextBlock>& given,
                        const std::function<Occupancy(const NdcWindow&)>& occupancyFor, bool fixedWindow,
                        double minWindow, const SubjectShare& subject, bool& clear) {
  ViewLayout layout;
  std::vector<TextBlock> blocks = given;
  std::vector<glm::vec2> sizes;
  for (const TextBlock& b : blocks) sizes.push_back(blockSize(b));
  auto dropLine = [&](std::size_t failed) {
    if (!dropLastLine(blocks, sizes, failed)) return false;
    layout.window = NdcWindow{};
    return true;
  };
  auto finish = [&] {
    layout.lines.clear();
    for (const TextBlock& b : blocks) layout.lines.push_back(b.lines.size());
    return layout;
  };
  const WindowLimits limits{occupancyFor, minWindow, subject};
  for (int attempt = 0;; ++attempt) {
    const Occupancy occupancy = occupancyFor(layout.window);
    const FailedBlock failed = placeBlocks(w, h, blocks, sizes, occupancy, fixedWindow, layout);
    clear = failed.index < 0;
    if (failed.index < 0 || attempt >= 40) return finish();
    const auto f = std::size_t(failed.index);
    if (fixedWindow) {
      if (dropLine(f)) continue;
      return finish();
    }
    const std::optional<NdcWindow> next =
        windowClearOf(w, h, blocks[f], sizes[f], failed, layout.window, occupancy, limits);
    if (!next) {
      if (dropLine(f)) continue;
      return finish();
    }
    layout.window = *next;
  }
}

}  // namespace

ViewLayout layoutView(int w, int h, const std::vector<TextBlock>& blocks,
                      const std::function<Occupancy(const NdcWindow&)>& occupancyFor, bool fixedWindow,
                      double minWindow, const SubjectShare& subject) {
  // The passes below try the same windows again (each starts from the
  // whole view; a dropped line starts over): each window's occupancy is
  // computed once. It is a function of the window alone, and costly (the
  // ball, its trail and the path as seen from every camera of the clip).
  std::vector<std::pair<NdcWindow, Occupancy>> seen;
  const std::function<Occupancy(const NdcWindow&)> occupancyOnce = [&](const NdcWindow& window) {
    for (const auto& [known, occupancy] : seen)
      if (sameWindow(known, window)) return occupancy;
    seen.emplace_back(window, occupancyFor(window));
    return seen.back().second;
  };
  bool clear = false;
  ViewLayout layout = layOutBlocks(w, h, blocks, occupancyOnce, fixedWindow, minWindow, subject, clear);
  // Text over the subject is worse than a smaller subject: where even the
  // lines that must stay find no room, allow the narrowest window.
  constexpr double kNarrowest = 0.6;
  if (!clear && minWindow > kNarrowest)
    layout = layOutBlocks(w, h, blocks, occupancyOnce, fixedWindow, kNarrowest, subject, clear);
  // Still no room (large text in a small figure): the lines each block
  // keeps give way too, down to its first (a heading, a caption's first
  // line with the rest of it), rather than lie over the subject.
  if (!clear) {
    std::vector<TextBlock> fewer = blocks;
    for (TextBlock& b : fewer) {
      std::size_t first = b.lines.empty() ? 0 : 1;
      while (first < b.lines.size() && b.lines[first].continued) ++first;
      b.keep = std::min(b.keep, first);
    }
    bool fewerClear = false;
    ViewLayout relaxed = layOutBlocks(w, h, fewer, occupancyOnce, fixedWindow, kNarrowest, subject, fewerClear);
    if (fewerClear) layout = relaxed;
  }
  return layout;
}

NdcWindow clearWindow(int w, int h, const std::vector<std::pair<glm::vec2, glm::vec2>>& boxes, float gap,
                      float aspect) {
  // Few boxes (a heading, a legend): every rectangle whose edges are the
  // view's or a padded box's is tried.
  std::vector<float> xs{0.0f, float(w)}, ys{0.0f, float(h)};
  for (const auto& [lo, hi] : boxes) {
    for (const float x : {lo.x - gap, hi.x + gap})
      if (x > 0.0f && x < float(w)) xs.push_back(x);
    for (const float y : {lo.y - gap, hi.y + gap})
      if (y > 0.0f && y < float(h)) ys.push_back(y);
  }
  auto meetsABox = [&](glm::vec2 a, glm::vec2 b) {
    return std::any_of(boxes.begin(), boxes.end(), [&](const auto& box) {
      return a.x < box.second.x + gap && box.first.x - gap < b.x && a.y < box.second.y + gap && box.first.y - gap < b.y;
    });
  };
  glm::vec2 bestLo{0.0f, 0.0f}, bestHi{float(w), float(h)};
  float bestSide = -1.0f, bestArea = -1.0f;
  for (const float x0 : xs)
    for (const float x1 : xs)
      for (const float y0 : ys)
        for (const float y1 : ys) {
          if (x1 <= x0 || y1 <= y0) continue;
          const float side = std::min((x1 - x0) / aspect, y1 - y0), area = (x1 - x0) * (y1 - y0);
          if (side < bestSide || (side == bestSide && area <= bestArea) || meetsABox({x0, y0}, {x1, y1})) continue;
          bestSide = side, bestArea = area;
          bestLo = {x0, y0}, bestHi = {x1, y1};
        }
  return {-1.0 + 2.0 * bestLo.x / w, -1.0 + 2.0 * bestHi.x / w, 1.0 - 2.0 * bestHi.y / h, 1.0 - 2.0 * bestLo.y / h};
}

std::size_t wordsBeforeTheFirstNumber(const std::string& text) {
  const std::size_t digit = text.find_first_of("0123456789");
  if (digit == std::string::npos || digit == 0) return 0;
  const std::size_t space = text.rfind(' ', digit - 1);
  return space == std::string::npos ? 0 : space + 1;
}

void addTextBlock(render::DrawList& list, const TextBlock& block, glm::vec2 origin, int view) {
  if (block.lines.empty()) return;
  const render::View& v = list.views[static_cast<std::size_t>(view)];
  const glm::vec2 size = blockSize(block);
  if (block.plate) {
    // Unproject the block's corners onto a plane just inside the near plane:
    // a screen-aligned quad in front of everything the view draws.
    static const auto quad = [] {
      auto m = std::make_shared<render::MeshData>();
      for (int k = 0; k < 4; ++k) m->vertices.push_back({glm::vec3(float(k & 1), float(k >> 1), 0.0f)});
      m->indices = {0, 1, 2, 1, 3, 2};
      return m;
    }();
    const glm::mat4 worldFromClip = glm::inverse(v.camera.clipFromView * v.camera.viewFromWorld);
    auto unproject = [&](glm::vec2 px) {
      const glm::vec4 p = worldFromClip * glm::vec4(2.0f * px.x / float(v.width) - 1.0f,
                                                    1.0f - 2.0f * px.y / float(v.height), -0.995f, 1.0f);
      return glm::vec3(p) / p.w;
    };
    const glm::vec3 p00 = unproject(origin), p10 = unproject(origin + glm::vec2(size.x, 0.0f)),
                    p01 = unproject(origin + glm::vec2(0.0f, size.y));
    glm::mat4 worldFromModel(1.0f);
    worldFromModel[0] = glm::vec4(p10 - p00, 0.0f);
    worldFromModel[1] = glm::vec4(p01 - p00, 0.0f);
    worldFromModel[2] = glm::vec4(glm::cross(p10 - p00, p01 - p00), 0.0f);
    worldFromModel[3] = glm::vec4(p00, 1.0f);
    render::Material plate;
    plate.color = {0.97f, 0.97f, 0.98f};
    plate.opacity = 0.78f;
    plate.lit = false;
    plate.castsShadow = false;
    plate.specular = 0.0f;
    plate.cull = render::Cull::None;
    list.meshes.push_back({quad, worldFromModel, plate, view});
    list.meshes.back().textPlate = true;
  }
  const float pad = kBlockPad * block.lines.front().sizePx;
  float y = origin.y + pad;
  for (const TextLine& line : block.lines) {
    render::LabelItem l;
    l.view = view;
    l.dynamic = line.live;  // running values are redrawn per frame over the retained layer
    l.text = line.text;
    // The words before a running value's number ("s = ", "lab rotation
    // angle = ") stay: a retained layer keeps them (left-aligned only).
    if (line.live && !block.centred) l.staticPrefixBytes = wordsBeforeTheFirstNumber(line.text);
    // The anchor is the middle of the capital height.
    const float x =
        block.centred ? origin.x + 0.5f * (size.x - textWidthPx(line.text, line.sizePx, line.bold)) : origin.x + pad;
    l.anchor = glm::vec3(x, y + 0.5f * line.sizePx, 0.0f);
    l.sizePx = line.sizePx;
    l.bold = line.bold;
    l.color = line.color;
    list.labels.push_back(l);
    y += kLineStep * line.sizePx;
  }
}

}  // namespace rollspin::draw
