#include "demos/render_scene.h"

#include "demos/camera_path.h"
#include "demos/contact_hold.h"
#include "demos/frame_overlay.h"
#include "demos/marks.h"
#include "demos/playback_timeline.h"
#include "demos/plot_recorder.h"
#include "demos/progress_bar.h"
#include "demos/scene_draw_list.h"
#include "demos/scene_preview.h"
#include "render/frame_pipeline.h"
#include "render/overlay_painter.h"
#include "render/png_io.h"
#include "render/video_encoder.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace impulse::demos {

namespace {

constexpr int kFramesInFlight = 3;  // drawn, being finished, waiting: enough to keep both busy

std::string frame_file(const std::string& directory, int64_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05lld.png", static_cast<long long>(index));
  return (std::filesystem::path(directory) / name).string();
}

bool wants_png(const RenderOptions& options, int64_t index) {
  if (options.png_directory.empty()) return false;
  return options.png_frames.empty() ||
         std::find(options.png_frames.begin(), options.png_frames.end(), index) != options.png_frames.end();
}

}  // namespace

physics::World build_world(const Scene& scene) {
  physics::World world(scene.world);
  for (const physics::BodyDef& def : scene.bodies) world.add_body(def);
  for (const physics::JointDef& def : scene.joints) world.add_joint(def);  // by index into bodies
  return world;
}

render::DrawList make_draw_list(const Scene& scene, const physics::World& world, const physics::StepRecord& record) {
  return scene_draw_list(scene, world.bodies(), poses_of(world.bodies()), world.joints(), record.contacts,
                         arrow_scales(scene, ScenePreview{}), scene.camera);
}

void render_scene(const Scene& scene, const RenderOptions& options) {
  const render::VideoSettings& video = scene.video;
  const ScenePreview preview = preview_scene(scene);
  const ArrowScales scales = arrow_scales(scene, preview);
  const PlaybackTimeline timeline(scene.playback, preview.impact_times, scene.duration, video.fps);

  physics::World world = build_world(scene);
  const double step = scene.world.time_step;
  render::Renderer renderer(video.width, video.height, options.renderer);
  std::unique_ptr<render::VideoEncoder> encoder;
  if (!options.video_path.empty()) encoder = std::make_unique<render::VideoEncoder>(options.video_path, video);
  if (!options.png_directory.empty()) std::filesystem::create_directories(options.png_directory);

  PlotRecorder plots(scene.overlay.plots, plotted_body(world.bodies(), scene.overlay.plot_body));
  ContactHold hold(scene.draw.contact_hold);
  CameraPath camera_path(scene);
  const FrameOverlay overlay_maker(scene, preview, scales, video.width, video.height);
  ProgressBar progress(options.progress, scene.path, timeline.frame_count());

  // The worker finishes frames in order: overlay, PNG, encoder. Declared after the encoder, so
  // it stops before the encoder (and its .part file) goes.
  render::OverlayPainter painter(video.width, video.height);
  std::atomic<int> frames_finished{0};
  render::FramePipeline pipeline(kFramesInFlight, [&](render::FrameJob& job) {
    painter.paint(job.overlay, job.frame);
    if (wants_png(options, job.index)) render::write_png(frame_file(options.png_directory, job.index), job.frame);
    if (encoder) encoder->add_frame(job.frame);
    ++frames_finished;
  });

  std::vector<BodyPose> before = poses_of(world.bodies()), after = before, shown;
  double time = 0;
  for (int frame = 0; frame < timeline.frame_count(); ++frame) {
    const double video_time = double(frame) / video.fps;
    // Step until the world is at or past this frame's moment; draw the bodies in between.
    while (world.time() < time - 1e-9) {
      before.swap(after);
      const physics::StepRecord& record = world.step();
      after = poses_of(world.bodies());
      hold.add_step(record, video_time);
      plots.add_step(record, world.bodies());
    }
    const double weight = world.step_count() == 0 ? 1.0 : std::clamp(1.0 - (world.time() - time) / step, 0.0, 1.0);
    interpolate(before, after, weight, shown);

    const int followed = camera_path.followed_body();
    FrameState state;
    state.time = time;
    state.speed = timeline.speed_at(time);
    state.slow_motion = timeline.slow_motion_at(time);
    state.bodies = &world.bodies();
    state.poses = &shown;
    state.contacts = &hold.shown(video_time);
    state.camera = camera_path.at(time, followed >= 0 ? shown[followed].position : physics::Vec3::Zero());

    render::FrameJob& job = pipeline.acquire();
    renderer.draw_into(scene_draw_list(scene, world.bodies(), shown, world.joints(), *state.contacts, scales, state.camera),
                       job.frame);
    overlay_maker.make(state, plots, job.overlay);
    pipeline.submit();
    progress.update(frames_finished);
    time = timeline.next_frame_time(time);
  }
  pipeline.finish();
  progress.finish();
  if (encoder) encoder->finish();
}

}  // namespace impulse::demos
