#pragma once
// Conduction between members that share a node (docs/theory.md, "Conduction between members").
// Each member is a lumped body at one temperature T_i (thermal/member_heat_balance.hpp) whose
// heat reaches its ends along half its length, a conductance g_i = 2 k_i A_i / L_i (W/K). A node
// that n ≥ 2 members share holds no heat: its temperature T_n = Σ g_i T_i / Σ g_i makes the flows
// into it sum to zero, and member i receives g_i (T_n − T_i). Over all shared nodes this is
//
//   P_cond = −K T,   K = Σ_nodes (diag(g) − g gᵀ / Σ g)   (W/K, symmetric, K·1 = 0)
//
// so conduction moves heat between members and creates none. The backward Euler step of the
// coupled members
//
//   m_i c_i (T_i − T_i⁰) = h [Q_i − ε σ A_i (T_i⁴ − T_sink⁴) − h_c A_i (T_i − T_air) − (K T)_i]
//
// is solved by Newton's method: its matrix h K + diag(m c + h (4 ε σ A T³ + h_c A)) is
// symmetric positive definite, factored sparse (Cholesky, its pattern analysed once).
// Joints between distinct nodes (pins, hinges) conduct nothing: a worn hinge's contact
// conductance is small and uncertain.

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <span>

#include "deploydyn/thermal/member_heat_balance.hpp"

namespace deploydyn::thermal {

// A member as conduction sees it: its end nodes and the conductance of each half, 2 k A / L.
struct ConductingMember {
  int node_a = 0, node_b = 0;
  double half_conductance_W_K = 0.0;
};

class ConductionNetwork {
 public:
  explicit ConductionNetwork(std::span<const ConductingMember> members);

  const Eigen::SparseMatrix<double>& conductance() const { return conductance_; }  // K (W/K)
  int shared_nodes() const { return shared_nodes_; }

  // The temperatures at the end of a step of `step_s` from `start_K`, every member's absorbed
  // power taken at the step's end (W). Throws std::runtime_error when Newton does not converge.
  Eigen::VectorXd backward_euler_step(std::span<const LumpedMember> bodies, const Eigen::VectorXd& start_K,
                                      double step_s, const Eigen::VectorXd& absorbed_W, const Surroundings& around);

 private:
  Eigen::SparseMatrix<double> conductance_;
  Eigen::SparseMatrix<double> iteration_matrix_;  // work space with K's pattern and the diagonal
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
  int shared_nodes_ = 0;
};

}  // namespace deploydyn::thermal
