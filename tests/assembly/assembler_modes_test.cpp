// The assembler evaluated in two mode states (Assembler::at_modes) in any order gives, in each,
// what an assembler that saw only that state gives: the modes are passed with every evaluation,
// not kept between them (issue 34). A chain of two hinges, one latched and the other sliding,
// then the other way round: the residual's parts, Φ, the constraint rates, the rows in force
// and the iteration matrix compared bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/elements/hinge/hinge_history.hpp"
#include "deploydyn/io/model_loader.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using namespace hinge::history;

// Everything the assembler gives in one mode state, side by side.
struct Evaluation {
  Eigen::VectorXd internal, rate, switched, phi, reaction, phi_t, bias;
  std::vector<double> matrix;
  int rows_in_force = 0;
  double strain_energy = 0.0;

  bool operator==(const Evaluation&) const = default;
};

class AssemblerModes : public ::testing::Test {
 protected:
  Model model_ = load_model_from_string(R"(
nodes: {A: [-1, 0.1], H: [0, 0], B: [0.8, 0.5], K: [1.15, 1.44]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements:
  a: {nodes: [A, H], area: 1.0e-4, material: steel, mass: 1, dT: 40}
  b: {nodes: [H, B], area: 1.0e-4, material: steel, mass: 1}
  c: {nodes: [B, K], area: 1.0e-4, material: steel, mass: 1}
  h1: {type: hinge, nodes: [A, H, B], stiffness: 7, rest_angle: -2.0, damping: 0.3, friction: 0.2,
       pin_radius: 0.01, latch: -2.9}
  h2: {type: hinge, nodes: [H, B, K], stiffness: 5, rest_angle: -2.1, damping: 0.2, friction: 0.3,
       pin_radius: 0.01, latch: -2.8}
supports: [{node: A}]
)",
                                        "chain");

  // Hinge `latched_hinge` latched at its latch angle (its lock on, no friction), the other
  // free and sliding in the + direction (friction on).
  Eigen::VectorXd history(const Assembler& assembler, int latched_hinge) const {
    Eigen::VectorXd h = assembler.initial_history();
    EXPECT_EQ(h.size(), 2 * kHistorySlots);
    for (int i = 0; i < 2; ++i) {
      const bool latched = i == latched_hinge;
      h[i * kHistorySlots + kMode] = static_cast<double>(latched ? HingeMode::latched : HingeMode::free);
      h[i * kHistorySlots + kLockAngle] = *model_.hinges[i].latch_rad;
      h[i * kHistorySlots + kSlip] = latched ? 0.0 : 1.0;
    }
    return h;
  }

  static Evaluation evaluate(const AssemblerAtModes& at, LinearSystem& system) {
    const Assembler& assembler = at.assembler();
    const int n = assembler.n_dofs();
    Eigen::VectorXd q = assembler.initial_coordinates(), v = Eigen::VectorXd::LinSpaced(n, 0.3, -0.7);
    for (int i = 0; i < n; ++i) q[i] += 0.05 * std::sin(1.0 + 3.0 * i);
    const Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(assembler.n_equations(), -2.0, 3.0);
    const double t = 0.3;
    Evaluation e;
    at.internal_force(q, t, 1.0, e.internal);
    at.rate_force(q, v, t, e.rate);
    at.switched_constraint_force(q, t, lambda, e.switched);
    at.constraints_and_force(q, t, lambda, e.phi, e.reaction);
    at.constraint_rates(q, v, t, e.phi_t, e.bias);
    at.iteration_matrix(q, t, 1.0, lambda, {1.0, 1.0, 2.0, 0.5, &v}, system);
    e.matrix.assign(system.values().begin(), system.values().end());
    e.rows_in_force = at.n_equations_in_force();
    e.strain_energy = at.strain_energy(q, t);
    return e;
  }

  // In `latched_hinge`'s state, on an assembler that has evaluated nothing else.
  Evaluation alone(int latched_hinge) const {
    const Assembler assembler(model_);
    const auto system = make_linear_system(assembler);
    const Eigen::VectorXd h = history(assembler, latched_hinge);
    return evaluate(assembler.at_modes(h), *system);
  }
};

