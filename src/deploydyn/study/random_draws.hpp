#pragma once
// Reproducible random draws for sampled studies (study/sampling.hpp), the same on any machine,
// compiler and number of processes: every number is a function of (seed, case, variable) alone
// (a counter-based generator: SplitMix64's finalizer over the three), not of a stream's state,
// so a case can be drawn by whichever process runs it. The standard library's distributions
// are not used: their algorithms differ between implementations.
//
// Latin hypercube sampling (McKay, Beckman & Conover 1979): for each variable the n cases take
// the n equal-probability strata (0, 1/n), ..., ((n−1)/n, 1) in an order that is a random
// permutation of that variable, each at a uniform point inside its stratum.

#include <cstdint>
#include <mutex>
#include <vector>

namespace deploydyn {

enum class SamplingMethod { monte_carlo, latin_hypercube };

class RandomDraws {
 public:
  RandomDraws(SamplingMethod method, std::uint64_t seed, long n_cases)
      : method_(method), seed_(seed), n_cases_(n_cases) {}

  // A probability in (0, 1) for variable `variable` of case `case_index` (0 ≤ case < n_cases):
  // independent uniform draws (Monte Carlo) or the case's point of the variable's Latin
  // hypercube strata.
  double probability(long case_index, long variable) const;

  // The same, through the inverse of the standard normal distribution function.
  double standard_normal(long case_index, long variable) const;

 private:
  // Uniform in (0, 1) from the counters alone.
  double uniform(std::uint64_t stream, long case_index, long variable) const;
  // The stratum of case_index for `variable`: a permutation of 0..n−1 drawn from the seed and
  // the variable (cached: a study asks for the same variables in every case; the cache is
  // shared by the threads that draw cases).
  long stratum(long case_index, long variable) const;

  SamplingMethod method_;
  std::uint64_t seed_;
  long n_cases_;
  mutable std::mutex permutations_mutex_;
  mutable std::vector<std::vector<long>> permutations_;  // by variable
};

// Φ⁻¹(p), the standard normal quantile, to full double precision for p in (0, 1).
double standard_normal_quantile(double p);

}  // namespace deploydyn
