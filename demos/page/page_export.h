// A scene's interactive page (`impulse export`): the scene run once as the film runs it
// (WorldTake), each video frame's poses written as JSON into one HTML file that holds the viewer
// (web/: three.js, bundled at build time) and fetches nothing.
#pragma once
#include "demos/film/film.h"
#include "demos/scene/scene.h"

#include <ostream>
#include <string>

namespace impulse::demos {

// A JSON string, quoted and escaped, that no text inside it can close a page's script element by.
void write_json_string(std::ostream& out, const std::string& value);

// The page's JSON: title, frame rate, gravity, camera, the bodies (shape, size, colour; a hull's or
// mesh's triangles in its frame; a moving body's mass and inertia) and per frame the poses of the
// bodies whose pose changed since the frame before, each as its index then x y z, w x y z; and
// likewise their velocity and spin after the frame's last step, index then vx vy vz, wx wy wz; and
// what the video marks on each frame (contact points, normals, impulses, velocities, rods), with
// its legend, where the scene draws any; the typeset equations shown at each frame (each SVG once,
// each panel once, per frame which and how opaque); and the video's playback speed at each frame.
void write_run_json(const Scene& scene, std::ostream& out);
// A comparison's (two to four panes, film.h): the first scene's title, clock, camera and captions,
// the playback slowed around an impact of any pane, one arrow scale for all; under "panes" each
// pane's label, colour, own captions, and its gravity, bodies, frames, motion, marks and equations
// as above. One pane: as the scene's own.
void write_run_json(const std::vector<Pane>& panes, std::ostream& out);

// The whole page: `script` is the viewer's bundle (page_script()).
void write_page(const Scene& scene, const std::string& script, std::ostream& out);
void write_page(const std::vector<Pane>& panes, const std::string& script, std::ostream& out);

// The page `impulse preview` serves: `run_json` (write_run_json's) and the viewer as above, and
// `state_json` ({"version":N,"error":...}, the server's /state when the page was made). The page
// may fetch from where it came (/state, which it polls): it reloads on a new run, keeping its
// camera and moment, and shows a scene's error over the last good run.
void write_live_page(const std::string& run_json, const std::string& state_json, const std::string& script, std::ostream& out);

// The page beside a video, as the catalogue writes it and the gallery links it: NAME.html.
std::string page_path(const std::string& video_path);

// The viewer's bundle: <prefix>/share/impulse/web/page.js beside an installed program, else the
// build tree's. Throws std::runtime_error saying how to build it when neither is there.
std::string page_script();

}  // namespace impulse::demos
