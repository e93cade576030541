#include "demos/page/page_export.h"

#include "demos/film/camera_path.h"
#include "demos/film/film.h"
#include "demos/film/live_equations.h"
#include "demos/film/marks.h"
#include "demos/film/playback_timeline.h"
#include "demos/film/plot_recorder.h"
#include "demos/film/render_types.h"
#include "demos/film/scene_draw_list.h"
#include "demos/film/world_take.h"
#include "render/camera_view.h"

#include <glib.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace impulse::demos {

namespace {

// Numbers as JSON: enough digits for 1e-6 m at lecture sizes, shortest form.
void number(std::ostream& out, double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.7g", std::isfinite(value) ? value : 0.0);
  out << text;
}
void vector(std::ostream& out, const physics::Vec3& v) {
  out << '[';
  number(out, v.x());
  out << ',';
  number(out, v.y());
  out << ',';
  number(out, v.z());
  out << ']';
}
// A JSON string, escaped; "</" written as "<\/" so that no text closes the page's script element.
void text(std::ostream& out, const std::string& value) {
  out << '"';
  char previous = 0;
  for (const char c : value) {
    if (c == '"' || c == '\\') out << '\\' << c;
    else if (c == '/' && previous == '<') out << "\\/";
    else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out << escaped;
    } else out << c;
    previous = c;
  }
  out << '"';
}

// ",value" with `digits` decimals, its trailing zeros (and a bare point) left out; "-0" is "0".
void fixed(std::string& out, double value, int digits) {
  char text[48] = ",";
  int length = 1 + std::snprintf(text + 1, sizeof text - 1, "%.*f", digits, std::isfinite(value) ? value : 0.0);
  while (length > 1 && text[length - 1] == '0') --length;
  if (text[length - 1] == '.') --length;
  if (length == 1 || (length == 3 && text[1] == '-' && text[2] == '0')) text[1] = '0', length = 2;
  out.append(text, size_t(length));
}

void triangle_corners(std::ostream& out, const physics::Shape& shape) {
  out << ",\"triangles\":[";
  bool first = true;
  auto corner = [&](const physics::Vec3& p) {
    for (int k = 0; k < 3; ++k) {
      if (!first) out << ',';
      first = false;
      number(out, p[k]);
    }
  };
  if (shape.type == physics::ShapeType::hull) {  // each face fanned from its first corner
    const physics::Hull& hull = *shape.hull();
    for (const physics::HullFace& face : hull.faces)
      for (int k = 1; k + 1 < face.count; ++k)
        for (const int c : {hull.corner_of(face, 0), hull.corner_of(face, k), hull.corner_of(face, k + 1)}) corner(hull.corners[size_t(c)]);
  } else {
    const physics::Mesh& mesh = *shape.mesh();
    for (const physics::MeshTriangle& triangle : mesh.triangles)
      for (const int c : triangle.corners) corner(mesh.vertices[size_t(c)]);
  }
  out << ']';
}

void body_json(std::ostream& out, const physics::Body& body, const Colour& colour) {
  const physics::Shape& s = body.shape;
  out << "{\"name\":";
  text(out, body.name);
  out << ",\"shape\":\"" << physics::shape_name(s.type) << "\",\"static\":" << (body.is_static() ? "true" : "false") << ",\"colour\":";
  vector(out, physics::Vec3(colour.r, colour.g, colour.b));
  if (!body.is_static()) {  // for the numbers the page shows on a click: momentum, energy
    out << ",\"mass\":";
    number(out, body.mass);
    out << ",\"inertia\":[";  // in the body's frame, row by row
    for (int k = 0; k < 9; ++k) {
      if (k > 0) out << ',';
      number(out, body.inertia_local(k / 3, k % 3));
    }
    out << ']';
  }
  switch (s.type) {
    case physics::ShapeType::sphere: out << ",\"radius\":"; number(out, s.radius); break;
    case physics::ShapeType::box: out << ",\"half_extents\":"; vector(out, s.half_extents); break;
    case physics::ShapeType::capsule:
    case physics::ShapeType::cylinder:
      out << ",\"radius\":";
      number(out, s.radius);
      out << ",\"half_height\":";
      number(out, s.half_height);
      break;
    case physics::ShapeType::hull:
    case physics::ShapeType::mesh: triangle_corners(out, s); break;
    case physics::ShapeType::plane:
      out << ",\"normal\":";
      vector(out, s.normal);
      out << ",\"offset\":";
      number(out, s.offset);
      break;
  }
  out << '}';
}

