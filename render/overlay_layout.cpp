#include "render/overlay_layout.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace impulse::render {
namespace {

constexpr float kSlop = 1e-3f;          // pixels: boxes that only touch, up to rounding, do not overlap
constexpr float kPaneWeight = 8;        // a pane's cell covered costs this many cells' widths of moving
constexpr float kPathWeight = 2;        // a cell some body passes through
constexpr float kStillWeight = 2;       // a still body's cell
constexpr int kSegmentWeight = 8;       // an avoided line crossed counts as this many body cells
constexpr int kCellsAcross = 48;        // the grid has this many cells along the frame's shorter side
constexpr int kStepsAcross = 16;        // the search tries places this far apart (and at elements' edges)

ScreenBox box_at(const Spot& spot, const Vec2f& size) {
  return {spot.point.x() - spot.align.x() * size.x(), spot.point.y() - spot.align.y() * size.y(), size.x(), size.y()};
}

// Moved the least to lie inside `bounds` (the box fits: the caller checked).
ScreenBox clamped(ScreenBox box, const ScreenBox& bounds) {
  box.x = std::clamp(box.x, bounds.x, bounds.right() - box.w);
  box.y = std::clamp(box.y, bounds.y, bounds.bottom() - box.h);
  return box;
}

ScreenBox intersection(const ScreenBox& a, const ScreenBox& b) {
  const float x = std::max(a.x, b.x), y = std::max(a.y, b.y);
  return {x, y, std::max(0.0f, std::min(a.right(), b.right()) - x), std::max(0.0f, std::min(a.bottom(), b.bottom()) - y)};
}

// The cell index of `value` pixels, rounded down (or up), within 0 .. limit (0 for not a number).
int cell_index(float value, float cell, int limit, bool up) {
  const float index = up ? std::ceil(value / cell) : std::floor(value / cell);
  return index >= 0 ? int(std::min(index, float(limit))) : 0;
}

// Adds `weight` to every cell `box` touches, in a columns x rows grid of `cell`-pixel cells.
void mark(std::vector<int32_t>& cells, int columns, int rows, float cell, const ScreenBox& box, int32_t weight) {
  const int i0 = cell_index(box.x, cell, columns, false), i1 = cell_index(box.right(), cell, columns, true);
  const int j0 = cell_index(box.y, cell, rows, false), j1 = cell_index(box.bottom(), cell, rows, true);
  for (int j = j0; j < j1; ++j)
    for (int i = i0; i < i1; ++i) cells[size_t(j) * columns + i] += weight;
}

// The summed-area table of `cells`: entry (i, j) of (columns + 1) x (rows + 1) sums cells [0, i) x [0, j).
void integrate(const std::vector<int32_t>& cells, int columns, int rows, std::vector<int32_t>& table) {
  table.assign(size_t(columns + 1) * (rows + 1), 0);
  for (int j = 0; j < rows; ++j) {
    int32_t row = 0;
    for (int i = 0; i < columns; ++i) {
      row += cells[size_t(j) * columns + i];
      table[size_t(j + 1) * (columns + 1) + i + 1] = table[size_t(j) * (columns + 1) + i + 1] + row;
    }
  }
}

void add_in(std::vector<float>& values, float value, float low, float high) {
  if (value >= low - kSlop && value <= high + kSlop) values.push_back(std::clamp(value, low, high));
}

}  // namespace

bool overlaps(const ScreenBox& a, const ScreenBox& b) {
  return a.x < b.right() - kSlop && b.x < a.right() - kSlop && a.y < b.bottom() - kSlop && b.y < a.bottom() - kSlop;
}

bool contains(const ScreenBox& outer, const ScreenBox& inner) {
  return inner.x >= outer.x - kSlop && inner.y >= outer.y - kSlop && inner.right() <= outer.right() + kSlop &&
         inner.bottom() <= outer.bottom() + kSlop;
}

bool segment_meets(const Vec2f& a, const Vec2f& b, const ScreenBox& box) {
  double enter = 0, leave = 1;
  const double d[2] = {double(b.x() - a.x()), double(b.y() - a.y())};
  const double p[4] = {-d[0], d[0], -d[1], d[1]};
  const double q[4] = {a.x() - box.x, box.right() - a.x(), a.y() - box.y, box.bottom() - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) enter = std::max(enter, t);
    else leave = std::min(leave, t);
    if (enter > leave) return false;
  }
  return true;
}

void OverlayLayout::fill_grids(const LayoutGround& ground) {
  width_ = ground.width;
  height_ = ground.height;
  gap_ = ground.gap;
  cell_ = std::max(2.0f, float(std::min(width_, height_)) / kCellsAcross);
  columns_ = std::max(1, int(std::ceil(width_ / cell_)));
  rows_ = std::max(1, int(std::ceil(height_ / cell_)));
  std::vector<int32_t>& cells = cells_;
  cells.assign(size_t(columns_) * rows_, 0);
  for (const ScreenBox& body : ground.moving) mark(cells, columns_, rows_, cell_, body, 1);
  integrate(cells, columns_, rows_, hard_);
  cells.assign(size_t(columns_) * rows_, 0);
  for (const ScreenBox& body : ground.still) mark(cells, columns_, rows_, cell_, body, 1);
  integrate(cells, columns_, rows_, still_);
  cells.assign(size_t(columns_) * rows_, 0);
  for (const ScreenBox& path : ground.paths) mark(cells, columns_, rows_, cell_, path, 1);
  integrate(cells, columns_, rows_, paths_);
  panes_ = ground.panes;
}

