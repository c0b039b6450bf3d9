#include "deploydyn/output/background_sink.hpp"

#include <utility>

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
  Item* const item = next_slot(lock);
  if (item == nullptr) return;
  item->is_record = true;
  item->record = record;
  queued();
}

void BackgroundSink::record_state(const Assembler& assembler, const MotionState& state,
                                  const WorkTally& work, bool output) {
  if (!output && !wants_every_step()) return;
  std::unique_lock lock(mutex_);
  Item* const item = next_slot(lock);
  if (item == nullptr) return;
  // Only what a record needs: not the accelerations. Copied into the slot's own storage.
  item->is_record = false;
  item->assembler = &assembler;
  item->state.time_s = state.time_s;
  item->state.q = state.q;
  item->state.v = state.v;
  item->state.lambda = state.lambda;
  item->state.history = state.history;
  item->work = work;
  item->output = output;
  queued();
}

BackgroundSink::Item* BackgroundSink::next_slot(std::unique_lock<std::mutex>& lock) {
  if (n_queued_ >= kMaxQueued) {
    changed_.notify_all();
    changed_.wait(lock, [this] { return n_queued_ < kMaxQueued || error_ != nullptr; });
  }
  if (error_ != nullptr) return nullptr;  // the sink failed; finish() reports it
  if (n_queued_ == queue_.size()) queue_.emplace_back();
  return &queue_[n_queued_];
}

void BackgroundSink::queued() {
  ++n_queued_;
  // Waking the writer costs a context switch: do it once per batch, not per record.
  if (n_queued_ == kBatch) changed_.notify_all();
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
  std::vector<Item> batch;  // the slots taken from the queue; given back, storage and all
  StepRecord built;         // each state's record, built into the same storage
  for (;;) {
    std::size_t n_batch = 0;
    {
      std::unique_lock lock(mutex_);
      // A batch, or whatever came within the wait: slow runs still reach the disk promptly.
      changed_.wait_for(lock, kLongestWait, [this] { return n_queued_ >= kBatch || closing_; });
      if (n_queued_ == 0 && closing_) return;
      batch.swap(queue_);
      n_batch = std::exchange(n_queued_, 0);
      changed_.notify_all();  // room again for a waiting solver
    }
    try {
      for (std::size_t i = 0; i < n_batch; ++i) {
        const Item& item = batch[i];
        if (item.is_record) {
          sink_.record(item.record);
        } else {
          fill_step_record(*item.assembler, item.state, item.work, item.output, built);
          sink_.record(built);
        }
      }
    } catch (...) {
      std::lock_guard lock(mutex_);
      error_ = std::current_exception();
      failed_.store(true);
      n_queued_ = 0;
      changed_.notify_all();
      return;
    }
  }
}

}  // namespace deploydyn
