#include "deploydyn/assembly/klu_linear_system.hpp"

#include <suitesparse/klu.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "deploydyn/assembly/metis_ordering.hpp"

namespace deploydyn {
namespace {

// A refactorization keeps the old pivot order; when its reciprocal condition estimate falls
// this far below the last full factorization's, pivots are searched anew.
constexpr double kRefactorConditionLoss = 1e-3;

// KLU's user ordering (Common.ordering = 3), called per block: 0 on failure, else the expected
// entries of the block's L, by which KLU sizes its first allocation of the factors.
int nested_dissection_for_klu(int n, int* column_start, int* row_index, int* perm, klu_common*) {
  const long entries = nested_dissection_order(n, column_start, row_index, perm);
  return static_cast<int>(std::min<long>(entries, std::numeric_limits<int>::max()));
}

}  // namespace

struct KluLinearSystem::Handles {
  klu_common common{};
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;

  explicit Handles(KluOrdering ordering) {
    klu_defaults(&common);
    if (ordering == KluOrdering::nested_dissection) {
      common.ordering = 3;
      common.user_order = nested_dissection_for_klu;
    }
    // No row scaling and no input check (-1): the assembler already sizes the constraint rows
    // like the force block (docs/theory.md), and the pattern is valid by construction (sorted, no
    // repeats: SparseLinearSystem::build_storage). Scaling and checking at every
    // refactorization cost 9 % of a roof's time step.
    common.scale = -1;
  }
  ~Handles() {
    if (numeric != nullptr) klu_free_numeric(&numeric, &common);
    if (symbolic != nullptr) klu_free_symbolic(&symbolic, &common);
  }
};

KluLinearSystem::KluLinearSystem(KluOrdering ordering) : klu_(std::make_unique<Handles>(ordering)) {}
KluLinearSystem::~KluLinearSystem() = default;

void KluLinearSystem::analyze_pattern() {
  if (klu_->numeric != nullptr) klu_free_numeric(&klu_->numeric, &klu_->common);
  if (klu_->symbolic != nullptr) klu_free_symbolic(&klu_->symbolic, &klu_->common);
  klu_->symbolic = klu_analyze(factored_size(), column_start_.data(), row_index_.data(), &klu_->common);
  if (klu_->symbolic == nullptr) throw std::runtime_error("KLU could not analyse the matrix pattern");
}

FactorizationStatus KluLinearSystem::factorize_pattern() {
  if (klu_->numeric == nullptr) return factorize_fully();
  Handles& k = *klu_;
  const bool refactored = klu_refactor(column_start_.data(), row_index_.data(), values_.data(),
                                       k.symbolic, k.numeric, &k.common) != 0 &&
                          klu_rcond(k.symbolic, k.numeric, &k.common) != 0;
  if (!refactored || !(k.common.rcond > kRefactorConditionLoss * reciprocal_condition_at_full_)) {
    return factorize_fully();
  }
  FactorizationStatus status;
  status.reciprocal_condition = k.common.rcond;
  return status;
}

FactorizationStatus KluLinearSystem::factorize_fully() {
  Handles& k = *klu_;
  if (k.numeric != nullptr) klu_free_numeric(&k.numeric, &k.common);
  ++full_factorizations_;
  k.numeric = klu_factor(column_start_.data(), row_index_.data(), values_.data(), k.symbolic, &k.common);
  if (k.numeric == nullptr || k.common.status == KLU_SINGULAR) {
    const int column = k.common.singular_col;
    FactorizationStatus status = singular(0.0);
    if (status.null_vector.size() == 0 && column >= 0 && column < factored_size()) {
      // Too large for an SVD: KLU's first zero pivot names one unknown of the null space.
      status.null_vector = Eigen::VectorXd::Unit(size_, unknown_of(column));
    }
    if (k.numeric != nullptr) klu_free_numeric(&k.numeric, &k.common);
    return status;
  }
  klu_rcond(k.symbolic, k.numeric, &k.common);
  reciprocal_condition_at_full_ = k.common.rcond;
  if (!(k.common.rcond > kSingularReciprocalCondition)) {
    const double rcond = k.common.rcond;
    klu_free_numeric(&k.numeric, &k.common);
    return singular(rcond);
  }
  FactorizationStatus status;
  status.reciprocal_condition = k.common.rcond;
  return status;
}

double KluLinearSystem::factor_nonzeros() const {
  return klu_->numeric != nullptr ? static_cast<double>(klu_->numeric->lnz) + klu_->numeric->unz : 0.0;
}

void KluLinearSystem::solve_pattern(double* rhs) {
  klu_solve(klu_->symbolic, klu_->numeric, factored_size(), 1, rhs, &klu_->common);
}

}  // namespace deploydyn
