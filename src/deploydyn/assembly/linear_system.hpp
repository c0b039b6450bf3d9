#pragma once
// The iteration matrix of a Newton step and its solution, behind one interface so that dense
// and sparse back ends are interchangeable without touching elements or solvers.
//
// Layout: n_dofs unknowns q first, then one row/column per constraint equation:
//   [ A   s Bᵀ ]
//   [ s B  0   ]
// The sparsity pattern is fixed once per model: analyze() receives the (row, col) of every
// value the assembler will write, in the order it writes them, and returns through slots()
// where each one lives in values(). Assembly is then `values[slots[k]] += v_k`: no allocation
// and no search per step. Sparse back ends do their symbolic analysis in analyze() too.

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "deploydyn/model/matrix_entry.hpp"

namespace deploydyn {

struct FactorizationStatus {
  bool ok = true;
  double reciprocal_condition = 1.0;  // estimate; 0 when exactly singular
  std::string message;                // why it failed
  // When singular: orthonormal columns the matrix (nearly) maps to zero, in the unknowns' order
  // (q, then λ), one for each independent free motion or redundant constraint (at least one);
  // their large entries name them. Empty when the back end cannot say.
  Eigen::MatrixXd null_vectors;
};

class LinearSystem {
 public:
  virtual ~LinearSystem() = default;

  // Sets the pattern: a size × size matrix whose only non-zeros are at `entries` (repeats
  // share a slot, their values add up). Call once; every value starts at zero.
  void analyze(int size, std::span<const MatrixEntry> entries) {
    size_ = size;
    slots_.assign(entries.size(), 0);
    build_storage(entries);
  }
  int size() const { return size_; }
  // Where the value of entry k (in analyze()'s order) lives in values().
  std::span<const int> slots() const { return slots_; }
  std::span<double> values() { return values_; }
  void set_zero() { std::fill(values_.begin(), values_.end(), 0.0); }

  // LU factorization of the current values; a singular or non-finite matrix is a status.
  FactorizationStatus factorize();
  // How many factorizations were made: a solver that kept an LU of its own knows from it
  // whether the system still holds that LU.
  long factorizations() const { return factorizations_; }
  // Overwrites rhs with the solution; call after a successful factorize().
  virtual void solve(Eigen::Ref<Eigen::VectorXd> rhs) = 0;
  // "dense LU", "KLU", "UMFPACK": for reports and benchmarks.
  virtual const char* name() const = 0;

  // What one factorization hands on to the next (KLU's pivot order, klu_linear_system.hpp), so
  // that a restarted run pivots, and rounds, as the run it continues did; empty when the back
  // end keeps nothing. restore_pivot_memory factorizes with it again.
  virtual std::vector<double> pivot_memory() const { return {}; }
  virtual void restore_pivot_memory(std::span<const double> /*memory*/) {}

  // The matrix as dense, for diagnosis of small systems and for tests.
  Eigen::MatrixXd to_dense() const;
  // The columns the current matrix (nearly) maps to zero: its null space's basis by sparse
  // inverse iteration (assembly/null_space.hpp), or the nearest vector when none is within the
  // tolerance; empty above 50 000 unknowns. A singular factorization reports them, unless
  // deferred: a solver that retries a singular matrix (load steps halved) asks for them once,
  // for the failure it reports.
  Eigen::MatrixXd null_vectors() const;
  void defer_null_vectors(bool defer) { defer_null_vectors_ = defer; }
  bool null_vectors_deferred() const { return defer_null_vectors_; }

 protected:
  // factorize() once the values are known to be finite.
  virtual FactorizationStatus factorize_finite() = 0;
  // The status of a factorization found singular: the message, and for systems small enough
  // the null vector.
  FactorizationStatus singular(double reciprocal_condition) const;
  // Below this estimated reciprocal condition number a solution carries no correct digits
  // (machine epsilon is 2.2e-16), so the matrix is treated as singular.
  static constexpr double kSingularReciprocalCondition = 1e-14;

  // Sizes values_ and fills slots_ for the pattern.
  virtual void build_storage(std::span<const MatrixEntry> entries) = 0;
  // (row, col) of values_[i]; used by to_dense().
  virtual MatrixEntry position(int value_index) const = 0;

  int size_ = 0;
  long factorizations_ = 0;
  std::vector<int> slots_;
  bool defer_null_vectors_ = false;
  std::vector<double> values_;
};

}  // namespace deploydyn
