#pragma once
// Dense LU back end (Eigen PartialPivLU): right for small models such as the four-bar
// linkages, where a 13 × 13 matrix is factorised faster than any sparse analysis.

#include <Eigen/LU>

#include "deploydyn/assembly/linear_system.hpp"

namespace deploydyn {

class DenseLinearSystem final : public LinearSystem {
 public:
  explicit DenseLinearSystem(int size) : matrix_(Eigen::MatrixXd::Zero(size, size)), lu_(size) {}

  int size() const override { return static_cast<int>(matrix_.rows()); }
  void set_zero() override { matrix_.setZero(); }
  void add(std::span<const int> rows, std::span<const int> cols,
           const Eigen::Ref<const Eigen::MatrixXd>& block) override;
  void add_symmetric_pair(std::span<const int> rows, std::span<const int> cols,
                          const Eigen::Ref<const Eigen::MatrixXd>& block) override;
  FactorizationStatus factorize() override;
  void solve(Eigen::Ref<Eigen::VectorXd> rhs) const override;

  const Eigen::MatrixXd& matrix() const { return matrix_; }

 private:
  Eigen::MatrixXd matrix_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace deploydyn
