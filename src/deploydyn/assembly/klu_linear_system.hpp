#pragma once
// KLU (Davis & Palamadai Natarajan, ACM TOMS 37, 2010): BTF + AMD ordering and left-looking
// partial-pivoting LU. Refactorizes with the pivot order of its last full factorization while
// that stays well conditioned, which skips the pivot search on nearly unchanged matrices.

#include <memory>

#include "deploydyn/assembly/sparse_linear_system.hpp"

namespace deploydyn {

// The fill-reducing order of each block: KLU's default AMD, or METIS's nested dissection
// (assembly/metis_ordering.hpp). docs/performance.md, "Faster large steps", compares them.
enum class KluOrdering { amd, nested_dissection };

class KluLinearSystem final : public SparseLinearSystem {
 public:
  explicit KluLinearSystem(KluOrdering ordering = KluOrdering::amd);
  ~KluLinearSystem() override;
  KluLinearSystem(const KluLinearSystem&) = delete;
  KluLinearSystem& operator=(const KluLinearSystem&) = delete;

  const char* name() const override { return "KLU"; }

  int full_factorizations() const { return full_factorizations_; }
  // Entries of the L and U factors (with their diagonals) of the last factorization; 0 before.
  double factor_nonzeros() const;

 protected:
  void analyze_pattern() override;
  FactorizationStatus factorize_pattern() override;
  void solve_pattern(double* rhs) override;

 private:
  struct Handles;  // klu_common, klu_symbolic, klu_numeric (klu.h stays out of this header)
  FactorizationStatus factorize_fully();
  std::unique_ptr<Handles> klu_;
  double reciprocal_condition_at_full_ = 0.0;
  int full_factorizations_ = 0;
};

}  // namespace deploydyn
