#include "deploydyn/study/random_draws.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace deploydyn {
namespace {

// SplitMix64's finalizer (Steele, Lea & Flood 2014): a bijection of 64-bit words that mixes
// every input bit into every output bit.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

std::uint64_t hash(std::uint64_t seed, std::uint64_t stream, std::uint64_t a, std::uint64_t b) {
  return mix(mix(mix(mix(seed) ^ stream) ^ a) ^ b);
}

constexpr std::uint64_t kPointStream = 1;        // a case's draw (its point inside its stratum)
constexpr std::uint64_t kPermutationStream = 2;  // a variable's order of strata

}  // namespace

double RandomDraws::uniform(std::uint64_t stream, long case_index, long variable) const {
  const std::uint64_t bits = hash(seed_, stream, static_cast<std::uint64_t>(case_index),
                                  static_cast<std::uint64_t>(variable));
  // The top 53 bits, centred in their interval: never exactly 0 or 1.
  return (static_cast<double>(bits >> 11) + 0.5) * 0x1.0p-53;
}

long RandomDraws::stratum(long case_index, long variable) const {
  const std::lock_guard lock(permutations_mutex_);
  if (permutations_.size() <= static_cast<std::size_t>(variable)) {
    permutations_.resize(static_cast<std::size_t>(variable) + 1);
  }
  std::vector<long>& order = permutations_[static_cast<std::size_t>(variable)];
  if (order.empty()) {
    order.resize(static_cast<std::size_t>(n_cases_));
    for (long i = 0; i < n_cases_; ++i) order[static_cast<std::size_t>(i)] = i;
    // Fisher–Yates, each swap from its own counter.
    for (long i = n_cases_ - 1; i > 0; --i) {
      const auto j = static_cast<long>(uniform(kPermutationStream, i, variable) * static_cast<double>(i + 1));
      std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(std::min(j, i))]);
    }
  }
  return order[static_cast<std::size_t>(case_index)];
}

double RandomDraws::probability(long case_index, long variable) const {
  if (case_index < 0 || case_index >= n_cases_ || variable < 0) {
    throw std::out_of_range("RandomDraws: case or variable out of range");
  }
  const double u = uniform(kPointStream, case_index, variable);
  if (method_ == SamplingMethod::monte_carlo) return u;
  return (static_cast<double>(stratum(case_index, variable)) + u) / static_cast<double>(n_cases_);
}

double RandomDraws::standard_normal(long case_index, long variable) const {
  return standard_normal_quantile(probability(case_index, variable));
}

double standard_normal_quantile(double p) {
  if (!(p > 0.0 && p < 1.0)) throw std::domain_error("standard_normal_quantile: p must be in (0, 1)");
  // Acklam's rational approximation (relative error 1.15e-9), then one Halley step on
  // Φ(x) − p with Φ from erfc, which brings it to full precision.
  static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                                 1.383577518672690e+02, -3.066479806614716e+01, 2.506628277459239e+00};
  static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                                 6.680131188771972e+01, -1.328068155288572e+01};
  static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                                 -2.549732539343734e+00, 4.374664141464968e+00, 2.938163982698783e+00};
  static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                                 3.754408661907416e+00};
  constexpr double kLow = 0.02425;
  double x = 0.0;
  if (p < kLow) {
    const double q = std::sqrt(-2.0 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  } else if (p <= 1.0 - kLow) {
    const double q = p - 0.5, r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  } else {
    const double q = std::sqrt(-2.0 * std::log1p(-p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  const double e = 0.5 * std::erfc(-x / std::numbers::sqrt2) - p;
  const double u = e * std::sqrt(2.0 * std::numbers::pi) * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

}  // namespace deploydyn
