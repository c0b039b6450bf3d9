#pragma once
// Threads a run's own work may use: a large model's residual and solves run two independent
// pieces side by side (util/side_by_side.hpp). A study that runs several cases at once keeps
// each case on one core.

namespace deploydyn {

// Threads available to the calling thread's runs: 2 when the process may use two cores or more,
// 1 on one core, or when `OMP_NUM_THREADS` (the variable users of numerical codes set) or
// `DEPLOYDYN_THREADS` is 1, or inside a RunsOnOneCore.
int run_threads();

// While it lives, the runs its thread makes stay on one core (when `active`); other threads
// keep theirs.
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