// What the video marks on a frame, kept until the run's scales are known (they fit its largest
// impulse and speed).
struct MarkedFrame {
  std::vector<BodyPose> poses;
  std::vector<physics::Vec3> velocities;
  std::vector<physics::ContactRecord> contacts;
};

// The marks as the video draws them (scene_draw_list, at the scene's camera): per frame its arrows
// (origin, direction, colour), dots (position, colour, radius in pixels, largest radius in m: 0 for
// none) and lines (from, to, colour, width in pixels), colours as indices into a palette; and the
// legend, each arrow entry with the metres its round value is long.
void write_marks(const Scene& scene, const WorldTake& take, const ArrowScales& scales, const std::vector<MarkedFrame>& frames,
                 const std::vector<render::Camera>& cameras, const PaneLayout& layout, std::ostream& out) {
  std::vector<physics::Body> bodies = take.bodies();
  std::vector<render::Colour> palette;
  auto colour = [&](std::string& to, const render::Colour& c) {
    size_t k = 0;
    while (k < palette.size() && !(palette[k].r == c.r && palette[k].g == c.g && palette[k].b == c.b)) ++k;
    if (k == palette.size()) palette.push_back(c);
    to += ',';
    to += std::to_string(k);
  };
  auto point = [](std::string& to, const render::Vec3f& p) {
    for (int c = 0; c < 3; ++c) fixed(to, p[c], 4);
  };
  std::string written;
  for (size_t k = 0; k < frames.size(); ++k) {
    const MarkedFrame& frame = frames[k];
    for (size_t i = 0; i < bodies.size(); ++i) bodies[i].velocity = frame.velocities[i];
    const render::DrawList list = scene_draw_list(scene, bodies, frame.poses, take.joints(), frame.contacts, scales, cameras[k]);
    std::string arrows, dots, lines;
    for (const render::ArrowItem& arrow : list.arrows) {
      point(arrows, arrow.origin);
      point(arrows, arrow.direction);
      colour(arrows, arrow.colour);
    }
    for (const render::PointItem& dot : list.points) {
      point(dots, dot.position);
      colour(dots, dot.colour);
      fixed(dots, dot.radius_pixels, 1);
      fixed(dots, std::isfinite(dot.largest_radius) ? dot.largest_radius : 0.0f, 4);
    }
    for (const render::LineItem& line : list.lines) {
      point(lines, line.from);
      point(lines, line.to);
      colour(lines, line.colour);
      fixed(lines, line.width_pixels, 1);
    }
    // Each list without its leading comma.
    written += k > 0 ? ",[[" : "[[";
    written.append(arrows, arrows.empty() ? 0 : 1);
    written += "],[";
    written.append(dots, dots.empty() ? 0 : 1);
    written += "],[";
    written.append(lines, lines.empty() ? 0 : 1);
    written += "]]";
  }
  out << ",\"marks\":{\"frames\":[" << written << "],\"palette\":[";
  for (size_t k = 0; k < palette.size(); ++k) {
    if (k > 0) out << ',';
    vector(out, physics::Vec3(palette[k].r, palette[k].g, palette[k].b));
  }
  // The video's legend, at its size: an arrow entry's pixels back into metres at the camera's target.
  const render::Camera& camera = cameras.front();
  const render::CameraView view = render::make_camera_view(camera, layout.width, layout.height);  // a pane's, as the video's
  const double pixels_per_metre = view.pixels_per_metre(camera.target);
  out << "],\"legend\":[";
  bool first = true;
  for (const render::LegendEntry& entry : legend(scene.draw, scales, view, camera.target, false)) {
    out << (first ? "" : ",") << "{\"text\":";
    text(out, entry.text);
    out << ",\"colour\":";
    vector(out, physics::Vec3(entry.colour.r, entry.colour.g, entry.colour.b));
    out << ",\"dot\":" << (entry.dot ? "true" : "false") << ",\"metres\":";
    number(out, pixels_per_metre > 0 ? entry.scale_pixels / pixels_per_metre : 0.0);
    out << '}';
    first = false;
  }
  out << "]}";
}

