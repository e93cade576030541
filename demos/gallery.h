// The gallery: OUT/index.html, a page to hand to students. Every scene of a directory whose video
// is in OUT gets its title, the scene file's description (its first comment lines), the video
// with its poster, captions and chapters tracks, the settings it used, and for a comparison a
// link to each pane rendered alone. Links are relative: the page works opened from disk and
// served by any static server.
#pragma once
#include <map>
#include <string>

namespace impulse::demos {

// The name of a comparison's pane rendered alone, beside the comparison: NAME.mp4 -> NAME.pane-2.mp4
// (panes from 1).
std::string pane_video_path(const std::string& video_path, int pane);

// Writes OUT/index.html (as a .part file, renamed when complete) and returns how many videos it
// shows. `failed` holds the scene files (by file name) that the catalogue's run did not render,
// each with its exit code: each is marked, with its video from an earlier run if there is one.
// Throws render::OutputError when it cannot be written.
int write_gallery(const std::string& scenes_directory, const std::string& out_directory,
                  const std::map<std::string, int>& failed = {});

}  // namespace impulse::demos
