#include "deploydyn/thermal/conduction_network.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace deploydyn::thermal {

namespace {

// The representative of `node` among the nodes joints link (union–find, path halving).
int cluster_of(std::map<int, int>& parent, int node) {
  if (!parent.contains(node)) return node;
  while (parent.at(node) != node) node = parent[node] = parent.at(parent.at(node));
  return node;
}

// K_N = diag(Σ_n B_in) − B G⁻¹ Bᵀ of a cluster of nodes linked by joints (header).
void add_cluster(std::span<const ConductingMember> members, const std::vector<int>& nodes,
                 const std::map<int, std::vector<int>>& at_node, std::span<const ConductingJoint> joints,
                 std::vector<Eigen::Triplet<double>>& entries) {
  std::map<int, Eigen::Index> local_node, local_member;
  for (const int node : nodes) local_node.emplace(node, std::ssize(local_node));
  std::vector<int> touching;
  for (const int node : nodes) {
    const auto found = at_node.find(node);
    if (found == at_node.end()) continue;
    for (const int i : found->second) {
      if (local_member.emplace(i, std::ssize(touching)).second) touching.push_back(i);
    }
  }
  const auto n_nodes = std::ssize(nodes);
  const auto n_touching = std::ssize(touching);
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n_nodes, n_nodes);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n_touching, n_nodes);
  for (const int i : touching) {
    const ConductingMember& member = members[static_cast<std::size_t>(i)];
    for (const int end : {member.node_a, member.node_b}) {
      const auto node = local_node.find(end);
      if (node == local_node.end()) continue;
      b(local_member.at(i), node->second) += member.half_conductance_W_K;
      g(node->second, node->second) += member.half_conductance_W_K;
    }
  }
  if (!(b.sum() > 0.0)) return;
  for (const ConductingJoint& joint : joints) {
    const auto a = local_node.find(joint.node_a);
    if (a == local_node.end() || !(joint.conductance_W_K > 0.0)) continue;
    const Eigen::Index ia = a->second, ib = local_node.at(joint.node_b);
    g(ia, ia) += joint.conductance_W_K;
    g(ib, ib) += joint.conductance_W_K;
    g(ia, ib) -= joint.conductance_W_K;
    g(ib, ia) -= joint.conductance_W_K;
  }
  // A node of the cluster that no member reaches but through joints still holds no heat; G is
  // positive definite as the cluster is connected and some member reaches it.
  const Eigen::MatrixXd k = Eigen::MatrixXd(b.rowwise().sum().asDiagonal()) - b * g.ldlt().solve(b.transpose());
  for (Eigen::Index r = 0; r < n_touching; ++r) {
    for (Eigen::Index c = 0; c < n_touching; ++c) {
      // Symmetric to round-off: the mean of the two halves keeps it exactly so.
      entries.emplace_back(touching[static_cast<std::size_t>(r)], touching[static_cast<std::size_t>(c)],
                           0.5 * (k(r, c) + k(c, r)));
    }
  }
}

}  // namespace

ConductionNetwork::ConductionNetwork(std::span<const ConductingMember> members,
                                     std::span<const ConductingJoint> joints) {
  const auto n = static_cast<Eigen::Index>(members.size());
  std::map<int, std::vector<int>> at_node;  // node → the members ending there
  for (std::size_t i = 0; i < members.size(); ++i) {
    at_node[members[i].node_a].push_back(static_cast<int>(i));
    at_node[members[i].node_b].push_back(static_cast<int>(i));
  }
  // The clusters of nodes that conducting joints link, by their representatives.
  std::map<int, int> parent;
  for (const ConductingJoint& joint : joints) {
    if (!(joint.conductance_W_K > 0.0) || joint.node_a == joint.node_b) continue;
    ++conducting_joints_;
    parent.try_emplace(joint.node_a, joint.node_a);
    parent.try_emplace(joint.node_b, joint.node_b);
    const int a = cluster_of(parent, joint.node_a), b = cluster_of(parent, joint.node_b);
    if (a != b) parent[a] = b;
  }
  std::map<int, std::vector<int>> clusters;  // representative → its nodes
  for (const auto& [node, up] : parent) clusters[cluster_of(parent, node)].push_back(node);
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, 0.0);  // every diagonal, for the heat capacities
  for (const auto& [node, meeting] : at_node) {
    if (meeting.size() < 2) continue;
    ++shared_nodes_;
    if (parent.contains(node)) continue;  // in a cluster, below
    double total = 0.0;
    for (const int i : meeting) total += members[static_cast<std::size_t>(i)].half_conductance_W_K;
    if (!(total > 0.0)) continue;
    for (const int i : meeting) {
      const double gi = members[static_cast<std::size_t>(i)].half_conductance_W_K;
      entries.emplace_back(i, i, gi);
      for (const int j : meeting) entries.emplace_back(i, j, -gi * members[static_cast<std::size_t>(j)].half_conductance_W_K / total);
    }
  }
  for (const auto& [representative, nodes] : clusters) add_cluster(members, nodes, at_node, joints, entries);
  conductance_.resize(n, n);
  conductance_.setFromTriplets(entries.begin(), entries.end());
  iteration_matrix_ = conductance_;
  factor_.analyzePattern(iteration_matrix_);
}

Eigen::VectorXd ConductionNetwork::backward_euler_step(std::span<const LumpedMember> bodies,
                                                       const Eigen::VectorXd& start_K, double step_s,
                                                       const Eigen::VectorXd& absorbed_W, const Surroundings& around) {
  const Eigen::Index n = start_K.size();
  Eigen::VectorXd t = start_K;
  Eigen::VectorXd residual(n);
  const double sink4 = fourth_power(around.sink_temperature_K);
  constexpr int kMaxIterations = 50;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    // F(T) = m c (T − T⁰) − h (Q − P_rad(T) − P_conv(T) − K T); its Jacobian h K + diag(…).
    residual.noalias() = step_s * (conductance_ * t);
    iteration_matrix_ = step_s * conductance_;
    for (Eigen::Index i = 0; i < n; ++i) {
      const LumpedMember& body = bodies[static_cast<std::size_t>(i)];
      const double radiation_W_K4 = body.emissivity * kStefanBoltzmann_W_m2K4 * body.surface_area_m2;
      residual[i] += body.heat_capacity_J_K * (t[i] - start_K[i]) -
                     step_s * (absorbed_W[i] - emitted_power_W(body, t[i], sink4) - convected_power_W(body, t[i], around));
      iteration_matrix_.coeffRef(i, i) += body.heat_capacity_J_K +
                                          step_s * (4.0 * radiation_W_K4 * t[i] * t[i] * t[i] +
                                                    around.convection_W_m2K * body.surface_area_m2);
    }
    factor_.factorize(iteration_matrix_);
    if (factor_.info() != Eigen::Success) break;
    Eigen::VectorXd change = factor_.solve(-residual);
    // A first step below 0 K (a cold member suddenly lit) goes half-way towards 0 instead.
    for (Eigen::Index i = 0; i < n; ++i) {
      if (t[i] + change[i] <= 0.0) change[i] = -0.5 * t[i];
    }
    t += change;
    if (change.cwiseAbs().maxCoeff() <= 1e-12 * t.cwiseAbs().maxCoeff()) return t;
  }
  throw std::runtime_error(fmt::format("thermal: the conduction between members did not converge over a step of {} s",
                                       step_s));
}

}  // namespace deploydyn::thermal
