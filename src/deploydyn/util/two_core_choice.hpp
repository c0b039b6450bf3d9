#pragma once
// Whether a pair of independent pieces that a run repeats (a residual's two halves, a solve's
// two domains) runs side by side or one after the other, decided by timing both as the run goes.
// The helper thread (util/helper_thread.hpp) never makes the caller wait for a thread that has
// not started; but once it has started, a busy machine may take its core away mid-piece, and
// small pieces may not pay for the wake-up. So each call site keeps the recent wall time of
// both ways and takes the faster, trying the other now and then, as the load on the machine
// changes (docs/performance.md, "Two cores on a busy machine"). Results are the same bit for bit
// either way: only who runs the second piece changes.

#include <chrono>

#include "deploydyn/util/run_threads.hpp"
#include "deploydyn/util/side_by_side.hpp"

namespace deploydyn {

class TwoCoreChoice {
 public:
  // One call in so many goes the slower way, to see whether the load has changed: on a busy
  // machine two cores may cost 3 × one, so this keeps the trials' cost near 3 %.
  static constexpr long kTryOtherEvery = 64;

  // Runs `first` and `second` (see side_by_side) the faster way of late; one after the other
  // when `worth_trying` is false or the run has one core.
  template <class First, class Second>
  void run(bool worth_trying, const First& first, const Second& second) {
    if (!worth_trying || run_threads() < 2) return side_by_side(false, first, second);
    const bool two_cores = next_is_two_cores();
    const auto start = std::chrono::steady_clock::now();
    side_by_side(two_cores, first, second);
    record(two_cores, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }

  // The policy run() follows: which way the next call goes, and the wall time a call took.
  bool next_is_two_cores() const;
  void record(bool two_cores, double seconds);
  // Calls made each way so far: [0] one core, [1] two cores.
  const long* calls() const { return calls_; }

 private:
  double recent_s_[2] = {0.0, 0.0};  // smoothed wall time per call: [0] one core, [1] two cores
  long calls_[2] = {0, 0};
};

}  // namespace deploydyn