int64_t OverlayLayout::sum(const std::vector<int32_t>& table, const ScreenBox& box) const {
  const int i0 = std::max(0, int(std::ceil(box.x / cell_ - 0.5f)));
  const int i1 = std::min(columns_, int(std::floor(box.right() / cell_ - 0.5f)) + 1);
  const int j0 = std::max(0, int(std::ceil(box.y / cell_ - 0.5f)));
  const int j1 = std::min(rows_, int(std::floor(box.bottom() / cell_ - 0.5f)) + 1);
  if (i1 <= i0 || j1 <= j0) return 0;
  const size_t stride = size_t(columns_) + 1;
  return int64_t(table[j1 * stride + i1]) - table[j0 * stride + i1] - table[j1 * stride + i0] + table[j0 * stride + i0];
}

bool OverlayLayout::free_of_elements(const ScreenBox& box) const {
  for (const ScreenBox& element : placed_) {
    const ScreenBox kept{element.x - gap_, element.y - gap_, element.w + 2 * gap_, element.h + 2 * gap_};
    if (overlaps(box, kept)) return false;
  }
  return true;
}

OverlayLayout::Candidate OverlayLayout::cost(const LayoutRequest& request, const ScreenBox& box, const ScreenBox& first) const {
  Candidate candidate{box, int(sum(hard_, box)), kStillWeight * float(sum(still_, box)), 0.0f};
  if (request.lasting) candidate.cover += kPathWeight * float(sum(paths_, box));
  for (const ScreenSegment& line : request.avoid)
    if (segment_meets(line.from, line.to, box)) candidate.hard += kSegmentWeight;
  // The panes' area exactly, not by cells: inside a pane every place covers the same.
  for (size_t i = 0; i < panes_.size(); ++i) {
    if (int(i) == request.home) continue;
    const ScreenBox common = intersection(panes_[i], box);
    candidate.cover += kPaneWeight * common.w * common.h / (cell_ * cell_);
  }
  candidate.soft = distance(request, box, first) + cell_ * candidate.cover;
  return candidate;
}

float OverlayLayout::distance(const LayoutRequest& request, const ScreenBox& box, const ScreenBox& first) const {
  return request.slide.x() * std::abs(box.x - first.x) + request.slide.y() * std::abs(box.y - first.y);
}

// Every place on a lattice round the first spot, at the frame's and bounds' edges, and beside
// each element placed (where free space begins): the best free of elements, if any.
bool OverlayLayout::search(const LayoutRequest& request, const Vec2f& size, const ScreenBox& bounds, const ScreenBox& first,
                           Candidate& best) const {
  const float low_x = bounds.x, high_x = bounds.right() - size.x(), low_y = bounds.y, high_y = bounds.bottom() - size.y();
  const float step = std::max(2 * cell_, float(std::min(width_, height_)) / kStepsAcross);
  xs_.clear();
  ys_.clear();
  for (float x = first.x; x >= low_x - kSlop; x -= step) add_in(xs_, x, low_x, high_x);
  for (float x = first.x + step; x <= high_x + kSlop; x += step) add_in(xs_, x, low_x, high_x);
  for (float y = first.y; y >= low_y - kSlop; y -= step) add_in(ys_, y, low_y, high_y);
  for (float y = first.y + step; y <= high_y + kSlop; y += step) add_in(ys_, y, low_y, high_y);
  add_in(xs_, low_x, low_x, high_x);
  add_in(xs_, high_x, low_x, high_x);
  add_in(ys_, low_y, low_y, high_y);
  add_in(ys_, high_y, low_y, high_y);
  for (const ScreenBox& element : placed_) {
    add_in(xs_, element.right() + gap_, low_x, high_x);
    add_in(xs_, element.x - gap_ - size.x(), low_x, high_x);
    add_in(ys_, element.bottom() + gap_, low_y, high_y);
    add_in(ys_, element.y - gap_ - size.y(), low_y, high_y);
  }
  bool found = false;
  for (const float y : ys_) {
    for (const float x : xs_) {
      const ScreenBox box{x, y, size.x(), size.y()};
      // The distance is the least a place can cost: past the best free place's cost, no need to look.
      if (found && best.hard == 0 && distance(request, box, first) >= best.soft) continue;
      const Candidate candidate = cost(request, box, first);
      if (found && (candidate.hard > best.hard || (candidate.hard == best.hard && candidate.soft >= best.soft))) continue;
      if (!free_of_elements(box)) continue;
      best = candidate;
      found = true;
    }
  }
  return found;
}

