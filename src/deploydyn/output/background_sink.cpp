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

void BackgroundSink::record(const StepRecord& record) { push(record); }

void BackgroundSink::record_state(const Assembler& assembler, const MotionState& state,
                                  const WorkTally& work, bool output) {
  if (!output && !wants_every_step()) return;
  // Only what a record needs: not the accelerations.
  Snapshot snapshot{&assembler, {}, work, output};
  snapshot.state.time_s = state.time_s;
  snapshot.state.q = state.q;
  snapshot.state.v = state.v;
  snapshot.state.lambda = state.lambda;
  snapshot.state.history = state.history;
  push(std::move(snapshot));
}

void BackgroundSink::push(Item item) {
  std::unique_lock lock(mutex_);
  if (queue_.size() >= kMaxQueued) {
    changed_.notify_all();
    changed_.wait(lock, [this] { return queue_.size() < kMaxQueued || error_ != nullptr; });
  }
  if (error_ != nullptr) return;  // the sink failed; finish() reports it
  queue_.push_back(std::move(item));
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
  std::deque<Item> batch;
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
      for (const Item& item : batch) {
        if (const auto* s = std::get_if<Snapshot>(&item)) {
          sink_.record(make_step_record(*s->assembler, s->state, s->work, s->output));
        } else {
          sink_.record(std::get<StepRecord>(item));
        }
      }
    } catch (...) {
      std::lock_guard lock(mutex_);
      error_ = std::current_exception();
      failed_.store(true);
      queue_.clear();
      changed_.notify_all();
      return;
    }
    batch.clear();
  }
}

}  // namespace deploydyn
