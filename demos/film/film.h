// What each frame of a video shows: one scene filling the frame, or two to four scenes side by
// side in panes (a comparison), each simulated once, their worlds stepped together and shown at
// the same simulated moments with the same camera (SceneFilm::together). The first scene sets the
// playback, duration and frame rate; its title, clock, legend and captions are the whole frame's;
// each pane carries a label naming what sets it apart (inside it, bottom left where free, in its
// colour), its labels and equation panels stay inside it, and the plots draw every pane's curve
// on one set of axes in the panes' colours.
#pragma once
#include "demos/film/scene_film.h"
#include "render/overlay.h"

#include <Eigen/Core>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace impulse::demos {

// One pane: a scene, and the label naming what sets it apart (e.g. "world.friction = false").
struct Pane {
  const Scene* scene = nullptr;  // must outlive the film
  std::string label;
};

// Where the panes go in a width x height frame, under a band for the title and clock: two side by
// side, each of the frame's aspect; three or four in a grid of two columns that fills the room
// (each pane 1.2 to 2.4 times as wide as high: a camera's field of view is vertical, so a wider
// pane shows more of the scene's width at the same size). Under one row of panes go the plots, in
// a row, and a band left for the captions; with two rows the plots take the column at the right,
// and four panes leave a band for the captions if there are any (three leave the grid's fourth
// cell).
struct PaneLayout {
  int width = 0;                          // of each pane, pixels
  int height = 0;
  std::vector<Eigen::Vector2i> origins;   // each pane's top-left corner in the frame
  float plots_row_top = -1.0f;            // the plots' row (render::Overlay::plots_row_top)
};
PaneLayout pane_layout(int panes, int width, int height, bool plots, bool captions);

render::Colour pane_colour(int pane);  // the label's and the plots' colour of each pane

// A frame as the drawing thread takes it: one draw list per pane, the overlay over the whole frame.
struct FilmPicture {
  std::vector<render::DrawList> panes;
  render::Overlay overlay;
  int frame = -1;               // the video's frame number; -1: a still (Shots)
  double time = 0;              // simulated s shown
  std::vector<BodyPose> poses;  // for a still: the first pane's bodies', in the order of bodies()
};

class Film {
 public:
  // Simulates every scene; the pictures are the video's frames, and stills if asked for.
  Film(const std::vector<Pane>& panes, int width, int height, const Shots& shots = {});

  int frame_count() const { return films_.front()->frame_count(); }  // the video's
  int picture_count() const { return films_.front()->picture_count(); }  // what next() gives
  int next_frame() const { return films_.front()->next_picture(); }  // the next picture's number
  const std::vector<physics::Body>& bodies() const { return films_.front()->bodies(); }  // the first pane's
  double video_time_of(double time) const { return films_.front()->video_time_of(time); }
  // The poster's frame (SceneFilm::poster_frame): the largest labelled impulse of any pane.
  int poster_frame() const;
  std::vector<double> impact_times() const;  // every pane's, in order: s of simulated time
  const PaneLayout& layout() const { return layout_; }
  std::vector<std::vector<CheckResult>> check_results() const;  // each pane's scene's [[check]]s
  // Each pair of panes (numbered from 0) whose worlds moved alike, step for step, so far.
  std::vector<std::pair<int, int>> identical_panes() const;
  void next(FilmPicture& picture);  // the next picture, from 0 up to picture_count() - 1

 private:
  void compose(std::vector<ScenePicture>& pictures, render::Overlay& overlay) const;

  std::vector<Pane> panes_;
  PaneLayout layout_;
  std::vector<std::unique_ptr<SceneFilm>> films_;
  std::vector<ScenePicture> pictures_;  // each pane's, reused frame to frame
};

}  // namespace impulse::demos
