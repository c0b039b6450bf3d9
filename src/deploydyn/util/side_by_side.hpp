#pragma once
// Two independent pieces of a run's work, on two cores or one after the other. For the library's
// own sources (built with OpenMP when it is found): a large model's residual
// (solvers/generalized_alpha.cpp) and its solves (assembly/klu_linear_system.cpp,
// assembly/sparse_linear_system.cpp).

#include <exception>

namespace deploydyn {

namespace detail {
// Runs `work` and returns what it threw: an exception must not leave an OpenMP section (that
// ends the process), so it is thrown again after both, as on one core.
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

// Runs `first` and `second`, which must write nothing the other reads or writes: side by side
// on two cores when `two_cores`, else one after the other. Either way each writes what it
// writes in its own order, so the results are the same bit for bit. On one core no parallel
// region is entered at all: even an inactive one allocates its team.
template <class First, class Second>
void side_by_side(bool two_cores, const First& first, const Second& second) {
  if (!two_cores) {
    first();
    second();
    return;
  }
  std::exception_ptr failures[2];
#pragma omp parallel sections num_threads(2)
  {
#pragma omp section
    failures[0] = detail::failure_of(first);
#pragma omp section
    failures[1] = detail::failure_of(second);
  }
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
}

}  // namespace deploydyn
