#pragma once
// Dense LU back end (Eigen PartialPivLU): right for small models such as the four-bar
// linkages, where a 13 × 13 matrix is factorised faster than any sparse analysis.
// Values are stored column-major, so the slot of (row, col) is row + col · size.

#include <Eigen/LU>

#include "deploydyn/assembly/linear_system.hpp"

namespace deploydyn {

class DenseLinearSystem final : public LinearSystem {
 public:
  void solve(Eigen::Ref<Eigen::VectorXd> rhs) override;
  const char* name() const override { return "dense LU"; }

 protected:
  FactorizationStatus factorize_finite() override;
  void build_storage(std::span<const MatrixEntry> entries) override;
  MatrixEntry position(int value_index) const override {
    return {value_index % size_, value_index / size_};
  }

 private:
  Eigen::Map<const Eigen::MatrixXd> matrix() const { return {values_.data(), size_, size_}; }

  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace deploydyn
