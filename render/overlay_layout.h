// Where each element of a frame's overlay goes (overlay_painter.cpp measures them, then paints
// each where this puts it), as plain geometry: sizes and wished-for places in, boxes out.
//
// Elements are placed one at a time, in the order given: an earlier one gets the better place.
// Each goes inside the frame (and inside its own bounds), never over an element placed before it
// nor within `gap` of one, and over the scene's moving bodies (or across the lines it avoids)
// only when no free place is left, then over as few as can be. The place is its first spot that
// covers nothing, else the free place nearest its first spot: the distance, weighted by `slide`
// (a column element moves down rather than across), plus what it would cover of the panes, of
// still bodies and (a lasting element) of where bodies go over the whole video, each cell so
// covered counting as some cells' width of distance; so an element prefers the space between a
// comparison's panes. A lasting element stays where it was last frame while that is free of
// bodies. An element with no free place at its first size tries its next (smaller, or wrapped
// narrower); one with no place at all, even over bodies, is left out.
//
// Cost: the bodies are summed into coarse grids once per frame (summed-area tables), so a
// candidate place costs a few lookups however many bodies there are; a frame of a dozen elements
// takes tens of microseconds.
#pragma once
#include "render/overlay.h"

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace impulse::render {

bool overlaps(const ScreenBox& a, const ScreenBox& b);       // their insides meet (touching edges do not)
bool contains(const ScreenBox& outer, const ScreenBox& inner);
// Whether the segment from a to b meets the box (Liang-Barsky clipping).
bool segment_meets(const Vec2f& a, const Vec2f& b, const ScreenBox& box);

// A place an element would like: its box's `align` point at `point`. `align` is in fractions of
// the box: (0, 0) its top left, (1, 0) its top right, (0.5, 1) the middle of its bottom.
struct Spot {
  Vec2f point = Vec2f::Zero();
  Vec2f align = Vec2f::Zero();
};

struct LayoutRequest {
  std::vector<Vec2f> sizes;  // (w, h) of each way it can be drawn, the preferred first
  std::vector<Spot> spots;   // where it would go, the preferred first; at least one
  Vec2f slide{1.0f, 1.0f};   // what moving away from the first spot costs per pixel, across and down
  ScreenBox bounds;          // it stays inside this (w = 0: the whole frame)
  std::vector<ScreenSegment> avoid;  // lines it should not cover (arrows), counted as bodies
  // It stays on screen for a while (it follows no anchor): it keeps off where the bodies go over
  // the whole video as well as where they are, so that it need not move when they come.
  bool lasting = true;
  // The same element has the same key from frame to frame (-1: none): a lasting element whose
  // first spot is taken stays where it was while that covers no body, rather than hop about.
  int key = -1;
  // An earlier request it goes under when it can (-1: none), e.g. the second plot of a column under
  // the first wherever that went: its first spot is then just under that element's box.
  int under = -1;
  // Its own pane in the ground's panes (-1: none): covering it costs nothing (a pane's equation
  // panel belongs there), others' cost as any pane does.
  int home = -1;
};

// What the elements go over.
struct LayoutGround {
  int width = 0, height = 0;     // the frame
  float gap = 0;                 // kept clear between two elements
  std::vector<ScreenBox> moving; // moving bodies: covered only when no free place is left
  std::vector<ScreenBox> still;  // still bodies (a ramp, a table): better left uncovered
  std::vector<ScreenBox> panes;  // a comparison's panes: elements prefer the space between them
  std::vector<ScreenBox> paths;  // where moving bodies go over the whole video: lasting elements keep off
};

struct Placement {
  int size = -1;  // which of the request's sizes; -1: no place, not drawn
  ScreenBox box;
  int covered = 0;  // grid cells of moving bodies and lines avoided it covers: 0 when free
};

// Keeps its grids between frames, so laying out a frame allocates nothing once warm, and where
// each keyed element went in the last frame laid out.
class OverlayLayout {
 public:
  // One placement per request, in their order.
  const std::vector<Placement>& place(const LayoutGround& ground, const std::vector<LayoutRequest>& requests);

 private:
  struct Candidate {
    ScreenBox box;
    int hard = 0;       // moving-body cells and avoided lines covered
    float cover = 0;    // cells of panes, still bodies and (lasting elements) paths covered, by weight
    float soft = 0;     // distance from the first spot, plus a cell's width per unit of cover
  };
  void fill_grids(const LayoutGround& ground);
  Placement place_one(const LayoutRequest& request, const std::optional<Spot>& under);
  bool free_of_elements(const ScreenBox& box) const;
  Candidate cost(const LayoutRequest& request, const ScreenBox& box, const ScreenBox& first) const;
  float distance(const LayoutRequest& request, const ScreenBox& box, const ScreenBox& first) const;
  bool search(const LayoutRequest& request, const Vec2f& size, const ScreenBox& bounds, const ScreenBox& first,
              Candidate& best) const;
  std::optional<ScreenBox> last_place(const LayoutRequest& request, int size, const ScreenBox& bounds) const;
  int64_t sum(const std::vector<int32_t>& table, const ScreenBox& box) const;  // cells whose centres are inside

  float cell_ = 8;                // pixels
  int columns_ = 0, rows_ = 0;
  float gap_ = 0;
  int width_ = 0, height_ = 0;
  std::vector<int32_t> cells_;         // a grid's cells, before summing
  std::vector<int32_t> hard_, still_, paths_;  // summed-area tables, (columns + 1) x (rows + 1)
  std::vector<ScreenBox> panes_;
  std::vector<ScreenBox> placed_;
  std::vector<Placement> placements_;
  std::vector<std::pair<int, Placement>> previous_;  // last frame's, by key
  mutable std::vector<float> xs_, ys_;  // search scratch
};

// Places `requests` over `ground` in one call (a fresh OverlayLayout): for tests and tools.
std::vector<Placement> lay_out(const LayoutGround& ground, const std::vector<LayoutRequest>& requests);

}  // namespace impulse::render
