// The assembler over element groups (elements/element.hpp, local_element_group.hpp): on a
// small heated truss in a deformed state, the assembled global quantities are the derivatives
// they claim to be (STYLE practice 9): f_int = ∂U/∂q, K = ∂f_int/∂q from the iteration
// matrix, ∂f_int/∂(thermal factor) and ∂f_int/∂t through ΔT(t) by differences; M from the
// iteration matrix equals M a; the results name each quantity once per element.
#include <gtest/gtest.h>

#include <random>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "support/finite_difference.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Steps about 1e-6 of the quantity's size: truncation and round-off both ≈ 1e-10 relative.
constexpr double kStep_m = 1e-6;
constexpr double kStepFactor = 1e-6;
constexpr double kStep_s = 1e-6;
constexpr double kDerivativeTolerance = 1e-6;  // relative, in the max norm of the analytic value
constexpr double kExactTolerance = 1e-12;      // same sums in another order: round-off only

// One assembly case: the dimension, and in 2D optionally two beams beside the bars (a mixed
// model: some nodes carry a rotation rz, others not).
struct AssemblyCase {
  int dimension = 2;
  bool beams = false;
};
std::ostream& operator<<(std::ostream& out, const AssemblyCase& c) {
  return out << c.dimension << "D" << (c.beams ? " with beams" : "");
}

// A tetrahedron of bars (in 2D a braced square) with different ΔT(t), moved off its
// reference so that every bar is strained and turned; in the mixed case also beams A–D (with a
// through-section gradient ΔT_gy(t)) and D–E, so that A and D carry rz, B and C do not.
Model heated_truss(const AssemblyCase& which) {
  const int dimension = which.dimension;
  testing::ModelBuilder builder(dimension);
  const int a = builder.node("A", {0.0, 0.0, 0.0});
  const int b = builder.node("B", {1.0, 0.1, 0.0});
  const int c = builder.node("C", {0.2, 0.9, 0.0});
  const int d = builder.node(
      "D", dimension == 3 ? Eigen::Vector3d(0.3, 0.2, 0.8) : Eigen::Vector3d(1.1, 1.0, 0.0));
  int k = 0;
  for (const auto& [i, j] : {std::pair{a, b}, {b, c}, {c, a}, {a, d}, {b, d}, {c, d}}) {
    testing::BarSpec spec;
    spec.youngs_modulus_Pa = 1e9 * (1 + k);
    spec.mass_kg = 0.5 + 0.1 * k;
    spec.temperature_change_C =
        TimeFunction(TimeFunction::SmoothStep{0.0, -40.0 + 20.0 * k, 1.0, 80.0});
    builder.bar(i, j, spec);
    ++k;
  }
  builder.point_mass(d, 0.3);
  builder.analysis().linear_solver = LinearSolverKind::dense;
  Model model = builder.model();
  if (which.beams) {
    const int e = builder.node("E", {1.6, 1.4, 0.0});
    model = builder.model();
    int k = 0;
    for (const auto& [i, j] : {std::pair{a, d}, {d, e}}) {
      BeamElement beam;
      beam.name = "beam" + std::to_string(k);
      beam.node_a = i;
      beam.node_b = j;
      beam.material = 0;
      beam.area_m2 = 1e-4;
      beam.inertia_z_m4 = 2e-9 * (1 + k);
      beam.shear_modulus_Pa = 4e8;
      beam.height_y_m = 0.02;
      beam.reference_length_m = (model.nodes[j].position_m - model.nodes[i].position_m).norm() * 1.01;
      beam.mass_kg = 0.4 + 0.1 * k;
      beam.temperature_change_C = TimeFunction(TimeFunction::SmoothStep{0.0, 10.0, 1.0, -60.0});
      beam.temperature_gradient_y_C = TimeFunction(TimeFunction::SmoothStep{0.2, -30.0 * k, 0.9, 50.0});
      beam.gradient_y_given = true;
      model.beams.push_back(beam);
      ++k;
    }
  }
  return model;
}

Eigen::VectorXd deformed(const Assembler& assembler) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::VectorXd q = assembler.initial_coordinates();
  for (Eigen::Index i = 0; i < q.size(); ++i) q[i] += 0.05 * unit(rng);
  return q;
}

