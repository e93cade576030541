// The gallery as a browser gets it: a catalogue of two small scenes (one a comparison) rendered
// by the program with its index.html, served from localhost by Python's http.server, opened in
// Debian's headless Chromium. Every video's metadata loads with the duration, width and height it
// was rendered with (decoded back here), and every captions and chapters track loads.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/child_process.h"
#include "tests/support/scene_scratch.h"
#include "tests/support/video_decode.h"

namespace impulse {
namespace {

namespace fs = std::filesystem;

// A ball dropped onto the ground, slowed at its landing (a chapter there), with a caption.
constexpr const char* kDrop = R"(# A ball dropped onto the ground.
[scene]
title = "A drop"
duration = 1.2
[video]
width = 320
height = 180
fps = 15
[playback]
slow_motion_impulse = 0.5
[[caption]]
text = "It falls, and bounces."
start = 0.0
end = 1.0
[[body]]
shape = "plane"
[[body]]
name = "ball"
shape = "sphere"
radius = 0.3
mass = 1.0
restitution = 0.6
position = [0, 1.0, 0]
)";

// The same drop at two restitutions, side by side.
const std::string kPair = std::string(kDrop) + R"(
[compare]
vary = "body[ball].restitution"
values = [0.2, 0.9]
)";

// Loads index.html in a frame and writes one line per video once its metadata and tracks loaded:
// "VIDEO file duration width height error tracks_loaded tracks".
constexpr const char* kCheckPage = R"(<!doctype html>
<html><body><pre id="out">waiting</pre><script>
const frame = document.createElement('iframe');
frame.src = 'index.html';
frame.onload = () => {
  const videos = [...frame.contentDocument.querySelectorAll('video')];
  const lines = [];
  let pending = videos.length;
  const done = () => { if (--pending <= 0) document.getElementById('out').textContent = lines.join('\n') + '\nDONE'; };
  if (videos.length === 0) { pending = 1; done(); }
  videos.forEach(video => {
    const tracks = [...video.querySelectorAll('track')];
    tracks.forEach(track => { track.track.mode = 'hidden'; });
    let reported = false;
    const report = () => {
      if (reported) return;
      if (tracks.some(track => track.readyState < 2)) { setTimeout(report, 50); return; }  // 2 loaded, 3 failed
      reported = true;
      lines.push(['VIDEO', (video.currentSrc || '').split('/').pop(), video.duration, video.videoWidth, video.videoHeight,
                  video.error ? video.error.code : 0, tracks.filter(track => track.readyState === 2).length,
                  tracks.length].join(' '));
      done();
    };
    if (video.readyState >= 1) report();
    video.addEventListener('loadedmetadata', report);
    video.addEventListener('error', report, true);
  });
};
document.body.appendChild(frame);
</script></body></html>
)";

int free_port() {
  const int probe = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t size = sizeof address;
  bind(probe, reinterpret_cast<sockaddr*>(&address), size);
  getsockname(probe, reinterpret_cast<sockaddr*>(&address), &size);
  close(probe);
  return ntohs(address.sin_port);
}

