// The teaching marks drawn over the bodies, one convention for every demo (demos/README.md, "What
// a frame shows"): their colours, and the scales that turn impulses and velocities into arrow lengths.
#pragma once
#include "demos/scene/scene.h"
#include "demos/film/take_summary.h"
#include "render/camera_view.h"
#include "render/overlay.h"
#include "render/palette.h"

#include <cmath>
#include <vector>

namespace impulse::demos {

namespace mark_colour {
inline constexpr render::Colour contact_point{0.00f, 0.00f, 0.00f};  // black dot
inline constexpr render::Colour contact_normal = render::okabe_ito::vermillion;
inline constexpr render::Colour normal_impulse = render::okabe_ito::blue;
inline constexpr render::Colour friction_impulse = render::okabe_ito::reddish_purple;
inline constexpr render::Colour velocity{0.20f, 0.20f, 0.20f};          // near black
inline constexpr render::Colour joint{0.45f, 0.45f, 0.47f};             // grey: rods, ropes, pivots
inline constexpr render::Colour asleep_swatch = render::okabe_ito::blue;  // the legend's sleeping body
}  // namespace mark_colour

struct ArrowScales {
  double impulse = 1.0;        // m of arrow per N s
  double longest_impulse = INFINITY;  // m: longer impulse arrows are cut to this, their value written
  double velocity = 1.0;       // m of arrow per m/s
  double normal_length = 0.6;  // m
};

// A body's size for its marks, m: a sphere's or capsule's radius, a box's smallest half-size, the
// smaller of a cylinder's radius and half height; a plane has none (infinity).
double body_size(const physics::Shape& shape);

// The scene's scales, or (for 0) a round number (1, 2 or 5 times a power of ten) that draws the
// largest value of the run (for impulses, summary.impulse_to_fit) about 1.5 m long; normals (for
// 0) 1.5 times the smallest moving body's radius or half-size. With an automatic impulse scale,
// impulse arrows longer than 1.5 times the fitted one are cut to that length.
ArrowScales arrow_scales(const Scene& scene, const TakeSummary& summary);

struct ImpulsePeak {
  double time = 0;     // s
  double impulse = 0;  // N s: the step's largest, normal or friction, on a moving body
  bool impact = true;  // more than a load can be (kLoadShare of every moving body's weight over a step)
};
constexpr double kLoadShare = 1.5;

// The impulse the automatic scale fits, from the impacts (the loads of resting contacts only when
// nothing hits: a scene is drawn to show its hits, and a load fitted before a hit draws the waiting
// bodies' arrows long and the hit's far too long): the largest impact, unless the impacts within
// 0.25 s of it outweigh every other moment's impacts more than 4 times. Then the largest of those,
// so that one hard hit does not shrink the other hits' arrows to nothing; its arrow is cut
// (ArrowScales::longest_impulse) and its value written beside it.
double impulse_to_fit(const std::vector<ImpulsePeak>& peaks);

// The contacts whose normals and impulse arrows a frame draws (and whose impulse its label may
// write). With at most `max_pairs` pairs of bodies in contact (or `max_pairs` 0), `contacts` as
// they are. Else the `max_pairs` pairs with the largest total normal impulse, each as one record:
// its points' total impulses at their impulse-weighted centre (their mean without impulse), along
// their mean normal; in the contacts' order.
std::vector<physics::ContactRecord> marked_contacts(const std::vector<physics::ContactRecord>& contacts, int max_pairs);

// `arrow` no longer than `longest`.
render::Vec3f cut_to(const render::Vec3f& arrow, double longest);

// The legend for the marks the scene draws. Arrow entries show how long a round value (1 N s,
// 0.5 m/s, ...) is on screen at the camera's target. With `someone_sleeps` (a moving body falls
// asleep in the film) and sleeping bodies drawn as such, a swatch says what pale and hatched means.
std::vector<render::LegendEntry> legend(const DrawOptions& draw, const ArrowScales& scales, const render::CameraView& camera,
                                        const render::Vec3f& target, bool someone_sleeps);

}  // namespace impulse::demos
