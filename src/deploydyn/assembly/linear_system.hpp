#pragma once
// The iteration matrix of a Newton step and its solution, behind one interface so that a
// sparse back end can replace the dense one without touching elements or solvers.
//
// Layout: n_dofs unknowns q first, then one row/column per constraint equation:
//   [ A   s Bᵀ ]
//   [ s B  0   ]
// Elements and constraints add small blocks at global indices; the back end decides storage.

#include <Eigen/Core>
#include <span>
#include <string>

namespace deploydyn {

struct FactorizationStatus {
  bool ok = true;
  double reciprocal_condition = 1.0;  // estimate; 0 when exactly singular
  std::string message;                // why it failed
  // When singular: the unit vector the matrix (nearly) maps to zero, in the unknowns' order
  // (q, then λ). Its large entries name the free motion or the redundant constraints.
  Eigen::VectorXd null_vector;
};

class LinearSystem {
 public:
  virtual ~LinearSystem() = default;

  virtual int size() const = 0;
  virtual void set_zero() = 0;
  // Adds `block` at rows × cols (global indices).
  virtual void add(std::span<const int> rows, std::span<const int> cols,
                   const Eigen::Ref<const Eigen::MatrixXd>& block) = 0;
  // Adds `block` and its transpose mirrored: rows × cols and cols × rows (for B and Bᵀ).
  virtual void add_symmetric_pair(std::span<const int> rows, std::span<const int> cols,
                                  const Eigen::Ref<const Eigen::MatrixXd>& block) = 0;
  virtual FactorizationStatus factorize() = 0;
  // Overwrites rhs with the solution; call after a successful factorize().
  virtual void solve(Eigen::Ref<Eigen::VectorXd> rhs) const = 0;
};

}  // namespace deploydyn
