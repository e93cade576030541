// The frame pipeline (demos/film/frame_pipeline.h): the worker finishes frames in the order they
// were submitted, on a thread of its own, with never more frames in flight than slots; its
// error comes back to the drawing thread; misuse is refused. Run under ThreadSanitizer too.
#include "demos/film/frame_pipeline.h"

#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace impulse::demos {
namespace {

TEST(FramePipeline, FinishesEveryFrameInOrderOnItsOwnThreadWithinItsSlots) {
  constexpr int kSlots = 3;
  std::vector<int64_t> finished;
  std::vector<int> times;
  std::set<const FrameJob*> slots;
  std::atomic<int> in_flight{0};
  int most_in_flight = 0;  // written by the worker only, read after finish()
  std::thread::id worker_thread;
  FramePipeline pipeline(kSlots, [&](FrameJob& job) {
    worker_thread = std::this_thread::get_id();
    most_in_flight = std::max(most_in_flight, in_flight.load());
    finished.push_back(job.index);
    times.push_back(int(job.time));
    slots.insert(&job);
    --in_flight;
  });
  for (int frame = 0; frame < 100; ++frame) {
    FrameJob& job = pipeline.acquire();
    ++in_flight;
    job.time = frame;
    pipeline.submit();
  }
  pipeline.finish();
  ASSERT_EQ(finished.size(), 100u);
  for (int frame = 0; frame < 100; ++frame) {
    EXPECT_EQ(finished[frame], frame);
    EXPECT_EQ(times[frame], frame);
  }
  EXPECT_NE(worker_thread, std::this_thread::get_id());
  EXPECT_LE(most_in_flight, kSlots);
  EXPECT_LE(slots.size(), size_t(kSlots));  // the slots cycle: memory stays the same
}

TEST(FramePipeline, AWorkersErrorComesBackToTheDrawingThread) {
  FramePipeline pipeline(2, [](FrameJob& job) {
    if (job.index == 3) throw std::runtime_error("the encoder failed on frame 3");
  });
  bool thrown = false;
  try {
    for (int frame = 0; frame < 1000; ++frame) {  // acquire() rethrows once the worker has failed
      pipeline.acquire();
      pipeline.submit();
    }
    pipeline.finish();
  } catch (const std::runtime_error& error) {
    thrown = true;
    EXPECT_STREQ(error.what(), "the encoder failed on frame 3");
  }
  EXPECT_TRUE(thrown);
}

TEST(FramePipeline, AcquireTwiceOrSubmitWithoutAcquireIsRefused) {
  FramePipeline pipeline(2, [](FrameJob&) {});
  EXPECT_THROW(pipeline.submit(), std::logic_error);
  pipeline.acquire();
  EXPECT_THROW(pipeline.acquire(), std::logic_error);
  pipeline.submit();
  pipeline.finish();
}

}  // namespace
}  // namespace impulse::demos
