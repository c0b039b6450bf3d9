// Verification 6: order of convergence in the time step (STYLE practice 11). The flexible
// general linkage (real E, ΔT = +130 °C, 0–5 s) at h = 1, ½, ¼, ⅛ ms against a reference
// computed far more accurately: the independent RK4 solution of verification 5 (its error,
// 3e-14 m, is 1e5 times below the finest run's). Errors are the largest over the 1001 output
// times, of B's and C's positions and of the three bars' total strains; the order of each
// halving is log2(e(h)/e(h/2)), and the row reports the smallest of the three.
//
// Every integrator offered is second order (solvers/generalized_alpha.hpp): Newmark(¼,½),
// generalized-α and HHT-α. h = 2 ms is not yet asymptotic for the 12 Hz coupler swing
// (measured order 1.4–1.7 from 2 ms to 1 ms), hence 1 ms as the coarsest step. The most
// damped setting, generalized-α ρ∞ = 0, needs smaller steps still: measured orders 1.73,
// 1.98, 2.00, 2.00 from 1 ms to 1/16 ms; it is left out to keep the suite fast.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "verification/general_linkage_comparison.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using verification::Bound;
using verification::check;

constexpr double kTemperatureChange_C = 130.0;
constexpr double kCoarsest_s = 1e-3;
constexpr int kHalvings = 3;
constexpr double kRequiredOrder = 1.9;  // order p = 2, less 0.1 (STYLE practice 11)

struct Orders {
  double position = 0.0, strain = 0.0;  // the smallest of the halvings'
  std::string position_orders, strain_orders;  // each halving's, for the report
  std::vector<double> position_errors_m, strain_errors;
};

Orders measure(const IntegratorOptions& integrator) {
  const auto& reference = verification::general_reference(kTemperatureChange_C);
  Orders o;
  for (int k = 0; k <= kHalvings; ++k) {
    const double h = kCoarsest_s / static_cast<double>(1 << k);
    const verification::Differences d = verification::compare_with_reference(
        verification::general_linkage(kTemperatureChange_C, integrator, h), reference);
    o.position_errors_m.push_back(d.position_m);
    o.strain_errors.push_back(d.strain);
  }
  const auto smallest_order = [](const std::vector<double>& e, std::string& each) {
    double order = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < e.size(); ++k) {
      const double halving = std::log2(e[k - 1] / e[k]);
      each += fmt::format("{}{:.2f}", k > 1 ? ", " : "", halving);
      order = std::min(order, halving);
    }
    return std::isfinite(order) ? order : 0.0;  // a failed run gives no order
  };
  o.position = smallest_order(o.position_errors_m, o.position_orders);
  o.strain = smallest_order(o.strain_errors, o.strain_orders);
  return o;
}

void check_orders(const IntegratorOptions& integrator, const std::string& name, int first_row) {
  const Orders o = measure(integrator);
  const std::string run = "flexible general linkage, ΔT = +130 °C, " + name + ", h = 1, ½, ¼, ⅛ ms: ";
  check({fmt::format("6.{}", first_row), run + "order of the position error",
         fmt::format("2 (second-order scheme); errors {:.2e} → {:.2e} m against the RK4 solution; "
                     "each halving: {}",
                     o.position_errors_m.front(), o.position_errors_m.back(), o.position_orders),
         o.position, kRequiredOrder, "", Bound::at_least});
  check({fmt::format("6.{}", first_row + 1), "same runs: order of the strain error",
         fmt::format("2; errors {:.2e} → {:.2e}; each halving: {}", o.strain_errors.front(), o.strain_errors.back(),
                     o.strain_orders),
         o.strain,
         kRequiredOrder, "", Bound::at_least});
}

TEST(VerificationConvergence, NewmarkTrapezoidalRuleIsSecondOrder) {
  check_orders({IntegratorOptions::Kind::newmark, 0.25, 0.5, 1.0}, "Newmark(¼,½)", 1);
}

TEST(VerificationConvergence, GeneralizedAlphaIsSecondOrder) {
  check_orders({IntegratorOptions::Kind::generalized_alpha, 0.25, 0.5, 0.9}, "generalized-α ρ∞ = 0.9", 3);
  check_orders({IntegratorOptions::Kind::generalized_alpha, 0.25, 0.5, 0.5}, "generalized-α ρ∞ = 0.5", 5);
}

TEST(VerificationConvergence, HhtAlphaIsSecondOrder) {
  check_orders({IntegratorOptions::Kind::hht, 0.25, 0.5, 0.9}, "HHT-α ρ∞ = 0.9", 7);
}

}  // namespace
}  // namespace deploydyn