// One pane's run as the page writes it, taken frame by frame as the video's frames sample it.
struct PaneRecord {
  const Scene* scene = nullptr;
  std::string label;
  std::unique_ptr<WorldTake> take;
  std::string frames;  // per frame, the bodies whose pose changed: index, then x y z, w x y z (ChangeWriter)
  std::string motion;  // per frame, the bodies whose velocity or spin changed: index, then v, ω
  std::vector<MarkedFrame> marked;     // where the scene marks anything
  std::vector<ImpactNumbers> impacts;  // each frame's latest impact, for the equations
  std::vector<physics::Vec3> followed; // each frame's position of the body the camera follows
};

// Whether the scene draws marks: contact points, normals, impulses, friction, velocities, rods.
bool marks_anything(const Scene& scene, const WorldTake& take) {
  const DrawOptions& draw = scene.draw;
  return draw.contact_points || draw.contact_normals || draw.impulses || draw.friction || draw.velocities || !take.joints().empty();
}

// Every frame that starts before the duration ends, as the video's at real speed (1 s at 30 fps:
// 30 frames, at 0 .. 29/30 s).
long frame_count(const Scene& scene) { return std::max(1L, std::lround(std::ceil(scene.duration * scene.video.fps - 0.5))); }

// Numbers of a body that change frame to frame, in whole units (1e-5 m ...), each written as its
// change since the body's last written ones (the first time: from 0), and only where one changed.
template <size_t N>
class ChangeWriter {
 public:
  explicit ChangeWriter(size_t bodies) : last_(bodies), written_(bodies, false) {}
  // Appends "i,d0,...,dN-1" (after a comma unless `first`) when body i's units changed.
  void write(std::string& to, size_t i, const std::array<long long, N>& units, bool& first) {
    if (written_[i] && units == last_[i]) return;
    if (!first) to += ',';
    first = false;
    to += std::to_string(i);
    for (size_t c = 0; c < N; ++c) {
      to += ',';
      to += std::to_string(units[c] - last_[i][c]);
    }
    last_[i] = units;
    written_[i] = true;
  }

 private:
  std::vector<std::array<long long, N>> last_;
  std::vector<bool> written_;
};

long long units(double value, double per_unit) { return std::llround((std::isfinite(value) ? value : 0.0) * per_unit); }

// Positions to 1e-5 m, orientations to 1e-6; velocities and spins to 1e-4 (m/s, rad/s: a resting
// body's jitter below it costs nothing). A body at rest or asleep costs nothing.
PaneRecord record(const Pane& pane) {
  PaneRecord run{pane.scene, pane.label, std::make_unique<WorldTake>(*pane.scene), "", "", {}, {}, {}};
  const Scene& scene = *pane.scene;
  WorldTake& take = *run.take;
  const long frames = frame_count(scene);
  const size_t bodies = take.bodies().size();
  const bool marked = marks_anything(scene, take);
  FrameSample sample;
  ChangeWriter<7> poses(bodies);
  ChangeWriter<6> motions(bodies);
  const int followed = find_body(scene, scene.camera_motion.follow);  // -1: none
  for (long k = 0; k < frames; ++k) {
    const double time = double(k) / scene.video.fps;
    while (!take.finished() && take.time() < time - 1e-9) take.step();
    take.sample(time, time, sample);
    run.frames += k > 0 ? ",[" : "[";
    bool first = true;
    for (size_t i = 0; i < sample.poses.size(); ++i) {
      const physics::Vec3& x = sample.poses[i].position;
      const physics::Quat& q = sample.poses[i].orientation;
      poses.write(run.frames, i, {units(x.x(), 1e5), units(x.y(), 1e5), units(x.z(), 1e5), units(q.w(), 1e6), units(q.x(), 1e6),
                                  units(q.y(), 1e6), units(q.z(), 1e6)}, first);
    }
    run.frames += ']';
    run.motion += k > 0 ? ",[" : "[";
    first = true;
    for (size_t i = 0; i < sample.velocities.size(); ++i) {
      const physics::Vec3& v = sample.velocities[i];
      const physics::Vec3& w = sample.angular_velocities[i];
      motions.write(run.motion, i, {units(v.x(), 1e4), units(v.y(), 1e4), units(v.z(), 1e4), units(w.x(), 1e4), units(w.y(), 1e4),
                                    units(w.z(), 1e4)}, first);
    }
    run.motion += ']';
    if (marked) run.marked.push_back({sample.poses, sample.velocities, sample.contacts});
    run.impacts.push_back(sample.impact);
    if (followed >= 0) run.followed.push_back(sample.poses[size_t(followed)].position);
  }
  while (!take.finished()) take.step();  // to the end, as the film: the summary (scales, impacts, extent) is the whole run's
  return run;
}

