#include "deploydyn/util/run_threads.hpp"

#include <sched.h>

#include <algorithm>
#include <cstdlib>

namespace deploydyn {

namespace {

// A thread count the user set in `variable`, or 0 when it is unset or not a positive number.
int threads_set_in(const char* variable) {
  const char* text = std::getenv(variable);
  if (text == nullptr) return 0;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return end != text && value > 0 ? static_cast<int>(std::min(value, 1024L)) : 0;
}

// Cores this process may run on (its affinity, as `taskset` or a batch system sets it), at most
// the 2 that a run's two pieces can use, and fewer when the user asks for fewer.
int process_threads() {
  int threads = 2;
  cpu_set_t cores;
  if (sched_getaffinity(0, sizeof(cores), &cores) == 0) threads = std::min(threads, CPU_COUNT(&cores));
  for (const char* variable : {"DEPLOYDYN_THREADS", "OMP_NUM_THREADS"}) {
    if (const int set = threads_set_in(variable); set > 0) return std::min(threads, set);
  }
  return std::max(threads, 1);
}

thread_local int thread_limit = 0;  // 0: none

}  // namespace

int run_threads() {
  static const int threads = process_threads();
  return thread_limit > 0 ? std::min(thread_limit, threads) : threads;
}

RunsOnOneCore::RunsOnOneCore(bool active) {
  if (!active) return;
  threads_before_ = thread_limit > 0 ? thread_limit : -1;
  thread_limit = 1;
}
RunsOnOneCore::~RunsOnOneCore() {
  if (threads_before_ != 0) thread_limit = threads_before_ > 0 ? threads_before_ : 0;
}

}  // namespace deploydyn
