#pragma once
// Hands records to another sink on a thread of its own, so that building, formatting and
// writing the results (StepRecords, history.csv, VTK frames) overlap the solver instead of
// adding to it. Records keep
// their order; finish() waits until all are written and rethrows what the sink threw.
// The queue is bounded: a solver faster than the disk waits rather than filling memory.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <variant>

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
  // A record, or the state to build it from.
  struct Snapshot {
    const Assembler* assembler = nullptr;
    MotionState state;
    WorkTally work;
    bool output = true;
  };
  using Item = std::variant<StepRecord, Snapshot>;

  void push(Item item);
  void work();

  static constexpr std::size_t kBatch = 64;        // records per wake-up of the writer
  static constexpr std::size_t kMaxQueued = 1024;  // the solver waits beyond this
  static constexpr std::chrono::milliseconds kLongestWait{100};
  RecordSink& sink_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Item> queue_;
  bool closing_ = false;
  std::exception_ptr error_;
  std::atomic<bool> failed_{false};
  std::thread worker_;
};

}  // namespace deploydyn
