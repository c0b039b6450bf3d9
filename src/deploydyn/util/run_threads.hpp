#pragma once
// Threads a run's own work may use (OpenMP, when the library is built with it): a large
// model's residual runs its independent parts on two cores (solvers/generalized_alpha.cpp).
// A study that runs several cases at once keeps each case on one core.

namespace deploydyn {

// Threads available to the calling thread's parallel work: 1 without OpenMP.
int run_threads();

// While it lives, the runs its thread makes stay on one core (when `active`). OpenMP's thread
// count is per thread (the nthreads-var ICV): other threads keep theirs.
class RunsOnOneCore {
 public:
  explicit RunsOnOneCore(bool active);
  ~RunsOnOneCore();
  RunsOnOneCore(const RunsOnOneCore&) = delete;
  RunsOnOneCore& operator=(const RunsOnOneCore&) = delete;

 private:
  int threads_before_ = 0;  // 0: nothing to restore
};

}  // namespace deploydyn
