#include "deploydyn/util/run_threads.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace deploydyn {

#ifdef _OPENMP
int run_threads() { return omp_get_max_threads(); }

RunsOnOneCore::RunsOnOneCore(bool active) {
  if (!active) return;
  threads_before_ = omp_get_max_threads();
  omp_set_num_threads(1);
}
RunsOnOneCore::~RunsOnOneCore() {
  if (threads_before_ > 0) omp_set_num_threads(threads_before_);
}
#else
int run_threads() { return 1; }
RunsOnOneCore::RunsOnOneCore(bool) {}
RunsOnOneCore::~RunsOnOneCore() = default;
#endif

}  // namespace deploydyn
