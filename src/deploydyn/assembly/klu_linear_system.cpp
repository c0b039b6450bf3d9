#include "deploydyn/assembly/klu_linear_system.hpp"

#include <suitesparse/klu.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

#include "deploydyn/assembly/metis_ordering.hpp"
#include "deploydyn/util/two_core_choice.hpp"

namespace deploydyn {
namespace {

// A refactorization keeps the old pivot order; when its reciprocal condition estimate falls
// this far below the last full factorization's, pivots are searched anew.
constexpr double kRefactorConditionLoss = 1e-3;

// From this many factored unknowns on, `automatic` orders by two domains: their solve on two
// cores pays from about 3 000 (the 32 × 32 roof: 1.31 → 0.92 ms), not at 864 (the 10³-bar
// roof: 0.062 → 0.081 ms). docs/performance.md, "Faster large steps".
constexpr int kTwoDomainUnknowns = 2000;

// KLU's user ordering (Common.ordering = 3), called per block: 0 on failure, else the expected
// entries of the block's L, by which KLU sizes its first allocation of the factors.
int nested_dissection_for_klu(int n, int* column_start, int* row_index, int* perm, klu_common*) {
  const long entries = nested_dissection_order(n, column_start, row_index, perm);
  return static_cast<int>(std::min<long>(entries, std::numeric_limits<int>::max()));
}

// One column of KLU's factors of a block, as KLU packs them (klu_internal.h, GET_POINTER): at
// `lu + start[k]` (in doubles) the column's row indices, then, from the next whole double on,
// its values.
struct FactorColumn {
  const int* rows;
  const double* values;
  int length;
};
FactorColumn factor_column(const double* lu, const int* start, const int* length, int k) {
  const double* at = lu + start[k];
  const int n = length[k];
  const auto index_doubles = (static_cast<std::size_t>(n) * sizeof(int) + sizeof(double) - 1) / sizeof(double);
  return {reinterpret_cast<const int*>(at), at + index_doubles, n};
}

}  // namespace

// The two-domain split of the factors (assembly/metis_ordering.hpp) and the work space of the
// solve that runs the domains on two cores. Outside the anonymous namespace: Handles, declared
// in the header, holds one.
struct TwoDomainSolve {
  int first = 0, second = 0;   // the domains' sizes, in pivot order; the separator follows
  bool split = false;          // the last full factorization kept the domains apart
  std::vector<double> x;       // the permuted right-hand side
  std::vector<double> second_to_separator;  // the second domain's updates of the separator's rows
  TwoCoreChoice two_cores;     // the domains side by side when that is faster
};

namespace {

int two_domains_for_klu(int n, int* column_start, int* row_index, int* perm, klu_common* common) {
  const TwoDomainOrder order = two_domain_order(n, column_start, row_index, perm);
  auto& solve = *static_cast<TwoDomainSolve*>(common->user_data);
  solve.first = order.first;
  solve.second = order.second;
  return static_cast<int>(std::min<long>(order.entries, std::numeric_limits<int>::max()));
}

// Whether KLU's pivoting kept the two domains apart (docs/theory.md, Eq. T1): no column of the first domain reaches a
// row of the second in L, and no column of the second reaches a row of the first in U. (A row
// taken from the separator as a pivot could; the ordering makes that unlikely, not impossible.)
bool factors_split(const klu_numeric& f, const TwoDomainSolve& d) {
  // The solve permutes but does not scale the rows (Handles sets scale = -1: no Rs).
  if (f.nblocks != 1 || f.Rs != nullptr || d.first <= 0 || d.second <= 0) return false;
  const int separator = d.first + d.second;
  const auto* lu = static_cast<const double*>(f.LUbx[0]);
  for (int k = 0; k < d.first; ++k) {
    const FactorColumn c = factor_column(lu, f.Lip, f.Llen, k);
    for (int p = 0; p < c.length; ++p) {
      if (c.rows[p] >= d.first && c.rows[p] < separator) return false;
    }
  }
  for (int k = d.first; k < separator; ++k) {
    const FactorColumn c = factor_column(lu, f.Uip, f.Ulen, k);
    for (int p = 0; p < c.length; ++p) {
      if (c.rows[p] < d.first) return false;
    }
  }
  return true;
}

}  // namespace

struct KluLinearSystem::Handles {
  klu_common common{};
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  TwoDomainSolve two_domains;

