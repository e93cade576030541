#include "demos/film/frame_pipeline.h"

#include <stdexcept>

namespace impulse::demos {

FramePipeline::FramePipeline(int slot_count, Worker worker)
    : worker_(std::move(worker)), slots_(static_cast<size_t>(slot_count < 1 ? 1 : slot_count)) {
  for (FrameJob& slot : slots_) free_.push_back(&slot);
  thread_ = std::thread([this] { run(); });
}

FramePipeline::~FramePipeline() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void FramePipeline::rethrow_worker_error() {
  if (worker_error_) std::rethrow_exception(worker_error_);
}

FrameJob& FramePipeline::acquire() {
  std::unique_lock lock(mutex_);
  if (acquired_ != nullptr) throw std::logic_error("FramePipeline: acquire() twice without submit()");
  changed_.wait(lock, [&] { return !free_.empty() || worker_error_; });
  rethrow_worker_error();
  acquired_ = free_.front();
  free_.pop_front();
  acquired_->index = next_index_++;
  return *acquired_;
}

void FramePipeline::submit() {
  {
    std::lock_guard lock(mutex_);
    if (acquired_ == nullptr) throw std::logic_error("FramePipeline: submit() without acquire()");
    ready_.push_back(acquired_);
    acquired_ = nullptr;
  }
  changed_.notify_all();
}

void FramePipeline::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return (ready_.empty() && busy_ == 0) || worker_error_; });
  rethrow_worker_error();
}

void FramePipeline::run() {
  std::unique_lock lock(mutex_);
  while (true) {
      changed_.wait(lock, [&] { return !ready_.empty() || stopping_; });
    if (stopping_ || worker_error_) return;
    FrameJob* job = ready_.front();
    ready_.pop_front();
    ++busy_;
    lock.unlock();
    std::exception_ptr error;
    try {
      worker_(*job);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    --busy_;
    free_.push_back(job);
    if (error) worker_error_ = error;
    changed_.notify_all();
    if (worker_error_) return;
  }
}

}  // namespace impulse::demos
