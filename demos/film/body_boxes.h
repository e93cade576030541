// Where each body of a scene is on screen, for the overlay's layout to go round (render::OverlayBody):
// the box its projection covers, from a sphere's centre and radius at its depth, or the eight
// corners of a box, or of the box in a cylinder's or capsule's frame that holds it, or a hull's
// corners. Planes (the ground) are everywhere and have none; a body behind the camera or wholly
// outside the frame has none.
#pragma once
#include "demos/film/scene_draw_list.h"
#include "physics/body.h"
#include "render/camera_view.h"
#include "render/overlay.h"

#include <cstdint>
#include <vector>

namespace impulse::demos {

// Appends the box of each body on screen, in pane 0 (a comparison moves them to their pane).
void add_body_boxes(const std::vector<physics::Body>& bodies, const std::vector<BodyPose>& poses,
                    const render::CameraView& view, std::vector<render::OverlayBody>& out);

// Where moving bodies go on screen over a whole film (render::Overlay::body_paths): each cell of a
// coarse grid (48 cells along the frame's shorter side) that some moving body's box covers in
// some frame, given back as few boxes: a row's runs of cells, each run merged with the same run
// in the rows under it.
class BodyPaths {
 public:
  BodyPaths(int width, int height);
  void add(const render::ScreenBox& box);
  std::vector<render::ScreenBox> boxes() const;

 private:
  float cell_;
  int columns_, rows_;
  std::vector<uint8_t> covered_;  // columns_ x rows_
};

}  // namespace impulse::demos
