#include "demos/film/film.h"

#include "render/palette.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impulse::demos {

PaneLayout pane_layout(int panes, int width, int height, bool plots, bool captions) {
  PaneLayout layout;
  if (panes <= 1) {
    layout.width = width;
    layout.height = height;
    layout.origins = {Eigen::Vector2i::Zero()};
    return layout;
  }
  // Sizes as the overlay painter's (render/overlay_painter.cpp), which scale with the height.
  const double scale = height / 720.0;
  const int columns = 2, rows = (panes + 1) / 2;
  const bool plots_row = plots && rows == 1;
  const double gap = 8 * scale, top = 72 * scale;                  // under the title and the clock
  const double plots_band = plots_row ? 108 * scale : 0;           // a plot and its gaps
  const double plots_column = plots && !plots_row ? 300 * scale : 0;
  // Three panes leave a cell of the grid for the captions; two (a row) and four, a band under them.
  const double captions_band = rows == 1 || (captions && panes == 4) ? 100 * scale : 0;  // two lines of caption
  const double room_width = width - plots_column - (columns + 1) * gap;
  const double room_height = height - top - plots_band - captions_band - rows * gap;
  if (rows == 1) {  // of the frame's shape
    const double pane_width = std::min(room_width / columns, room_height / rows * width / height);
    layout.width = int(pane_width) / 2 * 2;
    layout.height = int(pane_width * height / width) / 2 * 2;
  } else {  // a grid fills the room, each pane between kNarrowest and kWidest wide to 1 high
    constexpr double kNarrowest = 1.2, kWidest = 2.4;
    const double cell_width = room_width / columns, cell_height = room_height / rows;
    layout.width = int(std::min(cell_width, kWidest * cell_height)) / 2 * 2;
    layout.height = int(std::min(cell_height, cell_width / kNarrowest)) / 2 * 2;
  }

  const double block_width = columns * layout.width + (columns - 1) * gap;
  const double block_height = rows * layout.height + (rows - 1) * gap + plots_band;
  const double left = (width - plots_column - block_width) / 2;
  const double upper = top + std::max(0.0, (height - top - captions_band - block_height) / 2);
  for (int pane = 0; pane < panes; ++pane) {
    const int column = pane % columns, row = pane / columns;
    layout.origins.emplace_back(int(std::lround(left + column * (layout.width + gap))),
                                int(std::lround(upper + row * (layout.height + gap))));
  }
  if (plots_row) layout.plots_row_top = float(upper + layout.height + gap);
  return layout;
}

render::Colour pane_colour(int pane) {
  namespace oi = render::okabe_ito;
  const render::Colour colours[] = {oi::blue, oi::vermillion, oi::bluish_green, oi::reddish_purple};
  return colours[pane % 4];
}

Film::Film(const std::vector<Pane>& panes, int width, int height, const Shots& shots) : panes_(panes) {
  if (panes.empty() || panes.size() > 4) throw std::invalid_argument("a video shows one to four scenes");
  const Scene& first = *panes.front().scene;
  layout_ = pane_layout(int(panes.size()), width, height, !first.overlay.plots.empty(), !first.captions.empty());
  std::vector<const Scene*> scenes;
  for (const Pane& pane : panes) scenes.push_back(pane.scene);
  films_ = SceneFilm::together(scenes, layout_.width, layout_.height, shots);
  pictures_.resize(panes.size());
}

std::vector<std::pair<int, int>> Film::identical_panes() const {
  std::vector<std::pair<int, int>> pairs;
  for (size_t p = 0; p < films_.size(); ++p)
    for (size_t q = p + 1; q < films_.size(); ++q)
      if (films_[p]->motion_hash() == films_[q]->motion_hash()) pairs.emplace_back(int(p), int(q));
  return pairs;
}

std::vector<std::vector<CheckResult>> Film::check_results() const {
  std::vector<std::vector<CheckResult>> results;
  for (const auto& film : films_) results.push_back(film->check_results());
  return results;
}

int Film::poster_frame() const {
  SceneFilm::LabelledPeak peak;
  for (const auto& film : films_)
    if (film->labelled_peak().impulse > peak.impulse) peak = film->labelled_peak();
  return films_.front()->poster_frame(peak);
}

std::vector<double> Film::impact_times() const {
  std::vector<double> times;
  for (const auto& film : films_) times.insert(times.end(), film->impact_times().begin(), film->impact_times().end());
  std::sort(times.begin(), times.end());
  return times;
}

void Film::next(FilmPicture& picture) {
  picture.panes.resize(films_.size());
  for (size_t i = 0; i < films_.size(); ++i) {
    films_[i]->next(pictures_[i]);
    picture.panes[i] = std::move(pictures_[i].draw_list);
  }
  picture.frame = pictures_.front().frame;
  picture.time = pictures_.front().time;
  picture.poses = std::move(pictures_.front().poses);
  if (films_.size() == 1) {
    picture.overlay = std::move(pictures_.front().overlay);
  } else {
    compose(pictures_, picture.overlay);
  }
}

