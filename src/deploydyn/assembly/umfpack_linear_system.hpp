#pragma once
// UMFPACK (Davis, ACM TOMS 30, 2004): multifrontal LU with a COLAMD/AMD ordering from the
// symbolic analysis; every numeric factorization searches pivots anew.

#include <memory>

#include "deploydyn/assembly/sparse_linear_system.hpp"

namespace deploydyn {

class UmfpackLinearSystem final : public SparseLinearSystem {
 public:
  UmfpackLinearSystem();
  ~UmfpackLinearSystem() override;
  UmfpackLinearSystem(const UmfpackLinearSystem&) = delete;
  UmfpackLinearSystem& operator=(const UmfpackLinearSystem&) = delete;

  const char* name() const override { return "UMFPACK"; }

 protected:
  void analyze_pattern() override;
  FactorizationStatus factorize_pattern() override;
  void solve_pattern(double* rhs) override;

 private:
  struct Handles;  // control and info arrays, symbolic and numeric objects
  std::unique_ptr<Handles> umfpack_;
  Eigen::VectorXd right_hand_side_;  // UMFPACK solves out of place
};

}  // namespace deploydyn
