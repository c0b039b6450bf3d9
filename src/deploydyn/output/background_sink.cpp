#include "deploydyn/output/background_sink.hpp"

namespace deploydyn {

BackgroundSink::BackgroundSink(RecordSink& sink) : sink_(sink), worker_([this] { work(); }) {}

BackgroundSink::~BackgroundSink() {
  try {
    finish();
  } catch (...) {
    // finish() was not called by the owner: nothing left to report to.
  }
}

void BackgroundSink::record(const StepRecord& record) {
  std::unique_lock lock(mutex_);
  if (queue_.size() >= kMaxQueued) {
    changed_.notify_all();
    changed_.wait(lock, [this] { return queue_.size() < kMaxQueued || error_ != nullptr; });
  }
  if (error_ != nullptr) return;  // the sink failed; finish() reports it
  queue_.push_back(record);
  // Waking the writer costs a context switch: do it once per batch, not per record.
  if (queue_.size() == kBatch) changed_.notify_all();
}

void BackgroundSink::finish() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  if (worker_.joinable()) worker_.join();
  if (error_ != nullptr) std::rethrow_exception(std::exchange(error_, nullptr));
}

void BackgroundSink::work() {
  std::deque<StepRecord> batch;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      // A batch, or whatever came within the wait: slow runs still reach the disk promptly.
      changed_.wait_for(lock, kLongestWait, [this] { return queue_.size() >= kBatch || closing_; });
      if (queue_.empty() && closing_) return;
      batch.swap(queue_);
      changed_.notify_all();  // room again for a waiting solver
    }
    try {
      for (const StepRecord& record : batch) sink_.record(record);
    } catch (...) {
      std::lock_guard lock(mutex_);
      error_ = std::current_exception();
      queue_.clear();
      changed_.notify_all();
      return;
    }
    batch.clear();
  }
}

}  // namespace deploydyn
