// Overlaps drawing with everything after it: the caller draws frames on its thread while a
// worker thread finishes each one (overlay, PNG, encoder). A fixed number of frame slots cycle
// between the two, so memory stays the same however long the video is.
//
//   FramePipeline pipeline(3, [&](FrameJob& job) { paint, write, encode... });
//   FrameJob& job = pipeline.acquire();   // waits for a free slot
//   ... fill job.frame, job.overlay ...
//   pipeline.submit();                    // the worker takes it, in order
//   pipeline.finish();                    // waits for the worker to finish every frame
//
// An exception in the worker stops it; the next acquire() or finish() rethrows it.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "demos/film/scene_draw_list.h"
#include "render/frame.h"
#include "render/read_back.h"
#include "render/overlay.h"

namespace impulse::demos {

struct FrameJob {
  int64_t index = 0;  // frames are numbered from 0 in submission order
  render::Frame frame;
  // With `drawn_unfinished`, the image as read back (Renderer::draw_into), which the worker
  // finishes into `frame` first (render::finish): the drawing thread goes on to the next frame.
  render::ReadBack drawn;
  bool drawn_unfinished = false;
  render::Overlay overlay;
  int video_frame = -1;               // the video's frame number; -1: a still (scene_film.h, Shots)
  double time = 0;                    // simulated s shown
  std::vector<BodyPose> poses;        // a still's bodies
};

class FramePipeline {
 public:
  using Worker = std::function<void(FrameJob&)>;

  FramePipeline(int slot_count, Worker worker);
  ~FramePipeline();  // stops the worker; frames not yet finished are dropped
  FramePipeline(const FramePipeline&) = delete;
  FramePipeline& operator=(const FramePipeline&) = delete;

  FrameJob& acquire();  // the slot to fill next; waits while all are busy
  void submit();        // hands the acquired slot to the worker
  void finish();        // waits until the worker has finished every submitted frame


 private:
  void run();
  void rethrow_worker_error();  // with the lock held

  Worker worker_;
  std::vector<FrameJob> slots_;
  std::deque<FrameJob*> free_;
  std::deque<FrameJob*> ready_;
  FrameJob* acquired_ = nullptr;
  int64_t next_index_ = 0;
  int busy_ = 0;  // taken by the worker and not yet returned
  bool stopping_ = false;
  std::exception_ptr worker_error_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::thread thread_;  // last: started once everything above exists
};

}  // namespace impulse::demos
