#pragma once
// A polynomial p(x) = Σ c[k] xᵏ given by its coefficients c (lowest power first).

#include <vector>

namespace deploydyn {

// p⁽ᵒʳᵈᵉʳ⁾(x) for order ≥ 0, by Horner's rule on the derivative's coefficients; order −1 gives
// the antiderivative P with P(0) = 0.
double polynomial_derivative(const std::vector<double>& c, double x, int order);

// min p(x) over [from, to]; either end may be infinite (then −∞ when p falls without bound that
// way). Exact up to round-off: p at the ends and at the real roots of p' inside.
double least_polynomial_value(const std::vector<double>& c, double from, double to);

}  // namespace deploydyn
