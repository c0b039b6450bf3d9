#pragma once
// Hands records to another sink on a thread of its own, so that building, formatting and
// writing the results (StepRecords, history.csv, VTK frames) overlap the solver instead of
// adding to it. Records keep
// their order; finish() waits until all are written and rethrows what the sink threw.
// The queue is bounded: a solver faster than the disk waits rather than filling memory.
// Nothing is allocated per step once the queue has grown: its slots (states, records) are
// reused, the solver filling one batch while the writer empties the other, and the writer
// builds each step's record into the same StepRecord.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn {

class BackgroundSink final : public RecordSink {
 public:
  explicit BackgroundSink(RecordSink& sink);
  ~BackgroundSink() override;  // finishes, dropping any exception: call finish() to see it
  BackgroundSink(const BackgroundSink&) = delete;
  BackgroundSink& operator=(const BackgroundSink&) = delete;

  void record(const StepRecord& record) override;
  // Queues a copy of the state; the record is built on the writer thread.
  void record_state(const Assembler& assembler, const MotionState& state,
                    const WorkTally& work, bool output = true) override;
  bool wants_every_step() const override { return sink_.wants_every_step(); }
  // Waits until every record has reached the sink; rethrows the first exception it threw.
  void finish();
  // True once the sink has thrown: the records since are dropped. Any thread may ask.
  bool failed() const { return failed_.load(std::memory_order_relaxed); }

 private:
  // A record, or the state to build it from. Slots are reused: each keeps its storage.
  struct Item {
    bool is_record = false;  // `record` given whole, else built from the state below
    StepRecord record;
    const Assembler* assembler = nullptr;
    MotionState state;
    WorkTally work;
    bool output = true;
  };

  // The next free slot of the queue, once there is room (false: the sink failed). With the
  // lock held.
  Item* next_slot(std::unique_lock<std::mutex>& lock);
  // Counts the filled slot in, waking the writer once per batch. With the lock held.
  void queued();
  void work();

  static constexpr std::size_t kBatch = 64;        // records per wake-up of the writer
  // The solver waits beyond this. The slots stay allocated until the run ends: 256 of them keep
  // the queue's memory small (a four-bar: ~0.2 MB) and the writer busy.
  static constexpr std::size_t kMaxQueued = 256;
  static constexpr std::chrono::milliseconds kLongestWait{100};
  RecordSink& sink_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<Item> queue_;  // slots [0, n_queued_) hold what the writer has not taken
  std::size_t n_queued_ = 0;
  bool closing_ = false;
  std::exception_ptr error_;
  std::atomic<bool> failed_{false};
  std::thread worker_;
};

}  // namespace deploydyn
