// side_by_side (util/side_by_side.hpp) offers its second piece to the calling thread's helper
// (util/helper_thread.hpp) and takes it back when the helper has not started it. Whoever runs
// it, each piece runs exactly once and its failure reaches the caller.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "deploydyn/util/helper_thread.hpp"
#include "deploydyn/util/run_threads.hpp"
#include "deploydyn/util/side_by_side.hpp"
#include "deploydyn/util/two_core_choice.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

TEST(SideBySide, EachPieceRunsOnceWhoeverRunsIt) {
  std::vector<int> first(20000, 0), second(20000, 0);
  for (std::size_t k = 0; k < first.size(); ++k) {
    side_by_side(true, [&] { ++first[k]; }, [&] { ++second[k]; });
  }
  for (std::size_t k = 0; k < first.size(); ++k) {
    ASSERT_EQ(first[k], 1) << k;
    ASSERT_EQ(second[k], 1) << k;
  }
}

TEST(SideBySide, LongPiecesRunOnBothCores) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one core";
  // A piece long enough that the helper wakes and takes it: in some of 50 calls the second piece
  // runs on another thread than the caller's.
  const std::thread::id caller = std::this_thread::get_id();
  int on_helper = 0;
  for (int k = 0; k < 50; ++k) {
    std::thread::id ran_on;
    side_by_side(
        true, [] { std::this_thread::sleep_for(std::chrono::milliseconds(2)); },
        [&] { ran_on = std::this_thread::get_id(); });
    on_helper += ran_on != caller;
  }
  EXPECT_GT(on_helper, 0);
}

TEST(SideBySide, FailuresReachTheCaller) {
  int ran = 0;
  EXPECT_THROW(side_by_side(
                   true, [&] { ++ran; }, [&]() -> void { throw std::runtime_error("second"); }),
               std::runtime_error);
  EXPECT_THROW(side_by_side(
                   true, [&]() -> void { throw std::invalid_argument("first"); }, [&] { ++ran; }),
               std::invalid_argument);
  EXPECT_EQ(ran, 2) << "the other piece still ran";
  // The helper serves the next call after a failure.
  int after = 0;
  side_by_side(true, [&] { ++after; }, [&] { ++after; });
  EXPECT_EQ(after, 2);
}

TEST(SideBySide, EveryThreadHasItsOwnHelper) {
  std::atomic<long> sum{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] {
      EXPECT_NE(&HelperThread::of_this_thread(), nullptr);
      for (int k = 0; k < 2000; ++k) side_by_side(true, [&] { sum += 1; }, [&] { sum += 2; });
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(sum.load(), 4L * 2000 * 3);
}

TEST(HelperThread, AnOwnerTakesBackWhatTheHelperHasNotStarted) {
  // A piece offered and closed at once: the helper, asleep, needs a wake-up of microseconds to
  // take it, so the owner takes most back and runs them itself instead of waiting. Each runs
  // once either way.
  HelperThread helper;
  int ran = 0, by_helper = 0;
  struct Count {
    int* ran;
    static void run(void* self) noexcept { ++*static_cast<Count*>(self)->ran; }
  } count{&ran};
  for (int k = 0; k < 1000; ++k) {
    helper.offer(&Count::run, &count);
    by_helper += helper.finish();
  }
  EXPECT_EQ(ran, 1000);
  EXPECT_LT(by_helper, 1000) << "the owner took back the pieces the helper had not started";
}

// TwoCoreChoice samples both ways, settles on the faster, tries the other one call in 64, and
// follows a change of load: here each way's wall time is given, two cores taking 3 ms against
// 1 ms on one core, then the reverse after 10 trial intervals.
TEST(TwoCoreChoice, SettlesOnTheFasterWayAndFollowsAChangeOfLoad) {
  TwoCoreChoice choice;
  constexpr long every = TwoCoreChoice::kTryOtherEvery;
  const long change = 10 * every, end = 20 * every;
  long two_before = 0, two_after_settling = 0;
  for (long k = 0; k < end; ++k) {
    const bool two = choice.next_is_two_cores();
    const bool loaded = k < change;  // two cores slower while another process holds a core
    choice.record(two, two == loaded ? 3e-3 : 1e-3);
    if (k >= 6 && k < change) two_before += two;
    if (k >= change + 4 * every) two_after_settling += two;
  }
  EXPECT_EQ(choice.calls()[0] + choice.calls()[1], end);
  EXPECT_LE(two_before, (change - 6) / every + 1) << "two cores only tried, one call in " << every;
  EXPECT_GE(two_before, (change - 6) / every - 1);
  const long settled = end - change - 4 * every;
  EXPECT_GE(two_after_settling, settled - settled / every - 1) << "two cores taken once they are faster";
}

// Both ways run each piece once and on one core (or not worth trying) nothing is timed.
TEST(TwoCoreChoice, RunsEachPieceOnceEitherWay) {
  TwoCoreChoice choice;
  int first = 0, second = 0;
  for (int k = 0; k < 100; ++k) choice.run(true, [&] { ++first; }, [&] { ++second; });
  EXPECT_EQ(first, 100);
  EXPECT_EQ(second, 100);
  EXPECT_EQ(choice.calls()[0] + choice.calls()[1], run_threads() > 1 ? 100 : 0);
  TwoCoreChoice small;
  small.run(false, [&] { ++first; }, [&] { ++second; });
  EXPECT_EQ(small.calls()[0] + small.calls()[1], 0);
  EXPECT_EQ(first + second, 202);
}

}  // namespace
}  // namespace deploydyn
