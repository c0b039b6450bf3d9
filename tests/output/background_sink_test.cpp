// BackgroundSink: every record reaches the sink, in order, across batches and a full queue;
// an exception the sink throws comes back from finish().

#include "deploydyn/output/background_sink.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

class SlowCollector final : public RecordSink {
 public:
  void record(const StepRecord& r) override {
    if (++calls % 500 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    times.push_back(r.time_s);
  }
  std::atomic<int> calls{0};
  std::vector<double> times;
};

StepRecord record_at(double t) {
  StepRecord r;
  r.time_s = t;
  r.q = Eigen::VectorXd::Constant(3, t);
  return r;
}

TEST(BackgroundSink, DeliversEveryRecordInOrder) {
  SlowCollector collector;
  BackgroundSink sink(collector);
  constexpr int kRecords = 5000;  // several batches, and more than the queue holds
  for (int i = 0; i < kRecords; ++i) sink.record(record_at(i));
  sink.finish();
  ASSERT_EQ(collector.times.size(), static_cast<std::size_t>(kRecords));
  for (int i = 0; i < kRecords; ++i) EXPECT_EQ(collector.times[i], i);
}

TEST(BackgroundSink, ASingleRecordArrivesWithoutWaitingForABatch) {
  SlowCollector collector;
  BackgroundSink sink(collector);
  sink.record(record_at(1.0));
  // The writer wakes at least every 100 ms: a slow run's record is written long before the
  // run ends, not only when a batch is full or at finish().
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_EQ(collector.calls, 1);
  sink.record(record_at(2.0));
  sink.finish();
  EXPECT_EQ(collector.times, (std::vector<double>{1.0, 2.0}));
}

class FailingSink final : public RecordSink {
 public:
  void record(const StepRecord& r) override {
    if (r.time_s >= 10.0) throw std::runtime_error("disk full");
  }
};

TEST(BackgroundSink, FinishRethrowsWhatTheSinkThrew) {
  FailingSink failing;
  BackgroundSink sink(failing);
  for (int i = 0; i < 3000; ++i) sink.record(record_at(i));  // goes on after the failure
  EXPECT_THROW(
      {
        try {
          sink.finish();
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "disk full");
          throw;
        }
      },
      std::runtime_error);
}

// A run whose records are built on the writer thread (record_state) gives the records built on
// the solver's: same values, same order.
TEST(BackgroundSink, RecordsBuiltOnTheWriterThreadAreTheSolversOwn) {
  const Model model = load_model(std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper/general.yaml",
                                 {parse_override("analysis.end=0.5")});
  const Assembler assembler(model);
  testing::RecordCollector direct, through_thread;
  ASSERT_EQ(run_analysis(assembler, direct).status, RunStatus::completed);
  {
    BackgroundSink sink(through_thread);
    ASSERT_EQ(run_analysis(assembler, sink).status, RunStatus::completed);
    sink.finish();
  }
  ASSERT_EQ(through_thread.records.size(), direct.records.size());
  for (std::size_t r = 0; r < direct.records.size(); ++r) {
    const StepRecord& a = direct.records[r];
    const StepRecord& b = through_thread.records[r];
    EXPECT_EQ(a.time_s, b.time_s);
    EXPECT_EQ(a.q, b.q);
    EXPECT_EQ(a.driver_efforts, b.driver_efforts);
    EXPECT_EQ(a.external_work_J, b.external_work_J);
    ASSERT_EQ(bar_results(a).size(), bar_results(b).size());
    for (std::size_t k = 0; k < bar_results(a).size(); ++k) EXPECT_EQ(bar_results(a)[k].axial_force_N, bar_results(b)[k].axial_force_N);
  }
}

}  // namespace
}  // namespace deploydyn
