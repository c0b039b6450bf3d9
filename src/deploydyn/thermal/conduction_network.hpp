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
//
// A joint between distinct nodes a and b (a pin, a hinge) conducts through its contact
// conductance c (W/K), given by the model (a worn hinge's is small and uncertain; none: 0).
// The nodes that joints link form a cluster N; their temperatures, still holding no heat, solve
// G T_N = Bᵀ T with G = diag(Σ g at each node) + the joints' Laplacian, B the members' half
// conductances at the cluster's nodes (B_in = g_i when member i ends at node n), and eliminating
// them gives the cluster's part of K
//
//   K_N = diag(Σ_n B_in) − B G⁻¹ Bᵀ    (symmetric; K_N·1 = 0 since G·1_N = Bᵀ·1)
//
// which for one node is diag(g) − g gᵀ / Σ g, and for two members joined by a pin the series
// conductance 1 / (1/g₁ + 1/c + 1/g₂) between them.

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

// A joint as conduction sees it: its two nodes and their contact conductance (W/K, ≥ 0).
struct ConductingJoint {
  int node_a = 0, node_b = 0;
  double conductance_W_K = 0.0;
};

class ConductionNetwork {
 public:
  explicit ConductionNetwork(std::span<const ConductingMember> members,
                             std::span<const ConductingJoint> joints = {});

  const Eigen::SparseMatrix<double>& conductance() const { return conductance_; }  // K (W/K)
  int shared_nodes() const { return shared_nodes_; }
  int conducting_joints() const { return conducting_joints_; }  // joints with c > 0

  // The temperatures at the end of a step of `step_s` from `start_K`, every member's absorbed
  // power taken at the step's end (W). Throws std::runtime_error when Newton does not converge.
  Eigen::VectorXd backward_euler_step(std::span<const LumpedMember> bodies, const Eigen::VectorXd& start_K,
                                      double step_s, const Eigen::VectorXd& absorbed_W, const Surroundings& around);

 private:
  Eigen::SparseMatrix<double> conductance_;
  Eigen::SparseMatrix<double> iteration_matrix_;  // work space with K's pattern and the diagonal
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
  int shared_nodes_ = 0;
  int conducting_joints_ = 0;
};

}  // namespace deploydyn::thermal
