#include "demos/film/frame_overlay.h"

#include "demos/film/body_boxes.h"
#include "demos/film/render_types.h"
#include "demos/film/captions.h"
#include "demos/film/impulse_label.h"
#include "render/flat_arrows.h"

#include <cmath>
#include <cstdio>

namespace impulse::demos {
namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string playback_text(double speed, bool slow_motion, double base_speed) {
  if (slow_motion) return "slow motion \u00d7" + format("%.2f", speed);
  if (std::abs(speed - 1.0) < 1e-6 && std::abs(base_speed - 1.0) < 1e-6) return "real time";
  return "playback \u00d7" + format("%.2f", speed);
}

}  // namespace

FrameOverlay::FrameOverlay(const Scene& scene, TakeSummary summary, const ArrowScales& scales, int width,
                           int height)
    : scene_(scene), summary_(std::move(summary)), scales_(scales), width_(width), height_(height),
      label_body_(label_body(scene)), equations_(scene, film_typesetter()) {}

void FrameOverlay::add_label(const FrameState& state, const render::CameraView& view, render::Overlay& overlay) const {
  const std::string& kind = scene_.overlay.label;
  const auto& bodies = *state.bodies;
  render::Vec3f tip = render::Vec3f::Zero();
  std::string text;
  render::Colour colour;
  if (kind == "impulse") {
    const std::vector<physics::ContactRecord> marked = marked_contacts(*state.contacts, scene_.draw.marked_pairs);
    const LabelledImpulse labelled = labelled_impulse(marked, bodies, label_body_);
    const double largest = labelled.contact != nullptr ? labelled.contact->normal_impulse : 0.0;
    // A touching contact that pushes nothing (0.00 N s) is not worth a label.
    if (!(largest >= 0.005 && largest > 1e-3 * summary_.largest_impulse)) return;
    tip = labelled.contact->point.cast<float>() +
          cut_to(impulse_on(*labelled.contact, labelled.body) * float(scales_.impulse), scales_.longest_impulse);
    text = "J = " + render::three_figures(largest) + " N\u00b7s";
    colour = mark_colour::normal_impulse;
  } else if (kind == "velocity") {
    double fastest = -1;
    for (size_t i = 0; i < bodies.size(); ++i) {
      const bool chosen = !bodies[i].is_static() && (label_body_ < 0 || int(i) == label_body_);
    if (!chosen || !(bodies[i].velocity.norm() > fastest)) continue;
      fastest = bodies[i].velocity.norm();
      tip = ((*state.poses)[i].position + bodies[i].velocity * scales_.velocity).cast<float>();
    }
    if (fastest < 0) return;
    text = "v = " + render::three_figures(fastest) + " m/s";
    colour = mark_colour::velocity;
  } else if (scene_.draw.impulses) {
    // No label asked for, but a cut arrow's length no longer tells its value: write it.
    const std::vector<physics::ContactRecord> marked = marked_contacts(*state.contacts, scene_.draw.marked_pairs);
    const LabelledImpulse labelled = labelled_impulse(marked, bodies, -1);
    if (labelled.contact == nullptr || !(labelled.contact->normal_impulse * scales_.impulse > scales_.longest_impulse)) return;
    tip = labelled.contact->point.cast<float>() +
          cut_to(impulse_on(*labelled.contact, labelled.body) * float(scales_.impulse), scales_.longest_impulse);
    text = "J = " + render::three_figures(labelled.contact->normal_impulse) + " N\u00b7s";
    colour = mark_colour::normal_impulse;
  } else {
    return;
  }
  const auto pixels = view.to_pixels(tip);
  if (!pixels) return;
  render::OverlayLabel& label = overlay.labels.emplace_back(render::OverlayLabel{*pixels, text, colour, {}});
  if (state.arrows == nullptr) return;
  for (const render::ArrowItem& arrow : *state.arrows) render::append_flat_arrow_outline(arrow, view, label.avoid);
}

void FrameOverlay::make(const FrameState& state, const PlotRecorder& plots, render::Overlay& overlay) const {
  const OverlayOptions& options = scene_.overlay;
  const render::CameraView view = render::make_camera_view(state.camera, width_, height_);
  overlay.title = options.title ? scene_.title : "";
  overlay.captions = captions_at(scene_.captions, state.time);
  overlay.labels.clear();
  add_label(state, view, overlay);
  overlay.panels.clear();
  equations_.add_panels(state.time, state.impact != nullptr ? *state.impact : ImpactNumbers{}, overlay);
  overlay.clock = options.clock ? format("t = %.2f s", state.time) : "";
  overlay.playback = options.clock ? playback_text(state.speed, state.slow_motion, scene_.playback.speed) : "";
  overlay.playback_highlight = state.slow_motion;
  overlay.legend = options.legend ? legend(scene_.draw, scales_, view, state.camera.target, summary_.someone_sleeps) : std::vector<render::LegendEntry>{};
  if (!options.plots.empty()) {
    std::vector<PlotCurve> curves;
    for (const int body : plotted_bodies(*state.bodies, options.plot_bodies))
      curves.push_back({(*state.bodies)[size_t(body)].name,
                        size_t(body) < scene_.colours.size() ? to_render(scene_.colours[size_t(body)]) : render::Colour{}});
    overlay.plots = plots.plots(state.plotted_steps, scene_.duration, summary_.plot_maxima, curves);
  } else {
    overlay.plots.clear();
  }
  overlay.bodies.clear();
  add_body_boxes(*state.bodies, *state.poses, view, overlay.bodies);
  overlay.body_paths = body_paths_;
}

}  // namespace impulse::demos
