#pragma once
// KLU (Davis & Palamadai Natarajan, ACM TOMS 37, 2010): BTF + AMD ordering and left-looking
// partial-pivoting LU. Refactorizes with the pivot order of its last full factorization while
// that stays well conditioned, which skips the pivot search on nearly unchanged matrices.

#include <memory>

#include "deploydyn/assembly/sparse_linear_system.hpp"

namespace deploydyn {

// The fill-reducing order: KLU's default (BTF blocks, each by AMD), METIS's nested dissection
// of each block, or two domains and their separator (one block; assembly/metis_ordering.hpp),
// whose solve runs the domains on two cores. `automatic`: two domains for large systems, else
// AMD. docs/performance.md, "Faster large steps", compares them.
enum class KluOrdering { amd, nested_dissection, two_domains, automatic };

// Whether KLU first permutes the matrix to block triangular form (BTF), by a matching that puts
// a nonzero on every diagonal position, and orders each block (AMD, nested dissection) after that
// matching. Multipliers have no diagonal, so the matching puts constraint rows on their diagonal
// and the ordering then sees a pattern that is no longer symmetric: on 3D beams (six frame
// multipliers a node) the factors fill 2.3 × more and cost 6 × the operations of the matrix
// ordered as it is (`whole`). Two domains always order the whole matrix. docs/performance.md,
// "3D beams".
enum class KluBlocks { triangular, whole };

class KluLinearSystem final : public SparseLinearSystem {
 public:
  explicit KluLinearSystem(KluOrdering ordering = KluOrdering::automatic,
                           KluBlocks blocks = KluBlocks::triangular);
  ~KluLinearSystem() override;
  KluLinearSystem(const KluLinearSystem&) = delete;
  KluLinearSystem& operator=(const KluLinearSystem&) = delete;

  const char* name() const override { return "KLU"; }

  int full_factorizations() const { return full_factorizations_; }
  // Entries of the L and U factors (with their diagonals) of the last factorization; 0 before.
  double factor_nonzeros() const;
  // Multiplications and divisions of the last factorization, as KLU counts them (klu_flops);
  // a refactorization costs the same. 0 before.
  double factor_operations() const;
  // The ordering in use (`automatic` resolved), and whether solves run on two domains: the
  // last full factorization's pivots kept them apart (else KLU's own solve serves).
  KluOrdering ordering() const { return ordering_; }
  KluBlocks blocks() const { return blocks_; }
  bool solves_by_two_domains() const;

  // What one factorization hands on to the next: the pivot order of the last full
  // factorization, which refactorizations keep. pivot_memory() gives the values of the matrix
  // that made it; restore_pivot_memory factorizes them again, so that a restarted run pivots,
  // and rounds, as the run it continues did (solvers/restart_state.hpp).
  std::vector<double> pivot_memory() const override { return values_at_full_; }
  void restore_pivot_memory(std::span<const double> memory) override;

 protected:
  void analyze_pattern() override;
  FactorizationStatus factorize_pattern() override;
  void solve_pattern(double* rhs) override;

 private:
  struct Handles;  // klu_common, klu_symbolic, klu_numeric (klu.h stays out of this header)
  FactorizationStatus factorize_fully();
  void solve_two_domains(double* rhs);
  std::unique_ptr<Handles> klu_;
  KluOrdering requested_ordering_;
  KluBlocks blocks_;
  KluOrdering ordering_ = KluOrdering::amd;
  double reciprocal_condition_at_full_ = 0.0;
  std::vector<double> values_at_full_;  // pivot_memory
  int full_factorizations_ = 0;
};

}  // namespace deploydyn
