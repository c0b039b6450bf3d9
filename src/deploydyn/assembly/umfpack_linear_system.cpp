#include "deploydyn/assembly/umfpack_linear_system.hpp"

#include <suitesparse/umfpack.h>

#include <stdexcept>

namespace deploydyn {

struct UmfpackLinearSystem::Handles {
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  void* symbolic = nullptr;
  void* numeric = nullptr;

  Handles() {
    umfpack_di_defaults(control);
    // Newton corrects what iterative refinement would: no refinement steps, as with KLU.
    control[UMFPACK_IRSTEP] = 0;
  }
  ~Handles() {
    if (numeric != nullptr) umfpack_di_free_numeric(&numeric);
    if (symbolic != nullptr) umfpack_di_free_symbolic(&symbolic);
  }
};

UmfpackLinearSystem::UmfpackLinearSystem() : umfpack_(std::make_unique<Handles>()) {}
UmfpackLinearSystem::~UmfpackLinearSystem() = default;

void UmfpackLinearSystem::analyze_pattern() {
  Handles& u = *umfpack_;
  if (u.numeric != nullptr) umfpack_di_free_numeric(&u.numeric);
  if (u.symbolic != nullptr) umfpack_di_free_symbolic(&u.symbolic);
  const int status = umfpack_di_symbolic(factored_size(), factored_size(), column_start_.data(), row_index_.data(),
                                         nullptr, &u.symbolic, u.control, u.info);
  if (status != UMFPACK_OK) throw std::runtime_error("UMFPACK could not analyse the matrix pattern");
  right_hand_side_.resize(factored_size());
}

FactorizationStatus UmfpackLinearSystem::factorize_pattern() {
  Handles& u = *umfpack_;
  if (u.numeric != nullptr) umfpack_di_free_numeric(&u.numeric);
  const int result = umfpack_di_numeric(column_start_.data(), row_index_.data(), values_.data(),
                                        u.symbolic, &u.numeric, u.control, u.info);
  const double rcond = u.info[UMFPACK_RCOND];
  if (result != UMFPACK_OK || !(rcond > kSingularReciprocalCondition)) {
    if (result == UMFPACK_ERROR_out_of_memory) throw std::bad_alloc();
    return singular(result == UMFPACK_WARNING_singular_matrix ? 0.0 : rcond);
  }
  FactorizationStatus status;
  status.reciprocal_condition = rcond;
  return status;
}

void UmfpackLinearSystem::solve_pattern(double* rhs) {
  right_hand_side_ = Eigen::Map<const Eigen::VectorXd>(rhs, factored_size());
  umfpack_di_solve(UMFPACK_A, column_start_.data(), row_index_.data(), values_.data(), rhs,
                   right_hand_side_.data(), umfpack_->numeric, umfpack_->control, umfpack_->info);
}

}  // namespace deploydyn
