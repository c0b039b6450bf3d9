#pragma once
// Central finite differences for the derivative tests (STYLE practice 9).
// With step h the truncation error is O(h²·f''') and the round-off error O(ε_machine·|f|/h).

#include <Eigen/Core>

namespace deploydyn::testing {

// ∂g/∂x (rows: outputs of g, columns: entries of x) by central differences of step h.
template <class Function>
Eigen::MatrixXd central_jacobian(Function&& g, const Eigen::VectorXd& x, double h) {
  Eigen::MatrixXd jacobian;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    Eigen::VectorXd plus = x, minus = x;
    plus[j] += h;
    minus[j] -= h;
    const Eigen::VectorXd column = (Eigen::VectorXd(g(plus)) - Eigen::VectorXd(g(minus))) / (2.0 * h);
    if (j == 0) jacobian.resize(column.size(), x.size());
    jacobian.col(j) = column;
  }
  return jacobian;
}

// Gradient of a scalar function, as a column.
template <class Function>
Eigen::VectorXd central_gradient(Function&& g, const Eigen::VectorXd& x, double h) {
  return central_jacobian([&](const Eigen::VectorXd& y) { return Eigen::VectorXd::Constant(1, g(y)); },
                          x, h)
      .transpose();
}

}  // namespace deploydyn::testing