// The typeset mathematics the panes show (each [[equation]], the [overlay] equation panel), as the
// film typesets it: each distinct panel once (where, heading, its colour, which SVG, its size at
// 720 lines), each SVG once.
class PanelTable {
 public:
  // A pane's panels at each frame, as [index, opacity, ...]: "" when the scene shows none.
  std::string frames(const PaneRecord& run) {
    const Scene& scene = *run.scene;
    if (scene.equations.empty() && scene.overlay.equation == "none") return "";
    LiveEquations equations(scene, film_typesetter());
    std::string written;
    for (size_t k = 0; k < run.impacts.size(); ++k) {
      render::Overlay overlay;
      equations.add_panels(double(k) / scene.video.fps, run.impacts[k], overlay);
      std::string shown;
      for (const render::OverlayPanel& panel : overlay.panels) {
        shown += shown.empty() ? "" : ",";
        shown += std::to_string(index_of(panel));
        fixed(shown, panel.opacity, 2);
      }
      written += k > 0 ? ",[" : "[";
      written += shown;
      written += ']';
    }
    return written;
  }
  bool empty() const { return entries_.empty(); }
  void write(std::ostream& out) const {
    out << ",\"panels\":[";
    for (size_t k = 0; k < entries_.size(); ++k) out << (k > 0 ? "," : "") << entries_[k];
    out << "],\"svgs\":[";
    for (size_t k = 0; k < svgs_.size(); ++k) {
      if (k > 0) out << ',';
      text(out, *svgs_[k]);
    }
    out << ']';
  }

 private:
  int index_of(const render::OverlayPanel& panel) {
    const auto [svg, added] = svg_index_.emplace(panel.math.key, int(svgs_.size()));
    if (added) svgs_.push_back(panel.math.svg ? panel.math.svg : std::make_shared<const std::string>());
    static const char* const places[] = {"corner", "top-left", "top-right", "bottom-left", "bottom-right", "bottom"};
    std::ostringstream entry;
    entry << "{\"place\":\"" << places[int(panel.place)] << "\",\"lines\":[";
    for (size_t k = 0; k < panel.lines.size(); ++k) {
      if (k > 0) entry << ',';
      text(entry, panel.lines[k]);
    }
    entry << "],\"colour\":";
    vector(entry, physics::Vec3(panel.colour.r, panel.colour.g, panel.colour.b));
    entry << ",\"svg\":" << svg->second << ",\"scale\":";
    number(entry, panel.math.pixels_per_point);
    entry << '}';
    const auto [found, fresh] = entry_index_.emplace(entry.str(), int(entries_.size()));
    if (fresh) entries_.push_back(entry.str());
    return found->second;
  }

  std::vector<std::string> entries_;
  std::map<std::string, int> entry_index_;
  std::vector<std::shared_ptr<const std::string>> svgs_;
  std::map<std::string, int> svg_index_;
};

// A pane's own part of the run: gravity, bodies, frames, motion, marks and equation panels.
void write_pane(const PaneRecord& run, const ArrowScales& scales, const std::vector<render::Camera>& cameras, const PaneLayout& layout,
                const std::string& panel_frames, std::ostream& out) {
  const Scene& scene = *run.scene;
  const std::vector<physics::Body>& bodies = run.take->bodies();
  out << "\"gravity\":";
  vector(out, scene.world.gravity);
  out << ",\"bodies\":[";
  for (size_t i = 0; i < bodies.size(); ++i) {
    if (i > 0) out << ',';
    body_json(out, bodies[i], scene.colours[i]);
  }
  out << "],\"frames\":[" << run.frames << "],\"motion\":[" << run.motion << ']';
  if (marks_anything(scene, *run.take)) write_marks(scene, *run.take, scales, run.marked, cameras, layout, out);
  if (!panel_frames.empty()) out << ",\"panel_frames\":[" << panel_frames << ']';
}