namespace {

bool same_panel(const render::OverlayPanel& a, const render::OverlayPanel& b) {
  return a.place == b.place && a.place != render::PanelPlace::at_corner && a.lines == b.lines && a.math.key == b.math.key &&
         a.opacity == b.opacity;
}

// A panel that every one of `panes` shows alike (the same words and mathematics: not an impact's
// numbers, which differ) is shown once, for the frame, so that the panes keep their room for the
// bodies.
std::vector<render::OverlayPanel> shared_panels(std::vector<render::OverlayPanel> panels, int panes) {
  std::vector<render::OverlayPanel> kept;
  std::vector<bool> taken(panels.size(), false);
  for (size_t i = 0; i < panels.size(); ++i) {
    if (taken[i]) continue;
    std::vector<size_t> alike = {i};
    for (size_t j = i + 1; j < panels.size(); ++j)
      if (!taken[j] && panels[j].pane != panels[i].pane && same_panel(panels[i], panels[j]) &&
          std::none_of(alike.begin(), alike.end(), [&](size_t k) { return panels[k].pane == panels[j].pane; }))
        alike.push_back(j);
    if (int(alike.size()) == panes) {
      for (const size_t k : alike) taken[k] = true;
      kept.push_back(std::move(panels[i]));
      kept.back().pane = -1;
    } else {
      taken[i] = true;
      kept.push_back(std::move(panels[i]));
    }
  }
  return kept;
}

}  // namespace

// The first pane's overlay for the whole frame (its captions under the panes); every pane's
// labels, panels, bodies and own captions moved to where the pane is and kept inside it, its name
// in it, and each plot's curves of every pane on the first pane's axes.
void Film::compose(std::vector<ScenePicture>& pictures, render::Overlay& overlay) const {
  std::vector<render::OverlayLabel> labels;
  std::vector<render::Plot> plots;
  std::vector<render::OverlayPanel> panels;
  std::vector<render::OverlayPane> panes;
  std::vector<render::OverlayBody> bodies;
  std::vector<render::ScreenBox> paths;
  std::vector<render::Caption> captions;  // the first pane's for the frame, then every pane's own
  for (const render::Caption& caption : pictures.front().overlay.captions)
    if (caption.pane < 0) captions.push_back(caption);
  for (size_t i = 0; i < pictures.size(); ++i) {
    render::Overlay& pane = pictures[i].overlay;
    const render::Vec2f origin = layout_.origins[i].cast<float>();
    for (render::Caption caption : pane.captions)
      if (caption.pane >= 0) {
        caption.pane = int(i);
        captions.push_back(std::move(caption));
      }
    for (render::OverlayLabel label : pane.labels) {
      label.anchor += origin;
      for (render::ScreenSegment& segment : label.avoid) {
        segment.from += origin;
        segment.to += origin;
      }
      label.pane = int(i);
      labels.push_back(std::move(label));
    }
    for (render::OverlayPanel panel : pane.panels) {
      if (panel.place == render::PanelPlace::at_corner) panel.corner += origin;
      panel.pane = int(i);
      panels.push_back(std::move(panel));
    }
    for (render::OverlayBody& body : pane.bodies) {
      body.pane = int(i);
      body.box.x += origin.x();
      body.box.y += origin.y();
      bodies.push_back(std::move(body));
    }
    for (render::ScreenBox path : pane.body_paths) {
      path.x += origin.x();
      path.y += origin.y();
      paths.push_back(path);
    }
    panes.push_back({{origin.x(), origin.y(), float(layout_.width), float(layout_.height)}, panes_[i].label, pane_colour(int(i))});
    for (size_t k = 0; k < pane.plots.size(); ++k) {
      if (k == plots.size()) plots.push_back({pane.plots[k].title, pane.plots[k].unit, pane.plots[k].x_end, pane.plots[k].x_start, 0, 0, {}});
      render::Plot& plot = plots[k];
      plot.y_min = std::min(plot.y_min, pane.plots[k].y_min);
      plot.y_max = std::max(plot.y_max, pane.plots[k].y_max);
      for (render::PlotSeries series : pane.plots[k].series) {
        series.colour = pane_colour(int(i));
        plot.series.push_back(std::move(series));
      }
    }
  }
  overlay = std::move(pictures.front().overlay);
  overlay.captions = std::move(captions);
  overlay.labels = std::move(labels);
  overlay.panels = shared_panels(std::move(panels), int(pictures.size()));
  overlay.plots = std::move(plots);
  overlay.plots_row_top = layout_.plots_row_top;
  overlay.panes = std::move(panes);
  overlay.bodies = std::move(bodies);
  overlay.body_paths = std::move(paths);
  if (panes_.size() == 3) {  // the captions in the grid's empty cell, clear of the panes
    overlay.captions_left = float(layout_.origins[1].x());
    overlay.captions_right = float(layout_.origins[1].x() + layout_.width);
  }
}

}  // namespace impulse::demos
