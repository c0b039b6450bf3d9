#include "deploydyn/model/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace deploydyn {
namespace {

// Bisection halves a bracket per step: 200 halvings reach adjacent doubles from any finite one.
constexpr int kMaxBisections = 200;

// Without the zero coefficients of the highest powers, so that back() leads.
std::vector<double> trimmed(std::vector<double> c) {
  while (c.size() > 1 && c.back() == 0.0) c.pop_back();
  return c;
}

std::vector<double> derivative_coefficients(const std::vector<double>& c) {
  std::vector<double> d;
  for (std::size_t k = 1; k < c.size(); ++k) d.push_back(static_cast<double>(k) * c[k]);
  if (d.empty()) d.push_back(0.0);
  return d;
}

// The real roots of p in the finite [from, to]: p is monotone between the roots of p' (found
// the same way, one degree lower), so each sign change there brackets one root.
std::vector<double> roots_in(const std::vector<double>& c, double from, double to) {
  const std::vector<double> p = trimmed(c);
  if (p.size() <= 1) return {};
  std::vector<double> points{from};
  for (const double x : roots_in(derivative_coefficients(p), from, to)) points.push_back(x);
  points.push_back(to);
  std::vector<double> roots;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    double lo = points[i], hi = points[i + 1];
    double p_lo = polynomial_derivative(p, lo, 0);
    const double p_hi = polynomial_derivative(p, hi, 0);
    if (p_lo == 0.0) roots.push_back(lo);
    if (!(p_lo * p_hi < 0.0)) continue;
    for (int n = 0; n < kMaxBisections; ++n) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      const double p_mid = polynomial_derivative(p, mid, 0);
      if ((p_mid < 0.0) == (p_lo < 0.0)) {
        lo = mid;
        p_lo = p_mid;
      } else {
        hi = mid;
      }
    }
    roots.push_back(0.5 * (lo + hi));
  }
  if (polynomial_derivative(p, to, 0) == 0.0) roots.push_back(to);
  return roots;
}

}  // namespace

double polynomial_derivative(const std::vector<double>& c, double x, int order) {
  double result = 0.0;
  if (order == -1) {
    for (std::size_t k = c.size(); k-- > 0;) result = result * x + c[k] / static_cast<double>(k + 1);
    return result * x;
  }
  const auto n_derivatives = static_cast<std::size_t>(order);
  for (std::size_t k = c.size(); k-- > n_derivatives;) {
    double falling = 1.0;  // k (k − 1) ⋯ (k − order + 1)
    for (std::size_t j = 0; j < n_derivatives; ++j) falling *= static_cast<double>(k - j);
    result = result * x + c[k] * falling;
  }
  return result;
}

double least_polynomial_value(const std::vector<double>& c, double from, double to) {
  const std::vector<double> p = trimmed(c);
  const std::size_t degree = p.size() - 1;
  if (degree == 0) return p[0];
  // p → −∞ at +∞ when it leads negative; at −∞ also when it leads positive with odd degree.
  const bool falls_right = p.back() < 0.0;
  const bool falls_left = (p.back() < 0.0) == (degree % 2 == 0);
  if ((to == std::numeric_limits<double>::infinity() && falls_right) || (from == -std::numeric_limits<double>::infinity() && falls_left)) return -std::numeric_limits<double>::infinity();
  // Cauchy's bound: every root of p' lies within |x| ≤ 1 + max |d[k] / d.back()|.
  const std::vector<double> d = trimmed(derivative_coefficients(p));
  double bound = 1.0;
  for (std::size_t k = 0; k + 1 < d.size(); ++k) bound = std::max(bound, 1.0 + std::abs(d[k] / d.back()));
  double least = std::numeric_limits<double>::infinity();
  if (std::isfinite(from)) least = polynomial_derivative(p, from, 0);
  if (std::isfinite(to)) least = std::min(least, polynomial_derivative(p, to, 0));
  const double lo = std::max(from, -bound), hi = std::min(to, bound);
  if (lo < hi) {
    for (const double x : roots_in(d, lo, hi)) least = std::min(least, polynomial_derivative(p, x, 0));
  }
  return least;
}

}  // namespace deploydyn
