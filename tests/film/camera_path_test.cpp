// [camera] fit (camera_path.h): the camera aimed and moved back along its line of sight until every
// moving body's whole path is in view; a ball thrown far past the scene's own camera stays in the
// frame at every frame, and leaves it without fit.
#include "demos/film/film.h"
#include "render/camera_view.h"
#include "tests/support/scene_scratch.h"

#include <gtest/gtest.h>

#include <string>

namespace impulse {
namespace {

std::string throw_scene(bool fit) {
  return std::string(R"(
[scene]
duration = 2.0
[video]
width = 320
height = 180
fps = 20
[camera]
position = [0, 2, 6]
target = [0, 1, 0]
)") + (fit ? "fit = true\n" : "") + R"(
[[body]]
shape = "plane"
[[body]]
name = "ball"
shape = "sphere"
radius = 0.2
position = [-6, 0.2, 0]
velocity = [6, 9, 0]
)";
}

// The share of frames in which the whole ball (its centre and radius on screen) is in the frame.
double frames_with_the_ball_in_view(const demos::Scene& scene) {
  demos::Film film({{&scene, ""}}, 320, 180);
  demos::FilmPicture picture;
  int inside = 0, frames = 0;
  while (film.next_frame() < film.frame_count()) {
    film.next(picture);
    const render::CameraView view = render::make_camera_view(picture.panes[0].camera, 320, 180);
    if (picture.panes[0].spheres.size() != 1) {
      ADD_FAILURE() << "one ball drawn, not " << picture.panes[0].spheres.size();
      return 0;
    }
    const render::Vec3f centre = picture.panes[0].spheres[0].centre;
    const auto pixel = view.to_pixels(centre);
    const float radius = picture.panes[0].spheres[0].radius * view.pixels_per_metre(centre);
    ++frames;
    inside += pixel && pixel->x() - radius >= 0 && pixel->x() + radius <= 320 && pixel->y() - radius >= 0 && pixel->y() + radius <= 180;
  }
  return double(inside) / frames;
}

TEST(CameraFit, KeepsAThrownBallInViewWhereTheScenesCameraLosesIt) {
  const auto dir = testing::scratch("film_camera_fit_test", "throw");
  EXPECT_LT(frames_with_the_ball_in_view(testing::scene_from(dir, throw_scene(false))), 0.8) << "the scene's own camera loses it";
  EXPECT_EQ(frames_with_the_ball_in_view(testing::scene_from(dir, throw_scene(true))), 1.0);
}

}  // namespace
}  // namespace impulse
