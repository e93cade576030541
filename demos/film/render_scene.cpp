#include "demos/film/render_scene.h"

#include "demos/film/marks.h"
#include "demos/film/moments.h"
#include "demos/film/render_types.h"
#include "demos/film/scene_draw_list.h"
#include "demos/film/film.h"
#include "demos/film/frame_pipeline.h"
#include "demos/film/handoff_queue.h"
#include "demos/film/layout_report.h"
#include "render/overlay_painter.h"
#include "render/part_file.h"
#include "render/png_io.h"
#include "render/video_encoder.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

namespace impulse::demos {

namespace {

constexpr int kFramesInFlight = 3;  // drawn, being finished, waiting: enough to keep both busy
constexpr size_t kPicturesAhead = 2;  // pictures made ahead of the drawing
const render::Colour kBetweenPanes{0.93f, 0.93f, 0.94f};

bool wants_png(const RenderOptions& options, int64_t index, int frame_count) {
  if (options.png_directory.empty()) return false;
  if (options.png_frames.empty() && options.png_spread > 1) {
    for (int k = 0; k < options.png_spread; ++k)
      if (index == int64_t(k) * (frame_count - 1) / (options.png_spread - 1)) return true;
    return false;
  }
  if (options.png_frames.empty()) return options.moments.empty() && !options.moments_at_impacts;  // all, unless stills
  return std::find(options.png_frames.begin(), options.png_frames.end(), index) != options.png_frames.end();
}

}  // namespace

std::string captions_path(const std::string& video_path) {
  return std::filesystem::path(video_path).replace_extension(".vtt").string();
}

std::string poster_path(const std::string& video_path) {
  return std::filesystem::path(video_path).replace_extension(".png").string();
}

namespace {

std::string vtt_time(double seconds) {
  const long long millis = std::llround(std::max(seconds, 0.0) * 1000);
  char text[32];
  std::snprintf(text, sizeof text, "%02lld:%02lld:%02lld.%03lld", millis / 3600000, millis / 60000 % 60,
                millis / 1000 % 60, millis % 1000);
  return text;
}

// WebVTT: each [[caption]] as a cue in video time (slow motion stretches it), written to its own
// temporary and renamed when complete.
void write_captions(const Scene& scene, const Film& film, const std::string& path) {
  render::PartFile part(path);
  {
    std::ofstream file(part.part_path());
    file << "WEBVTT\n";
    int cue = 0;
    for (const CaptionCue& caption : scene.captions) {
      const double start = film.video_time_of(caption.start), end = film.video_time_of(caption.end);
      if (!(end > start)) continue;
      file << "\n" << ++cue << "\n" << vtt_time(start) << " --> " << vtt_time(end) << "\n" << caption.text << "\n";
    }
    file.close();
    if (!file) throw render::OutputError("cannot write " + part.part_path());
  }
  part.commit();
}

}  // namespace

std::string chapters_path(const std::string& video_path) {
  return std::filesystem::path(video_path).replace_extension(".chapters.vtt").string();
}

namespace {

// WebVTT chapters (a player's chapter menu): one at the start, and one at each impact that slows
// the video, impacts within kChapterGap s after one joining its chapter; or, without such
// impacts, one at each caption (a caption at the start names the first chapter). Returns false
// (and writes nothing) when there is neither an impact nor a caption.
constexpr double kChapterGap = 0.5;

bool write_chapters(const Scene& scene, const Film& film, const std::string& path) {
  std::vector<std::pair<double, std::string>> starts{{0.0, "Start"}};  // simulated s, title
  double last_impact = -kChapterGap;
  for (const double time : film.impact_times()) {
    if (time - last_impact < kChapterGap || time < 1e-3) continue;
    last_impact = time;
    char title[48];
    std::snprintf(title, sizeof title, "Impact at t = %.2f s", time);
    starts.emplace_back(time, title);
  }
  bool named = starts.size() > 1;
  if (!named) {
    for (const CaptionCue& caption : scene.captions) {
      if (caption.start < 1e-9 && !named) starts.front().second = caption.text;
      else if (caption.start > starts.back().first) starts.emplace_back(caption.start, caption.text);
      named = true;
    }
  }
  if (!named) return false;
  render::PartFile part(path);
  {
    std::ofstream file(part.part_path());
    file << "WEBVTT\n";
    const double end = film.video_time_of(1e300);
    for (size_t i = 0; i < starts.size(); ++i) {
      const double from = film.video_time_of(starts[i].first);
      const double to = i + 1 < starts.size() ? film.video_time_of(starts[i + 1].first) : end;
      if (!(to > from)) continue;
      file << "\n" << i + 1 << "\n" << vtt_time(from) << " --> " << vtt_time(to) << "\n" << starts[i].second << "\n";
    }
    file.close();
    if (!file) throw render::OutputError("cannot write " + part.part_path());
  }
  part.commit();
  return true;
}

}  // namespace

std::string frame_file(const std::string& directory, int64_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05lld.png", static_cast<long long>(index));
  return (std::filesystem::path(directory) / name).string();
}

std::string still_file(const std::string& directory, double time) {
  return (std::filesystem::path(directory) / (moment_name(time) + ".png")).string();
}

render::DrawList make_draw_list(const Scene& scene, const physics::World& world, const physics::StepRecord& record) {
  return scene_draw_list(scene, world.bodies(), poses_of(world.bodies()), world.joints(), record.contacts,
                         arrow_scales(scene, TakeSummary{}), to_render(scene.camera));
}

std::vector<CheckResult> render_scene(const Scene& scene, const RenderOptions& options) {
  return render_panes({{&scene, ""}}, options).front();
}

namespace {

// The video records the settings that changed each pane's scene.
std::string settings_comment(const std::vector<Pane>& panes) {
  std::string comment;
  for (size_t i = 0; i < panes.size(); ++i) {
    if (panes[i].scene->settings.empty()) continue;
    if (!comment.empty()) comment += "; ";
    if (panes.size() > 1) comment += "pane " + std::to_string(i + 1) + ":";
    for (const std::string& setting : panes[i].scene->settings) comment.append(comment.empty() ? "" : " ").append("--set ").append(setting);
  }
  return comment;
}

}  // namespace

// The film steps every world to its end first (one sample a frame kept). Then three threads, each
// a stage: what each frame shows (draw lists, overlay) is made ahead on its own thread; this
// thread draws (with llvmpipe's threads); a worker paints the overlay and encodes. Bounded queues
// between them keep the frames in flight few whatever the video's length.
std::vector<std::vector<CheckResult>> render_panes(const std::vector<Pane>& panes, const RenderOptions& options) {
  const Scene& scene = *panes.at(0).scene;  // sets the video, the captions and the frame's overlay
  render::VideoSettings video = to_render(scene.video);
  video.format = options.video_format;
  video.alpha = options.renderer.transparent;
  video.comment = settings_comment(panes);
  // The output first: a path that cannot be written is refused before any simulation.
  std::unique_ptr<render::VideoEncoder> encoder;
  if (!options.video_path.empty()) encoder = std::make_unique<render::VideoEncoder>(options.video_path, video);
  std::unique_ptr<LayoutReport> layout_report;
  if (!options.layout_report_path.empty())
    layout_report = std::make_unique<LayoutReport>(options.layout_report_path, video.width, video.height);
  Shots shots;
  shots.stills = options.moments;
  shots.stills_at_impacts = options.moments_at_impacts;
  const bool stills_only = !shots.stills.empty() || shots.stills_at_impacts;
  shots.video_frames = encoder || layout_report || !options.poster_path.empty() ||
                       (!options.png_directory.empty() && (!stills_only || !options.png_frames.empty() || options.png_spread > 1));
  // (without a video, poster or frame PNGs, the frames are simulated but not drawn)
  Film film(panes, video.width, video.height, shots);
  const PaneLayout& layout = film.layout();
  render::Renderer renderer(layout.width, layout.height, options.renderer);
  if (!options.png_directory.empty()) std::filesystem::create_directories(options.png_directory);
  const int poster = film.poster_frame();

  // The worker finishes frames in order: overlay, PNG, encoder. Declared after the encoder, so
  // it stops before the encoder (and its .part file) goes.
  render::OverlayPainter painter(video.width, video.height);
  std::atomic<int> frames_finished{0};
  render::Frame poster_frame;  // kept until the video is complete: a poster only ever sits beside its video
  FramePipeline pipeline(kFramesInFlight, [&](FrameJob& job) {
    if (job.drawn_unfinished) render::finish(job.drawn, job.frame);
    painter.paint(job.overlay, job.frame);
    if (options.renderer.transparent) render::unpremultiply(job.frame);
    if (job.video_frame < 0) {  // a still
      if (!options.png_directory.empty()) render::write_png(still_file(options.png_directory, job.time), job.frame);
      if (options.on_still) options.on_still(job.time, job.frame, job.poses);
      ++frames_finished;
      return;
    }
    if (layout_report) layout_report->add(job.video_frame, painter.layout(), job.overlay.bodies);
    if (wants_png(options, job.video_frame, film.frame_count()))
      render::write_png(frame_file(options.png_directory, job.video_frame), job.frame);
    if (!options.poster_path.empty() && job.video_frame == poster) poster_frame = job.frame;
    if (encoder) encoder->add_frame(job.frame);
    ++frames_finished;
  });

  HandoffQueue<FilmPicture> pictures(kPicturesAhead);
  std::thread picturing([&] {
    try {
      while (film.next_frame() < film.picture_count()) {
        FilmPicture picture;
        film.next(picture);
        if (!pictures.push(std::move(picture))) return;  // the drawing stopped
      }
      pictures.close();
    } catch (...) {
      pictures.fail(std::current_exception());
    }
  });
  // However this function ends, the picturing stops before the film it reads goes.
  struct StopPicturing {
    HandoffQueue<FilmPicture>& pictures;
    std::thread& thread;
    ~StopPicturing() {
      pictures.close();
      thread.join();
    }
  } stop{pictures, picturing};

  render::Frame pane_frame;
  while (std::optional<FilmPicture> picture = pictures.pop()) {
    FrameJob& job = pipeline.acquire();
    job.drawn_unfinished = picture->panes.size() == 1;
    if (job.drawn_unfinished) {
      renderer.draw_into(picture->panes.front(), job.drawn);
    } else {
      render::fill(job.frame, video.width, video.height, kBetweenPanes, options.renderer.transparent ? 0.0f : 1.0f);
      for (size_t i = 0; i < picture->panes.size(); ++i) {
        renderer.draw_into(picture->panes[i], pane_frame);
        render::paste(pane_frame, layout.origins[i].x(), layout.origins[i].y(), job.frame);
      }
    }
    job.overlay = std::move(picture->overlay);
    job.video_frame = picture->frame;
    job.time = picture->time;
    job.poses = std::move(picture->poses);
    pipeline.submit();
    if (options.progress) options.progress(frames_finished, film.picture_count());
  }
  pipeline.finish();
  if (options.progress) options.progress(film.picture_count(), film.picture_count());  // every frame finished
  if (encoder) encoder->finish();
  if (layout_report) layout_report->commit();
  if (encoder && !scene.captions.empty()) write_captions(scene, film, captions_path(options.video_path));
  if (encoder) write_chapters(scene, film, chapters_path(options.video_path));
  if (!options.poster_path.empty() && !poster_frame.rgba.empty()) render::write_png(options.poster_path, poster_frame);
  if (options.on_warning)
    for (const auto& [p, q] : film.identical_panes())
      options.on_warning("panes " + std::to_string(p + 1) + " (" + panes[p].label + ") and " + std::to_string(q + 1) + " (" +
                         panes[q].label + ") moved alike, step for step: what differs between them changes nothing in this "
                         "scene; vary something the bodies feel here");
  return film.check_results();
}

}  // namespace impulse::demos