// The video's live plots ([overlay] plots), whole: per plot its title, unit, time axis, value range
// (every pane's largest), and each curve's colour and points (t, value), as many as the video's
// last frame draws (every step, or every 2nd, 4th ... of a long run); a comparison's panes' curves
// on the same axes, each in its pane's colour. The page draws each up to the moment shown.
void write_plots(const std::vector<PaneRecord>& runs, const TakeSummary& shared, std::ostream& out) {
  std::vector<render::Plot> plots;
  for (size_t p = 0; p < runs.size(); ++p) {
    const Scene& scene = *runs[p].scene;
    const WorldTake& take = *runs[p].take;
    std::vector<PlotCurve> curves;
    for (const int body : plotted_bodies(take.bodies(), scene.overlay.plot_bodies))
      curves.push_back({take.bodies()[size_t(body)].name, to_render(scene.colours[size_t(body)])});
    std::vector<render::Plot> own = take.plots().plots(take.plots().steps(), scene.duration, shared.plot_maxima, curves);
    for (size_t k = 0; k < own.size(); ++k) {
      if (k == plots.size()) {
        plots.push_back(own[k]);
        plots.back().series.clear();
      }
      for (render::PlotSeries& series : own[k].series) {
        if (runs.size() > 1) series.colour = pane_colour(int(p));
        plots[k].series.push_back(std::move(series));
      }
    }
  }
  out << ",\"plots\":[";
  for (size_t k = 0; k < plots.size(); ++k) {
    const render::Plot& plot = plots[k];
    out << (k > 0 ? "," : "") << "{\"title\":";
    text(out, plot.title);
    out << ",\"unit\":";
    text(out, plot.unit);
    for (const auto& [name, value] : {std::pair{"x_start", plot.x_start}, {"x_end", plot.x_end}, {"y_min", plot.y_min}, {"y_max", plot.y_max}}) {
      out << ",\"" << name << "\":";
      number(out, value);
    }
    out << ",\"series\":[";
    for (size_t c = 0; c < plot.series.size(); ++c) {
      const render::PlotSeries& series = plot.series[c];
      out << (c > 0 ? "," : "") << "{\"colour\":";
      vector(out, physics::Vec3(series.colour.r, series.colour.g, series.colour.b));
      std::string points;
      for (const render::Vec2f& point : series.points) {
        fixed(points, point.x(), 4);
        fixed(points, point.y(), 4);
      }
      out << ",\"points\":[" << points.substr(points.empty() ? 0 : 1) << "]}";
    }
    out << "]}";
  }
  out << ']';
}

// Where the video puts its panes (one: the whole frame).
PaneLayout video_layout(const std::vector<PaneRecord>& runs) {
  const Scene& scene = *runs.front().scene;
  return pane_layout(int(runs.size()), scene.video.width, scene.video.height, !scene.overlay.plots.empty(), !scene.captions.empty());
}

// The video's camera at each frame: the scene's, or where [camera] follow, keyframes or fit move
// it (CameraPath, as the film moves it; a comparison's as its first pane's, fitted to a pane).
std::vector<render::Camera> camera_frames(const std::vector<PaneRecord>& runs, const TakeSummary& shared) {
  const Scene& scene = *runs.front().scene;
  CameraPath path(scene);
  if (scene.camera_motion.fit) {
    const PaneLayout layout = video_layout(runs);
    path.fit(shared.moving_extent, double(layout.width) / layout.height);
  }
  std::vector<render::Camera> cameras;
  const PaneRecord& first = runs.front();
  for (size_t k = 0; k < first.impacts.size(); ++k)
    cameras.push_back(path.at(double(k) / scene.video.fps, first.followed.empty() ? physics::Vec3::Zero() : first.followed[k]));
  return cameras;
}

bool camera_moves(const Scene& scene) {
  return !scene.camera_motion.follow.empty() || !scene.camera_motion.keyframes.empty() || scene.camera_motion.fit;
}

void write_captions(std::ostream& out, const std::vector<CaptionCue>& captions, bool own, double duration) {
  out << '[';
  bool first = true;
  for (const CaptionCue& caption : captions) {
    if (caption.own != own || (!own && caption.pane > 1)) continue;  // a file's own values: its first pane's
    out << (first ? "" : ",") << "{\"text\":";
    text(out, caption.text);
    out << ",\"start\":";
    number(out, caption.start);
    out << ",\"end\":";
    number(out, std::min(caption.end, duration));
    out << '}';
    first = false;
  }
  out << ']';
}

}  // namespace

