#include "demos/page/page_preview.h"

#include "demos/page/page_export.h"

#include <httplib.h>
#include <sys/stat.h>

#include <atomic>
#include <memory>
#include <chrono>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace impulse::demos {

std::string state_json(const PreviewState& state) {
  std::ostringstream out;
  out << "{\"version\":" << state.version << ",\"error\":";
  write_json_string(out, state.error);
  out << ",\"busy\":" << (state.busy ? "true" : "false") << '}';
  return out.str();
}

std::string empty_run_json() {
  return "{\"title\":\"\",\"fps\":30,\"duration\":0,\"camera\":{\"position\":[0,2,6],\"target\":[0,0.5,0],\"fov_y_degrees\":45},"
         "\"gravity\":[0,-9.81,0],\"captions\":[],\"bodies\":[],\"frames\":[[]],\"motion\":[[]]}";
}

namespace {

// What identifies one saved version of a file: a save rewrites it (time, size) or replaces it
// (inode); `exists` false while an editor has it renamed away.
struct Stamp {
  bool exists = false;
  long long seconds = 0, nanoseconds = 0, size = 0, inode = 0;
  bool operator==(const Stamp&) const = default;
};
Stamp stamp_of(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return {};
  return {true, status.st_mtim.tv_sec, status.st_mtim.tv_nsec, status.st_size, static_cast<long long>(status.st_ino)};
}

// The last good run and the state, shared by the server's threads and the watcher.
class Runs {
 public:
  explicit Runs(std::function<std::string()> make_run) : make_run_(std::move(make_run)) {}

  // Reads the scene again: a good run replaces the last; an error is kept beside it.
  void make() {
    {
      std::lock_guard lock(mutex_);
      state_.busy = true;
    }
    std::string run, error;
    try {
      run = make_run_();
    } catch (const std::exception& failure) {
      error = failure.what();
    }
    std::lock_guard lock(mutex_);
    if (error.empty()) run_ = std::move(run);
    state_.error = std::move(error);
    state_.busy = false;
    ++state_.version;
  }
  std::string page(const std::string& script) const {
    std::ostringstream out;
    std::lock_guard lock(mutex_);
    write_live_page(run_, state_json(state_), script, out);
    return out.str();
  }
  std::string state() const {
    std::lock_guard lock(mutex_);
    return state_json(state_);
  }
  std::string error() const {
    std::lock_guard lock(mutex_);
    return state_.error;
  }

 private:
  std::function<std::string()> make_run_;
  mutable std::mutex mutex_;
  std::string run_ = empty_run_json();
  PreviewState state_;
};

// A body sent as it is: httplib compresses a text body for a browser that accepts Brotli at
// Brotli's slowest setting (a second for a page); served on the loopback, it gains nothing.
void send(httplib::Response& response, std::string body, const char* type) {
  auto text = std::make_shared<const std::string>(std::move(body));
  response.set_header("Cache-Control", "no-store");
  response.set_content_provider(text->size(), type, [text](size_t offset, size_t length, httplib::DataSink& sink) {
    return sink.write(text->data() + offset, length);
  });
}

}  // namespace

void serve_preview(const std::string& scene_path, int port, const std::string& script, const std::function<std::string()>& make_run,
                   const std::function<void(const std::string& address)>& announce) {
  using namespace std::chrono_literals;
  Runs runs(make_run);
  Stamp seen = stamp_of(scene_path);
  runs.make();
  if (const std::string error = runs.error(); !error.empty()) std::fprintf(stderr, "impulse: %s\n", error.c_str());

  httplib::Server server;
  int bound = 0;
  server.set_pre_routing_handler([&bound](const httplib::Request& request, httplib::Response& response) {
    const std::string host = request.get_header_value("Host");
    const size_t colon = host.rfind(':');
    const std::string name = host.substr(0, colon);
    if (colon != std::string::npos && host.substr(colon + 1) == std::to_string(bound) && (name == "127.0.0.1" || name == "localhost"))
      return httplib::Server::HandlerResponse::Unhandled;
    response.status = 403;
    response.set_content("impulse preview answers only pages of 127.0.0.1 and localhost\n", "text/plain");
    return httplib::Server::HandlerResponse::Handled;
  });
  server.Get("/", [&](const httplib::Request&, httplib::Response& response) { send(response, runs.page(script), "text/html; charset=utf-8"); });
  server.Get("/state", [&](const httplib::Request&, httplib::Response& response) { send(response, runs.state(), "application/json"); });
  server.set_error_handler([](const httplib::Request&, httplib::Response& response) {
    if (response.status == 404) response.set_content("not found: impulse preview serves / and /state\n", "text/plain");
  });

  bound = port == 0 ? server.bind_to_any_port("127.0.0.1") : (server.bind_to_port("127.0.0.1", port) ? port : -1);
  if (bound <= 0)
    throw std::runtime_error("cannot listen on 127.0.0.1:" + std::to_string(port) +
                             " (is another preview running there?): choose another port with --port, or --port 0 for any free one");

  // The watcher: a changed file is read once it has stayed the same for 50 ms (an editor's save
  // may come in pieces).
  std::atomic<bool> stopping = false;
  std::thread watcher([&] {
    while (!stopping) {
      std::this_thread::sleep_for(100ms);
      Stamp now = stamp_of(scene_path);
      if (now == seen || !now.exists) continue;
      for (Stamp settled; std::this_thread::sleep_for(50ms), (settled = stamp_of(scene_path)) != now;) now = settled;
      seen = now;
      runs.make();
      const std::string error = runs.error();
      std::fprintf(stderr, error.empty() ? "impulse: %s read again\n" : "impulse: %s\n", error.empty() ? scene_path.c_str() : error.c_str());
    }
  });
  announce("http://127.0.0.1:" + std::to_string(bound) + "/");
  const bool listened = server.listen_after_bind();
  stopping = true;
  watcher.join();
  if (!listened) throw std::runtime_error("the preview's server stopped on 127.0.0.1:" + std::to_string(bound));
}

}  // namespace impulse::demos