// Where the element was last frame, at this size: its box moved to keep the point of it its first
// spot aligns (a clock's right edge stays where it was as its text changes width).
std::optional<ScreenBox> OverlayLayout::last_place(const LayoutRequest& request, int size, const ScreenBox& bounds) const {
  if (!request.lasting || request.key < 0) return std::nullopt;
  const auto last = std::find_if(previous_.begin(), previous_.end(), [&](const auto& p) { return p.first == request.key; });
  if (last == previous_.end() || last->second.size != size) return std::nullopt;
  const ScreenBox& was = last->second.box;
  const Vec2f& align = request.spots.front().align;
  const Vec2f& now = request.sizes[size];
  const Spot kept{Vec2f(was.x + align.x() * was.w, was.y + align.y() * was.h), align};
  const ScreenBox box = box_at(kept, now);
  if (!contains(bounds, box) || !free_of_elements(box)) return std::nullopt;
  return box;
}

// At the first size with a place free of bodies: where it was last frame, if that still covers
// nothing (no body, pane, path or line: text being read does not move); else the first of its
// spots that covers nothing; else where it was, if that covers no body; else the cheapest of its
// spots and the search's places. With no such size, the size and place covering fewest bodies
// (the earlier size on a tie), where it was or at its best spot unless moving halves what it
// covers: an element with no free place does not hop from frame to frame.
Placement OverlayLayout::place_one(const LayoutRequest& request, const std::optional<Spot>& under) {
  const ScreenBox frame{0, 0, float(width_), float(height_)};
  const ScreenBox bounds = request.bounds.w > 0 ? intersection(request.bounds, frame) : frame;
  Placement best;
  for (size_t s = 0; s < request.sizes.size() && !request.spots.empty(); ++s) {
    const Vec2f& size = request.sizes[s];
    if (!(size.x() >= 0 && size.y() >= 0) || size.x() > bounds.w + kSlop || size.y() > bounds.h + kSlop) continue;
    const ScreenBox first = clamped(box_at(under ? *under : request.spots.front(), size), bounds);
    const auto cheaper = [](const std::optional<Candidate>& a, const std::optional<Candidate>& b) {
      if (!a || !b) return a ? a : b;
      return a->hard < b->hard || (a->hard == b->hard && a->soft <= b->soft) ? a : b;
    };
    const std::optional<ScreenBox> last = last_place(request, int(s), bounds);
    const std::optional<Candidate> kept = last ? std::optional(cost(request, *last, first)) : std::nullopt;
    if (kept && kept->hard == 0 && kept->cover < kSlop) return {int(s), kept->box, 0};
    std::optional<Candidate> spotted;  // the cheapest spot
    for (int k = under ? -1 : 0; k < int(request.spots.size()); ++k) {
      const ScreenBox box = clamped(box_at(k < 0 ? *under : request.spots[k], size), bounds);
      if (!free_of_elements(box)) continue;
      const Candidate candidate = cost(request, box, first);
      if (candidate.hard == 0 && candidate.cover < kSlop) return {int(s), box, 0};
      spotted = cheaper(spotted, candidate);
    }
    if (kept && kept->hard == 0) return {int(s), kept->box, 0};
    std::optional<Candidate> searched;
    if (Candidate found; search(request, size, bounds, first, found)) searched = found;
    const std::optional<Candidate> cheapest = cheaper(spotted, searched);
    if (cheapest && cheapest->hard == 0) return {int(s), cheapest->box, 0};
    // Over bodies wherever it goes: it stays where it was (or at its best spot) unless moving
    // halves what it covers.
    std::optional<Candidate> chosen = kept ? kept : spotted;
    if (!chosen || (cheapest && 2 * cheapest->hard < chosen->hard)) chosen = cheapest;
    if (chosen && (best.size < 0 || chosen->hard < best.covered)) best = {int(s), chosen->box, chosen->hard};
  }
  return best;
}

const std::vector<Placement>& OverlayLayout::place(const LayoutGround& ground, const std::vector<LayoutRequest>& requests) {
  fill_grids(ground);
  placed_.clear();
  placements_.clear();
  for (const LayoutRequest& request : requests) {
    std::optional<Spot> under;
    if (request.under >= 0 && request.under < int(placements_.size()) && placements_[request.under].size >= 0 &&
        !request.spots.empty()) {
      const ScreenBox& above = placements_[request.under].box;
      const float align = request.spots.front().align.x();
      under = Spot{Vec2f(above.x + align * above.w, above.bottom() + gap_), Vec2f(align, 0)};
    }
    const Placement placement = place_one(request, under);
    placements_.push_back(placement);
    if (placement.size >= 0) placed_.push_back(placement.box);
  }
  previous_.clear();
  for (size_t i = 0; i < requests.size(); ++i)
    if (requests[i].key >= 0 && placements_[i].size >= 0) previous_.emplace_back(requests[i].key, placements_[i]);
  return placements_;
}

std::vector<Placement> lay_out(const LayoutGround& ground, const std::vector<LayoutRequest>& requests) {
  OverlayLayout layout;
  return layout.place(ground, requests);
}

}  // namespace impulse::render