  Handles() {
    klu_defaults(&common);
    // No row scaling and no input check (-1): the assembler already sizes the constraint rows
    // like the force block (docs/theory.md), and the pattern is valid by construction (sorted, no
    // repeats: SparseLinearSystem::build_storage). Scaling and checking at every
    // refactorization cost 9 % of a roof's time step.
    common.scale = -1;
  }
  void order_by(KluOrdering ordering, KluBlocks blocks) {
    common.ordering = 0;  // AMD
    common.btf = blocks == KluBlocks::triangular ? 1 : 0;
    common.user_order = nullptr;
    common.user_data = nullptr;
    if (ordering == KluOrdering::nested_dissection) {
      common.ordering = 3;
      common.user_order = nested_dissection_for_klu;
    } else if (ordering == KluOrdering::two_domains) {
      common.ordering = 3;
      common.user_order = two_domains_for_klu;
      common.user_data = &two_domains;
      common.btf = 0;  // one block, whose factors split as the order does
    }
  }
  ~Handles() {
    if (numeric != nullptr) klu_free_numeric(&numeric, &common);
    if (symbolic != nullptr) klu_free_symbolic(&symbolic, &common);
  }
};

KluLinearSystem::KluLinearSystem(KluOrdering ordering, KluBlocks blocks)
    : klu_(std::make_unique<Handles>()), requested_ordering_(ordering), blocks_(blocks) {}
KluLinearSystem::~KluLinearSystem() = default;

void KluLinearSystem::analyze_pattern() {
  if (klu_->numeric != nullptr) klu_free_numeric(&klu_->numeric, &klu_->common);
  if (klu_->symbolic != nullptr) klu_free_symbolic(&klu_->symbolic, &klu_->common);
  ordering_ = requested_ordering_;
  if (ordering_ == KluOrdering::automatic) {
    ordering_ = factored_size() >= kTwoDomainUnknowns ? KluOrdering::two_domains : KluOrdering::amd;
  }
  klu_->order_by(ordering_, blocks_);
  TwoDomainSolve& d = klu_->two_domains;
  d = {};
  klu_->symbolic = klu_analyze(factored_size(), column_start_.data(), row_index_.data(), &klu_->common);
  if (klu_->symbolic == nullptr) throw std::runtime_error("KLU could not analyse the matrix pattern");
  if (ordering_ == KluOrdering::two_domains) {  // the solve's work space, once per pattern
    d.x.resize(static_cast<std::size_t>(factored_size()));
    d.second_to_separator.resize(static_cast<std::size_t>(factored_size() - d.first - d.second));
  }
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
  k.two_domains.split = false;  // until these factors are found split
  ++full_factorizations_;
  k.numeric = klu_factor(column_start_.data(), row_index_.data(), values_.data(), k.symbolic, &k.common);
  if (k.numeric == nullptr || k.common.status == KLU_SINGULAR) {
    const int column = k.common.singular_col;
    FactorizationStatus status = singular(0.0);
    if (status.null_vectors.size() == 0 && column >= 0 && column < factored_size()) {
      // Too large for an SVD: KLU's first zero pivot names one unknown of the null space.
      status.null_vectors = Eigen::VectorXd::Unit(size_, unknown_of(column));
    }
    if (k.numeric != nullptr) klu_free_numeric(&k.numeric, &k.common);
    return status;
  }
  klu_rcond(k.symbolic, k.numeric, &k.common);
  reciprocal_condition_at_full_ = k.common.rcond;
  values_at_full_.assign(values_.begin(), values_.begin() + column_start_.back());
  if (!(k.common.rcond > kSingularReciprocalCondition)) {
    const double rcond = k.common.rcond;
    klu_free_numeric(&k.numeric, &k.common);
    return singular(rcond);
  }
  k.two_domains.split = ordering_ == KluOrdering::two_domains && factors_split(*k.numeric, k.two_domains);
  FactorizationStatus status;
  status.reciprocal_condition = k.common.rcond;
  return status;
}

void KluLinearSystem::restore_pivot_memory(std::span<const double> memory) {
  if (factored_size() == 0 || memory.size() != static_cast<std::size_t>(column_start_.back())) return;
  const std::vector<double> values = values_;
  std::copy(memory.begin(), memory.end(), values_.begin());
  factorize_fully();
  values_ = values;
}

double KluLinearSystem::factor_nonzeros() const {
  return klu_->numeric != nullptr ? static_cast<double>(klu_->numeric->lnz) + klu_->numeric->unz : 0.0;
}

double KluLinearSystem::factor_operations() const {
  if (klu_->numeric == nullptr) return 0.0;
  klu_common common = klu_->common;  // klu_flops writes its count there; this object stays as it is
  return klu_flops(klu_->symbolic, klu_->numeric, &common) != 0 ? common.flops : 0.0;
}

bool KluLinearSystem::solves_by_two_domains() const {
  return klu_->numeric != nullptr && klu_->two_domains.split;
}

void KluLinearSystem::solve_pattern(double* rhs) {
  if (solves_by_two_domains()) {
    solve_two_domains(rhs);
    return;
  }
  klu_solve(klu_->symbolic, klu_->numeric, factored_size(), 1, rhs, &klu_->common);
}

void KluLinearSystem::solve_two_domains(double* rhs) {
  const klu_numeric& f = *klu_->numeric;
  TwoDomainSolve& d = klu_->two_domains;
  const int n = factored_size();
  const int separator = d.first + d.second;
  const auto* lu = static_cast<const double*>(f.LUbx[0]);
  const auto* diagonal = static_cast<const double*>(f.Udiag);
  double* x = d.x.data();
  double* second_to_separator = d.second_to_separator.data();
  for (int k = 0; k < n; ++k) x[k] = rhs[f.Pnum[k]];
  // L y = P b (docs/theory.md, Eq. T2): a domain's columns reach its own rows and the separator's.
  const auto forward = [&](int begin, int end, double* separator_rows) {
    for (int k = begin; k < end; ++k) {
      const FactorColumn c = factor_column(lu, f.Lip, f.Llen, k);
      const double xk = x[k];
      for (int p = 0; p < c.length; ++p) {
        const int row = c.rows[p];
        if (row >= separator) separator_rows[row - separator] -= c.values[p] * xk;
        else x[row] -= c.values[p] * xk;
      }
    }
  };
  // U x = y from the last column back (Eq. T3): a domain's columns reach only its own rows.
  const auto backward = [&](int begin, int end) {
    for (int k = end - 1; k >= begin; --k) {
      const FactorColumn c = factor_column(lu, f.Uip, f.Ulen, k);
      const double xk = x[k] /= diagonal[k];
      for (int p = 0; p < c.length; ++p) x[c.rows[p]] -= c.values[p] * xk;
    }
  };
  std::fill(second_to_separator, second_to_separator + (n - separator), 0.0);
  d.two_cores.run(true, [&] { forward(0, d.first, x + separator); },
                 [&] { forward(d.first, separator, second_to_separator); });
  for (int k = separator; k < n; ++k) x[k] += second_to_separator[k - separator];
  forward(separator, n, x + separator);
  backward(separator, n);
  d.two_cores.run(true, [&] { backward(0, d.first); }, [&] { backward(d.first, separator); });
  const int* column_order = klu_->symbolic->Q;
  for (int k = 0; k < n; ++k) rhs[column_order[k]] = x[k];
}

}  // namespace deploydyn
