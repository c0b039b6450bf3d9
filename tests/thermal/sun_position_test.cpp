// The sun's position may be asked from several threads at once (a study runs its cases in
// threads): every answer must be the one a lone call gives. libnova keeps static caches, which
// thermal/sun_position.cpp serializes; without that, this test sees other threads' values.
// (Its accuracy against an independent algorithm is python/tests/test_sun_position.py's.)

#include "deploydyn/thermal/sun_position.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace deploydyn::thermal {
namespace DEPLOYDYN_FILE_SCOPE {

TEST(SunPosition, ThreadsAskingAtOnceGetWhatALoneCallGets) {
  const int n_times = 500;
  const double start_jd = julian_day_utc({2026, 7, 15, 8, 0, 0.0}, 2.0, 0.0);
  // Each thread walks its own hours: consecutive calls from different threads differ in time.
  const auto julian_day = [&](int thread, int k) { return start_jd + (thread * n_times + k) * 0.37 / 24.0; };
  constexpr int kThreads = 4;
  std::vector<std::vector<SunPosition>> expected(kThreads), seen(kThreads);
  for (int thread = 0; thread < kThreads; ++thread) {
    for (int k = 0; k < n_times; ++k) expected[thread].push_back(sun_position(48.14, 11.58, julian_day(thread, k)));
  }
  std::vector<std::thread> threads;
  for (int thread = 0; thread < kThreads; ++thread) {
    threads.emplace_back([&, thread] {
      for (int k = 0; k < n_times; ++k) seen[thread].push_back(sun_position(48.14, 11.58, julian_day(thread, k)));
    });
  }
  for (std::thread& t : threads) t.join();
  int n_wrong = 0;
  for (int thread = 0; thread < kThreads; ++thread) {
    for (int k = 0; k < n_times; ++k) {
      const bool same = seen[thread][k].altitude_deg == expected[thread][k].altitude_deg &&
                        seen[thread][k].azimuth_deg == expected[thread][k].azimuth_deg;
      n_wrong += same ? 0 : 1;
    }
  }
  EXPECT_EQ(n_wrong, 0) << "of " << kThreads * n_times << " positions asked from " << kThreads << " threads";
}

}  // namespace
}  // namespace deploydyn::thermal
