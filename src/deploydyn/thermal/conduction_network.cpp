#include "deploydyn/thermal/conduction_network.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <vector>

namespace deploydyn::thermal {

ConductionNetwork::ConductionNetwork(std::span<const ConductingMember> members) {
  const auto n = static_cast<Eigen::Index>(members.size());
  std::map<int, std::vector<int>> at_node;  // node → the members ending there
  for (std::size_t i = 0; i < members.size(); ++i) {
    at_node[members[i].node_a].push_back(static_cast<int>(i));
    at_node[members[i].node_b].push_back(static_cast<int>(i));
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, 0.0);  // every diagonal, for the heat capacities
  for (const auto& [node, meeting] : at_node) {
    if (meeting.size() < 2) continue;
    ++shared_nodes_;
    double total = 0.0;
    for (const int i : meeting) total += members[static_cast<std::size_t>(i)].half_conductance_W_K;
    if (!(total > 0.0)) continue;
    for (const int i : meeting) {
      const double gi = members[static_cast<std::size_t>(i)].half_conductance_W_K;
      entries.emplace_back(i, i, gi);
      for (const int j : meeting) entries.emplace_back(i, j, -gi * members[static_cast<std::size_t>(j)].half_conductance_W_K / total);
    }
  }
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
  constexpr int kMaxIterations = 50;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    // F(T) = m c (T − T⁰) − h (Q − P_rad(T) − P_conv(T) − K T); its Jacobian h K + diag(…).
    residual.noalias() = step_s * (conductance_ * t);
    iteration_matrix_ = step_s * conductance_;
    for (Eigen::Index i = 0; i < n; ++i) {
      const LumpedMember& body = bodies[static_cast<std::size_t>(i)];
      const double radiation_W_K4 = body.emissivity * kStefanBoltzmann_W_m2K4 * body.surface_area_m2;
      residual[i] += body.heat_capacity_J_K * (t[i] - start_K[i]) -
                     step_s * (absorbed_W[i] - emitted_power_W(body, t[i], around) - convected_power_W(body, t[i], around));
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