TEST_F(AssemblerModes, TwoModeStatesInAnyOrderGiveWhatEachGivesAlone) {
  const Evaluation first_alone = alone(0), second_alone = alone(1);
  // The two states differ wherever the modes act, so that an assembler mixing them up would show.
  EXPECT_NE(first_alone.rate, second_alone.rate);  // friction on the sliding hinge only
  EXPECT_NE(first_alone.phi, second_alone.phi);    // the latched hinge's lock
  EXPECT_NE(first_alone.switched, second_alone.switched);
  EXPECT_NE(first_alone.matrix, second_alone.matrix);
  const Assembler assembler(model_);
  EXPECT_EQ(first_alone.rows_in_force, assembler.n_equations() - assembler.n_switched_equations() + 1);

  const auto system = make_linear_system(assembler);
  const Eigen::VectorXd first = history(assembler, 0), second = history(assembler, 1);
  for (const auto& order : {std::vector<int>{0, 1, 0, 0, 1, 1, 0}, std::vector<int>{1, 0, 1, 1, 0}}) {
    for (const int which : order) {
      const Evaluation e = evaluate(assembler.at_modes(which == 0 ? first : second), *system);
      EXPECT_EQ(e, which == 0 ? first_alone : second_alone) << "hinge h" << which + 1 << " latched";
    }
  }
}

// The Assembler's own evaluations, and a solver given a plain Assembler, are those with every
// hinge free: the locks off, whatever a view evaluated before.
TEST_F(AssemblerModes, TheAssemblersOwnEvaluationsHaveEveryHingeFree) {
  const Assembler assembler(model_);
  const auto system = make_linear_system(assembler);
  const Evaluation free_modes = evaluate(assembler.at_modes(assembler.free_modes()), *system);
  const Eigen::VectorXd latched = history(assembler, 0);
  evaluate(assembler.at_modes(latched), *system);
  EXPECT_EQ(evaluate(assembler, *system), free_modes);  // the implicit view of a plain Assembler
  EXPECT_EQ(assembler.n_equations_in_force(), assembler.n_equations() - assembler.n_switched_equations());
  Eigen::VectorXd phi;
  assembler.constraints(assembler.initial_coordinates(), 0.0, phi);
  EXPECT_TRUE(phi.tail(assembler.n_switched_equations()).isZero(0.0));  // free: the locks read Φ = 0
}

// A free lock's B, Bᵀ and H(λ) are zeros whose entries the pattern keeps, and the iteration
// matrix moves past them instead of adding them (Assembler::for_each_matrix_block, ZeroBlock).
// With h1 free (not sliding) the matrix is the one with h1 latched at λ = 0 but for h1's lock
// row and column: zeros and s on the diagonal instead of B. Every other entry in its place.
TEST_F(AssemblerModes, AFreeLockLeavesEveryOtherEntryInItsPlace) {
  const Assembler assembler(model_);
  const auto system = make_linear_system(assembler);
  const Eigen::VectorXd latched = history(assembler, 0);
  Eigen::VectorXd free = latched;
  free[kMode] = static_cast<double>(HingeMode::free);  // h1: slip 0 as latched, so no friction
  const int n = assembler.n_dofs();
  Eigen::VectorXd q = assembler.initial_coordinates(), v = Eigen::VectorXd::LinSpaced(n, 0.3, -0.7);
  for (int i = 0; i < n; ++i) q[i] += 0.05 * std::sin(1.0 + 3.0 * i);
  const int lock_row = n + assembler.n_equations() - assembler.n_switched_equations();  // h1's lock
  Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(assembler.n_equations(), -2.0, 3.0);
  lambda[lock_row - n] = 0.0;  // latched: H(λ) = 0 as well
  const double scale = 2.0;
  const auto dense = [&](const Eigen::VectorXd& h) {
    assembler.at_modes(h).iteration_matrix(q, 0.3, 1.0, lambda, {1.0, 1.0, scale, 0.5, &v}, *system);
    return system->to_dense();
  };
  const Eigen::MatrixXd with_free = dense(free), with_latched = dense(latched);
  EXPECT_GT(with_latched.row(lock_row).head(n).cwiseAbs().maxCoeff(), 0.0);  // B: the test sees the lock
  Eigen::MatrixXd expected = with_latched;
  expected.row(lock_row).setZero();
  expected.col(lock_row).setZero();
  expected(lock_row, lock_row) = scale;
  EXPECT_TRUE(with_free.cwiseEqual(expected).all()) << (with_free - expected).cwiseAbs().maxCoeff();
}

}  // namespace
}  // namespace deploydyn
