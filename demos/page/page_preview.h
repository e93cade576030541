// `impulse preview`: the scene's live page, served on the loopback address and made again each
// time the scene file is saved.
#pragma once

#include <functional>
#include <string>

namespace impulse::demos {

// What the page polls: the run's number (one more at each reading of the file, good or bad), the
// scene's error in the words `impulse` prints (empty when it reads), and whether a new run is
// being made.
struct PreviewState {
  long version = 0;
  std::string error;
  bool busy = false;
};
std::string state_json(const PreviewState& state);

// The run shown before any reading of the scene has succeeded: no bodies, no frames but one.
std::string empty_run_json();

// Serves on 127.0.0.1:`port` (0: any free port) until the process is stopped (Ctrl-C):
//   GET /       the live page (write_live_page) of the last good run
//   GET /state  PreviewState as JSON
// and nothing else: any other path or method is 404, a request naming another host than
// 127.0.0.1 or localhost is 403 (a page elsewhere cannot read the scene through the browser).
// `make_run` reads `scene_path` and returns its run's JSON, or throws with the words a user reads;
// it is called once before serving and again, on a thread of its own, whenever the file's
// modification time, size or inode changes. `announce` is called with the page's address once
// the port is open. Throws std::runtime_error when the port cannot be had.
void serve_preview(const std::string& scene_path, int port, const std::string& script, const std::function<std::string()>& make_run,
                   const std::function<void(const std::string& address)>& announce);

}  // namespace impulse::demos
