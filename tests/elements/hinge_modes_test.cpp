// A hinge group evaluated at two mode states (sliding free, latched) in any order gives, at
// each, what a group that saw only that state gives: its modes travel in the evaluation point,
// not in the group (issue 34). Forces, rate forces, the iteration-matrix block, the results and
// the lock constraint are compared bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/elements/hinge/hinge_history.hpp"
#include "deploydyn/elements/hinge/hinge_kind.hpp"
#include "deploydyn/elements/switching_group.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/model/dof_map.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using namespace hinge::history;

// Everything a group gives at one point, side by side.
struct Evaluation {
  Eigen::VectorXd force;       // f_int + f_d
  std::vector<double> matrix;  // c_K (K + ∂f_d/∂q) + c_D ∂f_d/∂q̇, in the entries' order
  std::vector<double> results;
  Eigen::VectorXd lock_phi;
  Eigen::MatrixXd lock_jacobian;
  bool lock_active = false;

  bool operator==(const Evaluation&) const = default;
};

class HingeModes : public ::testing::Test {
 protected:
  Model model_ = load_model_from_string(R"(
nodes: {A: [-1, 0.1], H: [0, 0], B: [0.8, 0.5]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements:
  a: {nodes: [A, H], area: 1.0e-4, material: steel, mass: 1, dT: 40}
  b: {nodes: [H, B], area: 1.0e-4, material: steel, mass: 1}
  h: {type: hinge, nodes: [A, H, B], stiffness: 7, rest_angle: -2.0, damping: 0.3, friction: 0.2,
      pin_radius: 0.01, latch: -2.9}
supports: [{node: A}]
)",
                                        "hinge");
  DofMap dofs_{model_};

  std::unique_ptr<ElementGroup> make_group() const { return hinge_kind().make_group(model_, dofs_); }
  static const SwitchingGroup& switching(const ElementGroup& group) {
    return dynamic_cast<const SwitchingGroup&>(group);
  }

  // Free and sliding in the + direction (friction on), or latched at −2.9 rad (friction off,
  // the lock on).
  std::vector<double> history(HingeMode mode) const {
    const std::unique_ptr<ElementGroup> group = make_group();
    std::vector<double> h(static_cast<std::size_t>(switching(*group).n_history()));
    switching(*group).initial_history(h);
    h[kMode] = static_cast<double>(mode);
    h[kLockAngle] = -2.9;
    h[kSlip] = 1.0;
    h[kDissipated] = mode == HingeMode::latched ? 0.25 : 0.0;
    return h;
  }

  Evaluation evaluate(const ElementGroup& group, const SwitchedConstraint& lock,
                      const std::vector<double>& history) const {
    const int n = dofs_.n_dofs();
    Eigen::VectorXd q = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::LinSpaced(n, 0.3, -0.7);
    for (int i = 0; i < n; ++i) q[i] = 0.05 * std::sin(1.0 + 3.0 * i);
    q[dofs_.index(0, 0)] += -1.0, q[dofs_.index(0, 1)] += 0.1;  // near the model's nodes
    q[dofs_.index(2, 0)] += 0.8, q[dofs_.index(2, 1)] += 0.5;
    const EvaluationPoint at{q, 0.3, 1.0, &v, history};

    Evaluation e;
    e.force = Eigen::VectorXd::Zero(n);
    group.add_internal_force(at, e.force);
    group.add_rate_force(at, e.force);
    std::vector<MatrixEntry> entries;
    group.append_matrix_entries(entries);
    e.matrix.assign(entries.size(), 0.0);
    std::vector<int> slots(entries.size());
    for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
    const int* slot = slots.data();
    group.add_iteration_matrix(at, {1.0, 0.0, 2.0}, e.matrix, slot);
    e.results.resize(hinge_kind().quantities(2).size());
    group.results(0, at, e.results);
    e.lock_phi.resize(lock.n_equations());
    e.lock_jacobian.resize(lock.n_equations(), static_cast<Eigen::Index>(lock.dofs().size()));
    lock.evaluate(at, e.lock_phi, e.lock_jacobian);
    e.lock_active = lock.active(history);
    return e;
  }

  // At `history` on a group (and its lock) that has seen nothing else.
  Evaluation alone(const std::vector<double>& history) const {
    const std::unique_ptr<ElementGroup> group = make_group();
    const auto locks = switching(*group).make_switched_constraints();
    return evaluate(*group, *locks.at(0), history);
  }
};

TEST_F(HingeModes, TwoModeStatesInAnyOrderGiveWhatEachGivesAlone) {
  const std::vector<double> sliding = history(HingeMode::free), latched = history(HingeMode::latched);
  const Evaluation sliding_alone = alone(sliding), latched_alone = alone(latched);
  // The two states differ where the modes act, so that a group mixing them up would show.
  EXPECT_NE(sliding_alone.force, latched_alone.force);    // friction only while sliding
  EXPECT_NE(sliding_alone.matrix, latched_alone.matrix);  // its ∂f/∂q
  EXPECT_NE(sliding_alone.results, latched_alone.results);
  EXPECT_FALSE(sliding_alone.lock_active);
  EXPECT_TRUE(latched_alone.lock_active);
  EXPECT_NE(latched_alone.lock_phi[0], 0.0);  // θ + 2.9 at this q

  const std::unique_ptr<ElementGroup> group = make_group();
  const auto locks = switching(*group).make_switched_constraints();
  ASSERT_EQ(locks.size(), 1u);
  for (const auto& order : {std::vector<int>{0, 1, 0, 0, 1, 1, 0}, std::vector<int>{1, 0, 1, 1, 0}}) {
    for (const int which : order) {
      const Evaluation e = evaluate(*group, *locks[0], which == 0 ? sliding : latched);
      EXPECT_EQ(e, which == 0 ? sliding_alone : latched_alone) << (which == 0 ? "sliding" : "latched");
    }
  }
}

}  // namespace
}  // namespace deploydyn
