// Layout decided per clip: text blocks go where nothing important (the ball
// at any frame, the contact path, the trails) is drawn in any frame, and the
// camera frames the scene into the part of the view the text leaves free.
//   1. measure each block (lines × the font's advances, line step 1.4 em);
//   2. project the clip into an occupancy grid for the camera's window;
//   3. put each block in its first free slot (corners, then top/bottom
//      centre); a block that finds none narrows the window by its own width
//      (a side column) or height (a band), whichever costs the smaller share,
//      and the clip is projected again.
// Plain geometry; the text is ordinary DrawList labels over a translucent
// backing plate (a screen-aligned quad just inside the near plane).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "render/draw_list.hpp"

namespace rollspin::draw {

// The part of a view, in normalised device coordinates (y up), the camera
// frames its subject into.
struct NdcWindow {
  double x0 = -1.0, x1 = 1.0, y0 = -1.0, y1 = 1.0;
};

// Pixels that a clip draws something important on, in one view (cells of a
// coarse grid; y down from the view's top).
class Occupancy {
 public:
  Occupancy(int width, int height);
  void disc(glm::vec2 centre, float radius);
  void segment(glm::vec2 a, glm::vec2 b, float halfWidth);
  void rect(glm::vec2 lo, glm::vec2 hi);
  [[nodiscard]] bool anyIn(glm::vec2 lo, glm::vec2 hi) const;
  // The marked cells' bounding box in pixels (lo > hi when none).
  [[nodiscard]] std::pair<glm::vec2, glm::vec2> bounds() const;
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }

 private:
  void mark(int cx, int cy);
  int width_, height_, cellsX_, cellsY_;
  float cell_;
  std::vector<unsigned char> cells_;
};

struct TextLine {
  std::string text;
  float sizePx = 16.0f;
  bool bold = false;
  glm::vec4 color{0.0f, 0.0f, 0.0f, 1.0f};
  bool live =
      true;  // its text may change every frame; false: the same over a span of frames (a retained layer keeps it)
  bool continued = false;  // the rest of the line above, broken to fit (they stay or go together)
};

enum class Slot { TopLeft, TopRight, BottomLeft, BottomRight, TopCentre, BottomCentre };

struct TextBlock {
  std::vector<TextLine> lines;
  std::vector<Slot> slots;  // in order of preference
  bool plate = true;        // a translucent backing plate behind the text
  bool centred = false;     // lines centred in the block (a caption)
  glm::vec2 minSize{0.0f};  // the size reserved for it over the whole clip
  std::size_t keep = 1000;  // lines that stay when there is no room for all (from the top)
  int givesWay = 1;         // with no room, the lowest gives up a line first (a tie: the block that found none)
  bool bandOnly = false;    // makes room as a band across the view, never a side column (a portrait frame)
};

// Advance width in pixels of `text` at `sizePx` in the label font.
float textWidthPx(const std::string& text, float sizePx, bool bold);
// Lines of `text` at sizePx at most maxWidth wide, broken at spaces (a
// word wider than maxWidth alone on its line); `balanced`: as many lines
// as the greedy break, each as short as that allows (a caption).
std::vector<std::string> wrapText(const std::string& text, float sizePx, bool bold, float maxWidth, bool balanced);
// Makes the block at most maxWidth wide, padding included: a line too
// wide breaks at spaces onto more lines at its own size; only a line that
// is still too wide (one long word) shrinks, never below minSizePx. A
// running value's line is measured with its digits at their widest, so the
// breaks hold from frame to frame. `keep` counts the broken lines.
void wrapToWidth(TextBlock& block, float maxWidth, float minSizePx = 0.0f);
// The block's size in pixels (padding included).
glm::vec2 blockSize(const TextBlock& block);
// The block's lines as written, a line broken to fit (its continued
// pieces) joined again: what a reader is told is left out.
std::vector<std::string> wholeLines(const TextBlock& block);

struct ViewLayout {
  NdcWindow window;                // the camera frames the subject into this
  std::vector<glm::vec2> origins;  // each block's top-left corner, in view pixels
  std::vector<std::size_t> lines;  // how many of each block's lines there is room for
  std::vector<bool> found;         // whether each block found a free slot (else it lies on its first)
};

// A caption (a centred block) never breaks onto lines narrower than this
// many em: where it would, it goes below the views (SceneDrawer).
inline constexpr float kLeastCaptionEm = 12.0f;

// Places `blocks` in a view w × h. occupancyFor(window) projects the clip
// for a camera framed into that window; with fixedWindow (the scene sets
// the camera itself) the window stays whole and a block with no free slot
// takes its first slot. The window keeps at least minWindow of the view's
// NDC extent (2) on each axis; past that, blocks give up lines instead.
// With a SubjectShare (a figure) the window also keeps the subject at
// least that share of the view's shorter side.
struct SubjectShare {
  double least = 0.0;  // 0: no such rule
  // The subject's bounds in the view's pixels for a camera framed into a
  // window (a figure: its surface as drawn and the ball); none: the
  // occupancy's bounds.
  std::function<std::pair<glm::vec2, glm::vec2>(const NdcWindow&)> boundsFor;
};
ViewLayout layoutView(int w, int h, const std::vector<TextBlock>& blocks,
                      const std::function<Occupancy(const NdcWindow&)>& occupancyFor, bool fixedWindow,
                      double minWindow = 0.6, const SubjectShare& subject = {});

// The largest part of a view w × h clear of `boxes` (pixels, y down; each
// padded by `gap`), as a window: of the rectangles between the view's edges
// and the boxes' padded edges that meet no box, the one with the longest
// shorter side (then the largest). The whole view with no boxes. With a
// subject of width/height `aspect`, the one that shows it largest:
// min(width / aspect, height), then the largest (aspect 1: the longest
// shorter side).
NdcWindow clearWindow(int w, int h, const std::vector<std::pair<glm::vec2, glm::vec2>>& boxes, float gap,
                      float aspect = 1.0f);

// The length in bytes of a running value's leading words, the text up to
// the last space before its first digit ("s = " of "s = 3.78 of 18.85",
// "ψ = " of "ψ = −521.5°": the sign may change); 0 with no digit or no
// space before it.
std::size_t wordsBeforeTheFirstNumber(const std::string& text);

// Draws a placed block into `view` (whose camera must be set: the plate is
// a world-space quad just inside its near plane). A live line is a dynamic
// label whose leading words are static (see LabelItem::staticPrefixBytes).
void addTextBlock(render::DrawList& list, const TextBlock& block, glm::vec2 origin, int view);

// Line step and padding, in em.
inline constexpr float kLineStep = 1.4f;
inline constexpr float kBlockPad = 0.35f;

}  // namespace rollspin::draw