double relative_error(const Eigen::MatrixXd& computed, const Eigen::MatrixXd& reference) {
  return (computed - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

class ElementAssembly : public ::testing::TestWithParam<AssemblyCase> {};

TEST_P(ElementAssembly, ForceTangentAndThermalTermsAreDerivatives) {
  const Model model = heated_truss(GetParam());
  const Assembler assembler(model);
  const Eigen::VectorXd q = deformed(assembler);
  const double t = 0.4;

  Eigen::VectorXd f;
  assembler.internal_force(q, t, 1.0, f);
  const Eigen::VectorXd gradient = testing::central_gradient(
      [&](const Eigen::VectorXd& y) { return assembler.strain_energy(y, t); }, q, kStep_m);
  EXPECT_LT(relative_error(f, gradient), kDerivativeTolerance);

  // The iteration matrix with c_M = 0 and no constraint rows' weight: its force block is K.
  const auto system = make_linear_system(assembler);
  const Eigen::VectorXd lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  assembler.iteration_matrix(q, t, 1.0, lambda, {0.0, 1.0, 1.0}, *system);
  const Eigen::MatrixXd k =
      system->to_dense().topLeftCorner(assembler.n_dofs(), assembler.n_dofs());
  const Eigen::MatrixXd jacobian = testing::central_jacobian(
      [&](const Eigen::VectorXd& y) {
        Eigen::VectorXd g;
        assembler.internal_force(y, t, 1.0, g);
        return g;
      },
      q, kStep_m);
  EXPECT_LT(relative_error(k, jacobian), kDerivativeTolerance);

  Eigen::VectorXd by_factor;
  assembler.thermal_force_derivative(q, t, 1.0, by_factor);
  const Eigen::MatrixXd factor_difference = testing::central_jacobian(
      [&](const Eigen::VectorXd& factor) {
        Eigen::VectorXd g;
        assembler.internal_force(q, t, factor[0], g);
        return g;
      },
      Eigen::VectorXd::Ones(1), kStepFactor);
  EXPECT_LT(relative_error(by_factor, factor_difference), kDerivativeTolerance);

  // ∂r/∂t at fixed q (no loads, no drivers here): f_int's rate through ΔT(t).
  Eigen::VectorXd by_time, dphi;
  assembler.static_residual_time_derivative(q, t, lambda, by_time, dphi);
  const Eigen::MatrixXd time_difference = testing::central_jacobian(
      [&](const Eigen::VectorXd& time) {
        Eigen::VectorXd g;
        assembler.internal_force(q, time[0], 1.0, g);
        return g;
      },
      Eigen::VectorXd::Constant(1, t), kStep_s);
  EXPECT_LT(relative_error(by_time, time_difference), kDerivativeTolerance);
}

TEST_P(ElementAssembly, IterationMatrixMassIsTheMassOperator) {
  const Model model = heated_truss(GetParam());
  const Assembler assembler(model);
  const Eigen::VectorXd q = deformed(assembler);
  const auto system = make_linear_system(assembler);
  const Eigen::VectorXd lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  assembler.iteration_matrix(q, 0.0, 1.0, lambda, {1.0, 0.0, 1.0}, *system);
  const Eigen::MatrixXd mass =
      system->to_dense().topLeftCorner(assembler.n_dofs(), assembler.n_dofs());
  Eigen::MatrixXd applied(assembler.n_dofs(), assembler.n_dofs());
  for (int j = 0; j < assembler.n_dofs(); ++j) {
    Eigen::VectorXd column;
    assembler.mass_times(Eigen::VectorXd::Unit(assembler.n_dofs(), j), column);
    applied.col(j) = column;
  }
  EXPECT_LT(relative_error(mass, applied), kExactTolerance);
}

TEST_P(ElementAssembly, ResultsByQuantityName) {
  const Model model = heated_truss(GetParam());
  const Assembler assembler(model);
  const Eigen::VectorXd q = deformed(assembler);
  ASSERT_EQ(assembler.element_groups().size(), element_kinds().size());
  const std::vector<double> forces = assembler.element_quantity("axial_force_N", q, 0.4);
  const std::vector<double> lengths = assembler.element_quantity("length_m", q, 0.4);
  ASSERT_EQ(forces.size(), model.bars.size() + model.beams.size());
  EXPECT_EQ(element_names(model, "axial_force_N").front(), model.bars.front().name);
  for (std::size_t b = 0; b < model.bars.size(); ++b) {
    const BarElement& bar = model.bars[b];
    const double length = (testing::node_position(assembler, q, bar.node_b) -
                           testing::node_position(assembler, q, bar.node_a))
                              .norm();
    EXPECT_NEAR(lengths[b], length, kExactTolerance * length);
  }
  EXPECT_TRUE(assembler.element_quantity("no such quantity", q, 0.4).empty());
}

INSTANTIATE_TEST_SUITE_P(Dimensions, ElementAssembly,
                         ::testing::Values(AssemblyCase{2, false}, AssemblyCase{3, false},
                                           AssemblyCase{2, true}),
                         [](const ::testing::TestParamInfo<AssemblyCase>& info) {
                           return std::to_string(info.param.dimension) + "D" +
                                  (info.param.beams ? "WithBeams" : "");
                         });

}  // namespace
}  // namespace deploydyn