bool accepts(int port) {
  const int client = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(uint16_t(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const bool connected = connect(client, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  close(client);
  return connected;
}

std::string contents(const fs::path& path) {
  std::ostringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

TEST(Gallery, ChromiumLoadsEveryVideoAndTrackAsRendered) {
  const fs::path dir = testing::scratch("gallery_test", "chromium");
  fs::create_directories(dir / "scenes");
  std::ofstream(dir / "scenes" / "drop.toml") << kDrop;
  std::ofstream(dir / "scenes" / "pair.toml") << kPair;
  const fs::path out = dir / "out";
  const testing::ChildResult catalogue = testing::run_child(
      {IMPULSE_PROGRAM, "-q", "catalogue", "--scenes", (dir / "scenes").string(), "-o", out.string()});
  ASSERT_TRUE(catalogue.succeeded()) << catalogue.describe();
  const std::string index = contents(out / "index.html");
  for (const char* part : {"<video", "drop.mp4", "drop.png", "drop.vtt", "drop.chapters.vtt", "pair.mp4",
                           "pair.pane-1.mp4", "pair.pane-2.mp4", "A ball dropped onto the ground.", "href=\"drop.html\"",
                           "href=\"pair.html\""})
    EXPECT_NE(index.find(part), std::string::npos) << part;
  // Each linked page is the scene's, as `impulse export` writes it.
  for (const char* name : {"drop", "pair"}) {
    const testing::ChildResult exported = testing::run_child(
        {IMPULSE_PROGRAM, "-q", "export", (dir / "scenes" / (std::string(name) + ".toml")).string(), "-o", (dir / (std::string(name) + ".html")).string()});
    ASSERT_TRUE(exported.succeeded()) << exported.describe();
    EXPECT_EQ(contents(out / (std::string(name) + ".html")), contents(dir / (std::string(name) + ".html"))) << name;
  }
  // Chapters at the landing (0.38 s: 0.7 m of fall) and the next bounce, 0.5 s or more later.
  const std::string chapters = contents(out / "drop.chapters.vtt");
  EXPECT_NE(chapters.find("Start\n"), std::string::npos) << chapters;
  EXPECT_NE(chapters.find("Impact at t = 0.38 s\n"), std::string::npos) << chapters;
  std::ofstream(out / "check.html") << kCheckPage;

  const int port = free_port();
  testing::ChildProcess server({"/usr/bin/python3", "-m", "http.server", std::to_string(port), "--bind", "127.0.0.1",
                                "--directory", out.string()});
  for (int tries = 0; tries < 100 && !accepts(port); ++tries) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(accepts(port)) << "the static server did not start";
  const std::string url = "http://127.0.0.1:" + std::to_string(port) + "/check.html";
  const testing::ChildResult browser = testing::run_child(
      {"/bin/sh", "-c",
       "timeout 120 chromium --headless --no-sandbox --disable-gpu --user-data-dir='" + (dir / "profile").string() +
           "' --virtual-time-budget=30000 --dump-dom '" + url + "' > '" + (dir / "dom.html").string() + "'"});
  ASSERT_TRUE(browser.succeeded()) << browser.describe();
  const std::string dom = contents(dir / "dom.html");
  ASSERT_NE(dom.find("DONE"), std::string::npos) << dom;

  std::map<std::string, std::vector<double>> seen;  // file -> duration, width, height, error, loaded, tracks
  const std::regex line(R"(VIDEO (\S+) (\S+) (\d+) (\d+) (\d+) (\d+) (\d+))");
  for (std::sregex_iterator it(dom.begin(), dom.end(), line), end; it != end; ++it)
    seen[(*it)[1]] = {std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4]), std::stod((*it)[5]),
                      std::stod((*it)[6]), std::stod((*it)[7])};
  ASSERT_EQ(seen.size(), 2u) << dom;
  for (const char* name : {"drop.mp4", "pair.mp4"}) {
    SCOPED_TRACE(name);
    ASSERT_EQ(seen.count(name), 1u) << dom;
    const std::vector<double>& browser_saw = seen[name];
    const testing::DecodedVideo decoded = testing::decode_video((out / name).string());
    EXPECT_EQ(browser_saw[3], 0) << "the browser's media error code";
    EXPECT_NEAR(browser_saw[0], decoded.frames.size() / decoded.fps, 1.5 / decoded.fps) << "s";
    EXPECT_EQ(browser_saw[1], decoded.width);
    EXPECT_EQ(browser_saw[2], decoded.height);
    EXPECT_EQ(browser_saw[5], 2) << "a captions and a chapters track";
    EXPECT_EQ(browser_saw[4], browser_saw[5]) << "tracks loaded";
  }
}

}  // namespace
}  // namespace impulse