void write_json_string(std::ostream& out, const std::string& value) { text(out, value); }

void write_run_json(const std::vector<Pane>& panes, std::ostream& out) {
  if (panes.empty()) throw std::invalid_argument("a page shows one to four scenes");
  std::vector<PaneRecord> runs;
  for (const Pane& pane : panes) runs.push_back(record(pane));
  const Scene& scene = *panes.front().scene;  // the first sets the clock, the camera and the captions
  const int fps = scene.video.fps;
  const long frames = frame_count(scene);
  std::vector<const TakeSummary*> summaries;
  for (const PaneRecord& run : runs) summaries.push_back(&run.take->summary());
  const TakeSummary shared = shared_summary(summaries);
  out << "{\"title\":";
  text(out, scene.title);
  out << ",\"fps\":" << fps << ",\"duration\":";
  number(out, scene.duration);
  // The camera the page starts from: the video's first; and where it moves, the video's at each
  // frame (x y z, target x y z, field of view), which the page follows until it is orbited.
  const std::vector<render::Camera> cameras = camera_frames(runs, shared);
  const render::Camera& start = cameras.front();
  out << ",\"camera\":{\"position\":";
  vector(out, start.position.cast<double>());
  out << ",\"target\":";
  vector(out, start.target.cast<double>());
  out << ",\"fov_y_degrees\":";
  number(out, start.fov_y_degrees);
  out << '}';
  if (camera_moves(scene)) {
    std::string path;
    for (const render::Camera& camera : cameras) {
      std::string numbers;
      for (int c = 0; c < 3; ++c) fixed(numbers, camera.position[c], 4);
      for (int c = 0; c < 3; ++c) fixed(numbers, camera.target[c], 4);
      fixed(numbers, camera.fov_y_degrees, 3);
      numbers[0] = '[';
      path += path.empty() ? "" : ",";
      path += numbers;
      path += ']';
    }
    out << ",\"camera_path\":[" << path << ']';
  }
  out << ",\"captions\":";
  write_captions(out, scene.captions, false, scene.duration);
  // The video's playback: simulated s per second of video at each frame (slower around an impact
  // of any pane), and the speed outside them.
  const PlaybackTimeline timeline(scene.playback, shared.impact_times, scene.duration, fps);
  out << ",\"playback_speed\":";
  number(out, scene.playback.speed);
  out << ",\"speeds\":[";
  for (long k = 0; k < frames; ++k) {
    if (k > 0) out << ',';
    number(out, timeline.speed_at(double(k) / fps));
  }
  out << ']';
  if (!scene.overlay.plots.empty()) write_plots(runs, shared, out);
  PanelTable panels;
  std::vector<std::string> panel_frames;
  for (const PaneRecord& run : runs) panel_frames.push_back(panels.frames(run));
  if (!panels.empty()) panels.write(out);
  if (runs.size() == 1) {
    out << ',';
    write_pane(runs.front(), arrow_scales(scene, shared), cameras, video_layout(runs), panel_frames.front(), out);
  } else {
    // Each pane's own bodies and run, with the label naming what sets it apart, in its colour.
    out << ",\"panes\":[";
    for (size_t p = 0; p < runs.size(); ++p) {
      out << (p > 0 ? ",{" : "{") << "\"label\":";
      text(out, runs[p].label);
      out << ",\"colour\":";
      const render::Colour colour = pane_colour(int(p));
      vector(out, physics::Vec3(colour.r, colour.g, colour.b));
      out << ",\"captions\":";
      write_captions(out, runs[p].scene->captions, true, scene.duration);
      out << ',';
      write_pane(runs[p], arrow_scales(*runs[p].scene, shared), cameras, video_layout(runs), panel_frames[p], out);
      out << '}';
    }
    out << ']';
  }
  out << '}';
}

void write_run_json(const Scene& scene, std::ostream& out) { write_run_json({Pane{&scene, ""}}, out); }

