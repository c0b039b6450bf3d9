// Conduction between members that share a node (thermal/conduction_network.hpp) against closed
// forms: the conductance matrix of a node, two members in series relaxing as the scheme's exact
// solution says, a chain carrying one heat flow through every node (Fourier's law), a star that
// keeps its heat, and the coupled step with radiation meeting its own equations. Joints: two
// members joined by a pin conduct as their halves and the contact in series, a cluster of
// joints creates no heat, and a stiff contact conducts as a shared node.

#include "deploydyn/thermal/conduction_network.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <vector>

namespace deploydyn::thermal {
namespace DEPLOYDYN_FILE_SCOPE {

// A body that only stores heat (no radiation, no convection): capacity C (J/K).
LumpedMember store(double capacity_J_K) {
  LumpedMember body;
  body.heat_capacity_J_K = capacity_J_K;
  body.surface_area_m2 = 0.06;
  return body;
}

// K symmetric, K·1 = 0 and K ≥ 0: conduction moves heat and creates none. K's eigenvalues,
// ascending.
Eigen::VectorXd expect_no_heat_created(const ConductionNetwork& network) {
  const Eigen::MatrixXd k = Eigen::MatrixXd(network.conductance());
  EXPECT_LT((k - k.transpose()).norm(), 1e-15);
  EXPECT_LT((k * Eigen::VectorXd::Ones(k.rows())).norm(), 1e-14);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(k);
  EXPECT_GT(eigen.eigenvalues().minCoeff(), -1e-14);
  return eigen.eigenvalues();
}

TEST(ConductionNetwork, ANodeOfTwoMembersConductsAsTheirHalvesInSeries) {
  const std::vector<ConductingMember> members{{0, 1, 2.0}, {1, 2, 6.0}};
  const ConductionNetwork network(members);
  EXPECT_EQ(network.shared_nodes(), 1);  // nodes 0 and 2 are ends of one member only
  const Eigen::MatrixXd k = Eigen::MatrixXd(network.conductance());
  const double series = 2.0 * 6.0 / (2.0 + 6.0);
  EXPECT_NEAR(k(0, 0), series, 1e-15);
  EXPECT_NEAR(k(1, 1), series, 1e-15);
  EXPECT_NEAR(k(0, 1), -series, 1e-15);
  EXPECT_NEAR(k(1, 0), -series, 1e-15);
}

TEST(ConductionNetwork, ANodeOfManyMembersCreatesNoHeat) {
  // Four members meeting at node 9, two of them also at node 5: K symmetric, K·1 = 0, K ≥ 0.
  const std::vector<ConductingMember> members{{9, 1, 1.0}, {2, 9, 3.0}, {9, 5, 0.5}, {5, 9, 7.0}};
  const ConductionNetwork network(members);
  EXPECT_EQ(network.shared_nodes(), 2);
  expect_no_heat_created(network);
}

TEST(ConductionNetwork, TwoMembersInSeriesRelaxAsTheSchemeSays) {
  // C1 ḋ1 = −G (T1 − T2), C2 ḋ2 = +G (T1 − T2): backward Euler keeps C1 T1 + C2 T2 and takes the
  // difference d to d / (1 + h G (1/C1 + 1/C2)) every step.
  const double c1 = 300.0, c2 = 900.0, g1 = 2.0, g2 = 6.0, step_s = 20.0;
  const double g = g1 * g2 / (g1 + g2);
  const std::vector<ConductingMember> members{{0, 1, g1}, {1, 2, g2}};
  ConductionNetwork network(members);
  const std::vector<LumpedMember> bodies{store(c1), store(c2)};
  Eigen::VectorXd t(2);
  t << 400.0, 250.0;
  const double heat_J = c1 * t[0] + c2 * t[1];
  double difference_K = t[0] - t[1];
  for (int step = 0; step < 30; ++step) {
    t = network.backward_euler_step(bodies, t, step_s, Eigen::Vector2d::Zero(), Surroundings{});
    difference_K /= 1.0 + step_s * g * (1.0 / c1 + 1.0 / c2);
    EXPECT_NEAR(t[0] - t[1], difference_K, 1e-10);
    EXPECT_NEAR(c1 * t[0] + c2 * t[1], heat_J, 1e-9 * heat_J);
  }
}

TEST(ConductionNetwork, AChainCarriesOneHeatFlowThroughEveryNode) {
  // Five members in a line; the first absorbs Q, the last loses it by convection to air at
  // T_air; the steady state carries Q through every node: T_i − T_i+1 = Q / G_i,i+1 and
  // h_c A (T_last − T_air) = Q.
  const std::vector<double> half{4.0, 2.5, 6.0, 1.0, 3.0};
  std::vector<ConductingMember> members;
  for (int i = 0; i < 5; ++i) members.push_back({i, i + 1, half[static_cast<std::size_t>(i)]});
  ConductionNetwork network(members);
  std::vector<LumpedMember> bodies(5, store(50.0));
  Surroundings around;
  around.air_temperature_K = 280.0;
  around.convection_W_m2K = 10.0;
  for (int i = 0; i < 4; ++i) bodies[static_cast<std::size_t>(i)].surface_area_m2 = 0.0;  // only the last convects
  Eigen::VectorXd absorbed = Eigen::VectorXd::Zero(5);
  const double heat_W = 3.0;
  absorbed[0] = heat_W;
  Eigen::VectorXd t = Eigen::VectorXd::Constant(5, 280.0);
  for (int step = 0; step < 400; ++step) t = network.backward_euler_step(bodies, t, 1.0e3, absorbed, around);
  for (int i = 0; i < 4; ++i) {
    const double a = half[static_cast<std::size_t>(i)], b = half[static_cast<std::size_t>(i) + 1];
    EXPECT_NEAR(t[i] - t[i + 1], heat_W * (1.0 / a + 1.0 / b), 1e-9) << i;
  }
  EXPECT_NEAR(t[4] - 280.0, heat_W / (10.0 * 0.06), 1e-9);
}

TEST(ConductionNetwork, TheCoupledStepMeetsItsEquationsWithRadiation) {
  // Three radiating members at one node, one in the sun: after a step the residual of every
  // member's balance, m c (T − T⁰) = h (Q − ε σ A (T⁴ − T_s⁴) + P_cond), is at round-off, and
  // the conducted powers sum to zero.
  const std::vector<ConductingMember> members{{0, 3, 0.8}, {1, 3, 0.4}, {2, 3, 1.2}};
  ConductionNetwork network(members);
  std::vector<LumpedMember> bodies(3);
  for (LumpedMember& body : bodies) {
    body.heat_capacity_J_K = 120.0;
    body.emissivity = 0.8;
    body.surface_area_m2 = 0.06;
  }
  Surroundings around;
  around.sink_temperature_K = 3.0;
  const Eigen::Vector3d start(200.0, 150.0, 300.0), absorbed(16.0, 0.0, 0.0);
  const double step_s = 60.0;
  const Eigen::VectorXd t = network.backward_euler_step(bodies, start, step_s, absorbed, around);
  const Eigen::VectorXd conducted = -(network.conductance() * t);
  EXPECT_NEAR(conducted.sum(), 0.0, 1e-12);
  for (int i = 0; i < 3; ++i) {
    const LumpedMember& body = bodies[static_cast<std::size_t>(i)];
    const double balance = body.heat_capacity_J_K * (t[i] - start[i]) -
                           step_s * (absorbed[i] - emitted_power_W(body, t[i], around) + conducted[i]);
    EXPECT_NEAR(balance, 0.0, 1e-9) << i;
  }
  EXPECT_GT(t[0], t[1]);  // the lit member is warmest...
  EXPECT_GT(t[1], start[1]);  // ...and warms the cold one through the node
}

// The steady state of two members, the first absorbing Q, the second losing it to air by
// convection (h_c A): T₂ − T_air = Q / (h_c A), T₁ − T₂ = Q / G. Steps long enough that
// m c (T − T⁰) / h is below the tolerance.
Eigen::VectorXd steady_pair(ConductionNetwork& network, double heat_W, const Surroundings& around) {
  std::vector<LumpedMember> bodies(2, store(50.0));
  bodies[0].surface_area_m2 = 0.0;  // only the second convects
  Eigen::VectorXd t = Eigen::VectorXd::Constant(2, around.air_temperature_K);
  for (int step = 0; step < 5; ++step) t = network.backward_euler_step(bodies, t, 1.0e12, Eigen::Vector2d(heat_W, 0.0), around);
  return t;
}

TEST(ConductionNetwork, TwoMembersJoinedByAPinConductAsTheirHalvesAndTheContactInSeries) {
  // Member 0 ends at node 1, member 1 starts at node 2; a pin joins nodes 1 and 2 with c.
  const double g1 = 2.0, g2 = 6.0, c = 0.5;
  const std::vector<ConductingMember> members{{0, 1, g1}, {2, 3, g2}};
  const std::vector<ConductingJoint> joints{{1, 2, c}};
  ConductionNetwork network(members, joints);
  EXPECT_EQ(network.shared_nodes(), 0);
  EXPECT_EQ(network.conducting_joints(), 1);
  const double series = 1.0 / (1.0 / g1 + 1.0 / c + 1.0 / g2);
  const Eigen::MatrixXd k = Eigen::MatrixXd(network.conductance());
  EXPECT_NEAR(k(0, 0), series, 1e-14);
  EXPECT_NEAR(k(1, 1), series, 1e-14);
  EXPECT_NEAR(k(0, 1), -series, 1e-14);
  EXPECT_NEAR(k(1, 0), -series, 1e-14);

  Surroundings around;
  around.air_temperature_K = 290.0;
  around.convection_W_m2K = 10.0;
  const double heat_W = 0.8;
  const Eigen::VectorXd t = steady_pair(network, heat_W, around);
  EXPECT_NEAR(t[1] - 290.0, heat_W / (10.0 * 0.06), 1e-9);
  EXPECT_NEAR(t[0] - t[1], heat_W / series, 1e-9);
}

TEST(ConductionNetwork, AJointWithoutConductanceLeavesItsMembersApart) {
  const std::vector<ConductingMember> members{{0, 1, 2.0}, {2, 3, 6.0}};
  const std::vector<ConductingJoint> joints{{1, 2, 0.0}};
  const ConductionNetwork network(members, joints);
  EXPECT_EQ(network.conducting_joints(), 0);
  EXPECT_EQ(Eigen::MatrixXd(network.conductance()).cwiseAbs().maxCoeff(), 0.0);
}

TEST(ConductionNetwork, AStiffContactConductsAsASharedNode) {
  // Three members at node 5, two more at node 6 pinned to it with c ≫ g: as if all five met at
  // one node, to O(g / c).
  const std::vector<ConductingMember> shared{{0, 5, 1.0}, {1, 5, 3.0}, {5, 2, 0.5}, {3, 5, 2.0}, {5, 4, 4.0}};
  const std::vector<ConductingMember> pinned{{0, 5, 1.0}, {1, 5, 3.0}, {5, 2, 0.5}, {3, 6, 2.0}, {6, 4, 4.0}};
  const std::vector<ConductingJoint> stiff{{5, 6, 1.0e9}};
  const Eigen::MatrixXd one_node = Eigen::MatrixXd(ConductionNetwork(shared).conductance());
  const Eigen::MatrixXd joined = Eigen::MatrixXd(ConductionNetwork(pinned, stiff).conductance());
  EXPECT_LT((joined - one_node).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(ConductionNetwork, JointsCreateNoHeat) {
  // A cluster of four nodes linked by three joints, one node (7) reached by no member, another
  // member with both ends in the cluster; and a shared node outside it: K symmetric, K·1 = 0,
  // K ≥ 0.
  const std::vector<ConductingMember> members{{0, 1, 1.0}, {2, 9, 3.0}, {1, 3, 0.5}, {3, 9, 7.0}, {9, 4, 2.0}};
  const std::vector<ConductingJoint> joints{{1, 2, 0.3}, {2, 7, 1.1}, {7, 3, 0.2}};
  const ConductionNetwork network(members, joints);
  EXPECT_EQ(network.conducting_joints(), 3);
  const Eigen::VectorXd eigenvalues = expect_no_heat_created(network);
  EXPECT_GT(eigenvalues(1), 1e-6);  // one network: only uniform temperatures are free
}

}  // namespace
}  // namespace deploydyn::thermal
