#pragma once
// Two independent pieces of a run's work, on two cores or one after the other: a large model's
// residual (solvers/generalized_alpha.cpp) and its solves (assembly/klu_linear_system.cpp).

#include <exception>

#include "deploydyn/util/helper_thread.hpp"

namespace deploydyn {

namespace detail {
// Runs `work` and returns what it threw: the helper thread must not end by an exception, so it
// is thrown again on the calling thread after both pieces, as on one core.
template <class Work>
std::exception_ptr failure_of(const Work& work) noexcept {
  try {
    work();
  } catch (...) {
    return std::current_exception();
  }
  return nullptr;
}
}  // namespace detail

// Runs `first` and `second`, which must write nothing the other reads or writes. When
// `two_cores`, `second` is offered to the calling thread's helper (util/helper_thread.hpp) while
// this thread runs `first`, and run here after `first` if the helper has not started it: never
// a wait for a thread that has no core. Either way each piece writes what it writes in its own
// order, so the results are the same bit for bit.
template <class First, class Second>
void side_by_side(bool two_cores, const First& first, const Second& second) {
  if (!two_cores) {
    first();
    second();
    return;
  }
  struct Offered {
    const Second& work;
    std::exception_ptr failure;
    static void run(void* self) noexcept {
      auto& offered = *static_cast<Offered*>(self);
      offered.failure = detail::failure_of(offered.work);
    }
  } offered{second, nullptr};
  HelperThread& helper = HelperThread::of_this_thread();
  helper.offer(&Offered::run, &offered);
  const std::exception_ptr first_failure = detail::failure_of(first);
  helper.finish();
  if (first_failure) std::rethrow_exception(first_failure);
  if (offered.failure) std::rethrow_exception(offered.failure);
}

}  // namespace deploydyn