namespace {

// Runs the packed viewer: its text unpacked by the browser's DecompressionStream, as an inline
// script (the page's policy allows those).
constexpr const char* kUnpacker =
    "(async () => {\n"
    "  const text = document.getElementById('impulse-viewer').textContent.trim();\n"
    "  const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));\n"
    "  const script = document.createElement('script');\n"
    "  script.textContent = await new Response(new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'))).text();\n"
    "  document.body.append(script);\n"
    "})().catch((failure) => { document.getElementById('errors').textContent = 'error: ' + failure; });\n";

// `bytes` gzipped (zlib's default level), then in base64: a page's run, which the page unpacks with
// the browser's DecompressionStream.
std::string gzip_base64(const std::string& bytes) {
  z_stream stream{};
  if (deflateInit2(&stream, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)  // 16: gzip's header
    throw std::runtime_error("zlib cannot start");
  std::string packed(deflateBound(&stream, uLong(bytes.size())), '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = uInt(bytes.size());
  stream.next_out = reinterpret_cast<Bytef*>(packed.data());
  stream.avail_out = uInt(packed.size());
  const int done = deflate(&stream, Z_FINISH);
  packed.resize(stream.total_out);
  deflateEnd(&stream);
  if (done != Z_STREAM_END) throw std::runtime_error("zlib cannot pack the page's run");
  const std::unique_ptr<gchar, decltype(&g_free)> text(g_base64_encode(reinterpret_cast<const guchar*>(packed.data()), packed.size()), g_free);
  return text.get();
}

// The page around the run (its JSON), `live` the live block (or nothing); a live page may fetch
// from where it came.
void write_html(const std::string& script, std::ostream& out, bool live, const std::string& run_json, const std::string& state_json) {
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src data:"
      << (live ? "; connect-src 'self'" : "")
      << "\">\n"
         "<title>impulse page</title>\n<style>\n"
         "html, body { margin: 0; height: 100%; font-family: 'DejaVu Sans', sans-serif; background: #eaedf4; }\n"
         "#view { position: absolute; inset: 0 0 56px 0; }\n#view canvas { width: 100%; height: 100%; display: block; }\n"
         "#overlay, .pane { position: absolute; inset: 0; pointer-events: none; }\n"
         ".corner { position: absolute; display: flex; flex-direction: column; gap: 8px; }\n"
         ".top-left { top: 64px; left: 16px; align-items: flex-start; } .top-right { top: 12px; right: 16px; align-items: flex-end; }\n"
         ".bottom-left { bottom: 16px; left: 16px; align-items: flex-start; } .bottom-right { bottom: 16px; right: 16px; align-items: flex-end; }\n"
         ".bottom { bottom: 16px; left: 50%; transform: translateX(-50%); align-items: center; width: 80%; }\n"
         ".pane .top-left { top: 8px; left: 8px; } .pane .top-right { top: 8px; right: 8px; } .pane .bottom-left { bottom: 40px; left: 8px; }\n"
         ".pane .bottom-right { bottom: 8px; right: 8px; } .pane .bottom { bottom: 8px; }\n"
         ".plot, .equation { padding: 6px 10px; border-radius: 8px; background: rgba(255, 255, 255, 0.92); font-size: 14px; }\n"
         ".equation img { display: block; margin-top: 2px; }\n.plot svg { display: block; margin-top: 2px; }\n"
         "#plots { display: flex; flex-direction: column; gap: 8px; align-items: flex-end; }\n"
         ".label { position: absolute; left: 8px; bottom: 8px; padding: 3px 10px; border: 2px solid; border-radius: 6px; background: rgba(255, 255, 255, 0.9); font-size: 15px; }\n"
         "#bar { position: absolute; left: 0; right: 0; bottom: 0; height: 56px; display: flex; gap: 10px; align-items: center; padding: 0 14px; background: #fff; }\n"
         "#time { flex: 1; }\n#clock { font-family: 'DejaVu Sans Mono', monospace; min-width: 7em; }\n"
         "h1 { position: absolute; top: 12px; left: 16px; margin: 0; padding: 8px 12px; font-size: 20px; background: #fff; border-radius: 8px; }\n"
         "#caption, .caption { max-width: 100%; padding: 8px 16px; border-radius: 8px; background: rgba(40, 42, 48, 0.85); color: #fff; font-size: 18px; text-align: center; }\n"
         ".caption { font-size: 15px; padding: 5px 12px; }\n"
         "#caption:empty, .caption:empty { display: none; }\n"
         "pre#probe, pre#errors { position: absolute; left: -9999px; }\n"
         "#problem { position: absolute; top: 64px; left: 16px; right: 16px; margin: 0; padding: 10px 14px; border-radius: 8px; background: #fff0f0; color: #8a1010; border: 2px solid #d04040; font: 15px 'DejaVu Sans Mono', monospace; white-space: pre-wrap; }\n"
         "#problem:empty { display: none; }\n"
         "#panel { padding: 8px 14px 10px; border-radius: 8px; background: rgba(255, 255, 255, 0.94); font-size: 14px; box-shadow: 0 1px 6px rgba(0, 0, 0, 0.2); }\n"
         "#panel h2 { margin: 0 0 6px; font-size: 16px; } #panel td { padding: 1px 8px 1px 0; white-space: nowrap; } #panel td:nth-child(2) { font-family: 'DejaVu Sans Mono', monospace; font-size: 13px; }\n"
         "#panel p { margin: 6px 0 0; font-size: 12px; color: #555; max-width: 300px; }\n"
         "#legend { padding: 6px 10px; border-radius: 8px; background: rgba(255, 255, 255, 0.9); font-size: 13px; line-height: 18px; }\n"
         "#legend svg { vertical-align: middle; }\n"
         "[hidden] { display: none !important; }\n"
         "body.bare #legend, body.bare #caption, body.bare .caption, body.bare .label { display: none; }\n"
         "body.bare #view { inset: auto; left: 0; top: 0; } body.bare #bar, body.bare h1 { display: none; }\n</style></head><body>\n"
         "<div id=\"view\"><div id=\"overlay\"></div></div>\n<h1 id=\"title\"></h1>\n<div id=\"caption\"></div>\n"
         "<div id=\"bar\"><button id=\"play\">Play</button><button id=\"back\" title=\"one frame back\">&#9664;</button>"
         "<button id=\"forward\" title=\"one frame on\">&#9654;</button>"
         "<input id=\"time\" type=\"range\" min=\"0\" max=\"0\" step=\"1\" value=\"0\" aria-label=\"time\">"
         "<span id=\"clock\">t = 0.00 s</span><label>speed <select id=\"speed\"><option value=\"0.25\">\u00bc\u00d7</option>"
         "<option value=\"0.5\">\u00bd\u00d7</option><option value=\"1\" selected>1\u00d7</option><option value=\"2\">2\u00d7</option></select></label></div>\n"
         "<div id=\"legend\" hidden></div><div id=\"panel\" hidden></div><pre id=\"problem\"></pre><pre id=\"probe\"></pre><pre id=\"errors\"></pre>\n"
         "<script id=\"impulse-run\" type=\"application/gzip;base64\">"
      << gzip_base64(run_json) << "</script>\n";
  if (live) out << "<script id=\"impulse-live\" type=\"application/json\">" << state_json << "</script>\n";
  // The viewer packed as the run is (a third of its size), and the few lines that unpack and run it.
  out << "<script id=\"impulse-viewer\" type=\"application/gzip;base64\">" << gzip_base64(script)
      << "</script>\n<script>\n" << kUnpacker << "</script>\n</body></html>\n";
}

}  // namespace

void write_page(const std::vector<Pane>& panes, const std::string& script, std::ostream& out) {
  std::ostringstream run;
  write_run_json(panes, run);
  write_html(script, out, false, run.str(), "");
}

void write_page(const Scene& scene, const std::string& script, std::ostream& out) { write_page({Pane{&scene, ""}}, script, out); }

void write_live_page(const std::string& run_json, const std::string& state_json, const std::string& script, std::ostream& out) {
  write_html(script, out, true, run_json, state_json);
}

std::string page_path(const std::string& video_path) {
  return std::filesystem::path(video_path).replace_extension(".html").string();
}

std::string page_script() {
  namespace fs = std::filesystem;
  std::error_code error;
  std::vector<fs::path> places;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (!error) places.push_back(self.parent_path().parent_path() / "share" / "impulse" / "web" / "page.js");
  places.push_back(IMPULSE_BUILD_PAGE_SCRIPT);
  for (const fs::path& place : places) {
    std::ifstream in(place, std::ios::binary);
    if (!in) continue;
    std::ostringstream script;
    script << in.rdbuf();
    return script.str();
  }
  throw std::runtime_error(std::string("the page's viewer is not built (") + IMPULSE_BUILD_PAGE_SCRIPT +
                           "): run scripts/build.sh, which bundles web/ with npm");
}

}  // namespace impulse::demos
