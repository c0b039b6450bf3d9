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
#include "deploydyn/util/side_by_side.hpp"

namespace deploydyn {
namespace {

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

}  // namespace
}  // namespace deploydyn
