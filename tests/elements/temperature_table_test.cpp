// Every element type with a material whose E and α follow temperature tables (docs/theory.md,
// "Temperature-dependent material properties"): its ∂f/∂λ (the thermal continuation's ∂r/∂λ,
// T = T_ref + λΔT(t)), its ∂f/∂t through ΔT(t) and the gradients, and its tangent ∂f/∂q
// against central differences of the internal force, at a deformed configuration; and a
// table of constant values gives the plain number's forces to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/finite_difference.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// E and α tables of a steel data sheet (T_ref = 20 °C, the default). The points below keep T
// inside one interval of each table (76 °C at λ = 0.8, 90 °C at λ = 1, t = 0.7 s), where the
// law is smooth, so that central differences see no kink.
const std::string kTables =
    "materials:\n"
    "  steel: {E: {temperature_C: [-50, 20, 150, 400], value: [2.15e11, 2.1e11, 1.9e11, 1.6e11]},\n"
    "          alpha: {temperature_C: [-50, 20, 150, 400], value: [1.0e-5, 1.2e-5, 1.35e-5, 1.5e-5]},\n"
    "          density: 7850}\n";
// The same constants as tables of equal values, and as plain numbers.
const std::string kConstantTables =
    "materials:\n"
    "  steel: {E: {temperature_C: [-50, 400], value: [2.1e11, 2.1e11]},\n"
    "          alpha: {temperature_C: [0], value: [1.2e-5]}, density: 7850}\n";
const std::string kPlain = "materials: {steel: {E: 2.1e11, alpha: 1.2e-5, density: 7850}}\n";

// ΔT(t) and the through-depth differences rise smoothly over 2 s.
const std::string kHeating = "{type: smooth_step, t0: 0, v0: 0, t1: 2, v1: 250}";
const std::string kGradient = "{type: smooth_step, t0: 0, v0: 0, t1: 2, v1: 40}";
const std::string kCooledGradient = "{type: smooth_step, t0: 0, v0: 0, t1: 2, v1: -25}";

struct ElementCase {
  const char* name;
  std::string elements;  // the model without its materials
};

std::vector<ElementCase> element_cases() {
  return {
      {"bar 2D", "nodes: {A: [0, 0], B: [1.3, 0.4]}\nelements: {1: {nodes: [A, B], area: 1.0e-4, material: steel, dT: " +
                     kHeating + "}}\n"},
      {"bar 3D", "nodes: {A: [0, 0, 0], B: [1.3, 0.4, -0.5]}\nelements: {1: {nodes: [A, B], area: 1.0e-4, material: steel, dT: " +
                     kHeating + "}}\n"},
      {"cable 2D", "nodes: {A: [0, 0], B: [1.3, 0.4]}\nelements: {1: {type: cable, nodes: [A, B], area: 1.0e-5, "
                   "material: steel, dT: " + kHeating + "}}\n"},
      {"cable 3D", "nodes: {A: [0, 0, 0], B: [1.3, 0.4, -0.5]}\nelements: {1: {type: cable, nodes: [A, B], area: 1.0e-5, "
                   "material: steel, dT: " + kHeating + "}}\n"},
      {"beam 2D with a gradient",
       "nodes: {A: [0, 0], B: [0.9, 0.3]}\nelements: {1: {type: beam, nodes: [A, B], area: 1.0e-4, inertia_z: 8.0e-10, "
       "material: steel, height_y: 0.01, dT_gradient_y: " + kGradient + ", dT: " + kHeating + "}}\n"},
      {"beam 2D, G given",
       "nodes: {A: [0, 0], B: [0.9, 0.3]}\nelements: {1: {type: beam, nodes: [A, B], area: 1.0e-4, inertia_z: 8.0e-10, "
       "material: steel, shear_modulus: 7.0e10, dT: " + kHeating + "}}\n"},
      {"beam 3D with gradients",
       "nodes: {A: [0, 0, 0], B: [0.9, 0.3, 0.2]}\nelements: {1: {type: beam, nodes: [A, B], area: 1.0e-4, "
       "inertia_y: 6.0e-10, inertia_z: 8.0e-10, torsion: 1.2e-9, orientation: [0, 0, 1], material: steel, "
       "height_y: 0.01, height_z: 0.012, dT_gradient_y: " + kGradient + ", dT_gradient_z: " + kCooledGradient +
           ", dT: " + kHeating + "}}\n"},
  };
}

constexpr double kTime_s = 0.7;
constexpr double kFactor = 0.8;
// The force is smooth in λ, t and q at these points: central differences err by h²|f'''|/6
// (≈ 1e-9 relative at these steps) and round-off ε|f|/h (≈ 1e-10 relative). A missing E(T)
// term alone changes ∂f/∂λ by |E'| ΔT / E ≈ 1e-2 of itself.
constexpr double kFactorStep = 1e-4;
constexpr double kTimeStep_s = 1e-4;
constexpr double kCoordinateStep_m = 1e-7;
constexpr double kRelativeTolerance = 1e-6;

// The element groups' sums: f(q, t, λ), ∂f/∂λ, ∂f/∂t (λ = 1) and K = ∂f/∂q (dense).
class Forces {
 public:
  explicit Forces(const Model& model) : model_(model), assembler_(model_) {}

  const Assembler& assembler() const { return assembler_; }
  Eigen::VectorXd force(const Eigen::VectorXd& q, double t, double factor) const {
    Eigen::VectorXd f;
    assembler_.internal_force(q, t, factor, f);
    return f;
  }
  Eigen::VectorXd per_factor(const Eigen::VectorXd& q, double t, double factor) const {
    Eigen::VectorXd f;
    assembler_.thermal_force_derivative(q, t, factor, f);
    return f;
  }
  // No loads, drivers or multipliers: the static residual's ∂r/∂t is the elements' ∂f/∂t.
  Eigen::VectorXd per_time(const Eigen::VectorXd& q, double t) const {
    Eigen::VectorXd dr, dphi;
    assembler_.static_residual_time_derivative(q, t, Eigen::VectorXd::Zero(assembler_.n_equations()), dr, dphi);
    return dr;
  }
  Eigen::MatrixXd tangent(const Eigen::VectorXd& q, double t, double factor) const {
    const int n = assembler_.n_dofs();
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
    for (const auto& group : assembler_.element_groups()) {
      std::vector<MatrixEntry> entries;
      group->append_matrix_entries(entries);
      std::vector<double> values(entries.size(), 0.0);
      std::vector<int> slots(entries.size());
      for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
      const int* slot = slots.data();
      group->add_iteration_matrix({q, t, factor}, {1.0, 0.0}, values, slot);
      for (std::size_t i = 0; i < entries.size(); ++i) k(entries[i].row, entries[i].col) += values[i];
    }
    return k;
  }

 private:
  Model model_;
  Assembler assembler_;
};

// Stretched by 2 % (a cable stays taut) and moved off the initial state.
Eigen::VectorXd deformed(const Assembler& assembler) {
  const Eigen::VectorXd q0 = assembler.initial_coordinates();
  return 1.02 * q0 + 0.003 * Eigen::VectorXd::LinSpaced(q0.size(), -1.0, 1.0);
}

void expect_close(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric, double tolerance) {
  const double scale = analytic.lpNorm<Eigen::Infinity>();
  ASSERT_GT(scale, 0.0) << "the test must exercise a non-zero derivative";
  EXPECT_LE((analytic - numeric).lpNorm<Eigen::Infinity>(), tolerance * scale)
      << "analytic\n" << analytic << "\nnumeric\n" << numeric;
}

TEST(TemperatureTables, ThermalFactorDerivativeMatchesDifferences) {
  for (const ElementCase& c : element_cases()) {
    SCOPED_TRACE(c.name);
    const Forces forces(load_model_from_string(c.elements + kTables, c.name));
    const Eigen::VectorXd q = deformed(forces.assembler());
    const Eigen::MatrixXd numeric = testing::central_jacobian(
        [&](const Eigen::VectorXd& x) { return forces.force(q, kTime_s, x[0]); }, Eigen::VectorXd::Constant(1, kFactor),
        kFactorStep);
    expect_close(forces.per_factor(q, kTime_s, kFactor), numeric, kRelativeTolerance);
  }
}

TEST(TemperatureTables, TimeDerivativeMatchesDifferences) {
  for (const ElementCase& c : element_cases()) {
    SCOPED_TRACE(c.name);
    const Forces forces(load_model_from_string(c.elements + kTables, c.name));
    const Eigen::VectorXd q = deformed(forces.assembler());
    const Eigen::MatrixXd numeric = testing::central_jacobian(
        [&](const Eigen::VectorXd& x) { return forces.force(q, x[0], 1.0); }, Eigen::VectorXd::Constant(1, kTime_s),
        kTimeStep_s);
    expect_close(forces.per_time(q, kTime_s), numeric, kRelativeTolerance);
  }
}

TEST(TemperatureTables, TangentMatchesDifferences) {
  for (const ElementCase& c : element_cases()) {
    SCOPED_TRACE(c.name);
    const Forces forces(load_model_from_string(c.elements + kTables, c.name));
    const Eigen::VectorXd q = deformed(forces.assembler());
    const Eigen::MatrixXd numeric = testing::central_jacobian(
        [&](const Eigen::VectorXd& x) { return forces.force(x, kTime_s, kFactor); }, q, kCoordinateStep_m);
    expect_close(forces.tangent(q, kTime_s, kFactor), numeric, kRelativeTolerance);
  }
}

// E(T) enters: the force of the tables differs from the constant-material one by about
// (E(T) − E(T_ref))/E(T_ref), so a kernel that kept E(T_ref) fails here.
TEST(TemperatureTables, TheForceFollowsE) {
  for (const ElementCase& c : element_cases()) {
    SCOPED_TRACE(c.name);
    const Forces tables(load_model_from_string(c.elements + kTables, c.name));
    const Forces plain(load_model_from_string(c.elements + kPlain, c.name));
    const Eigen::VectorXd q = deformed(tables.assembler());
    const Eigen::VectorXd a = tables.force(q, kTime_s, kFactor), b = plain.force(q, kTime_s, kFactor);
    EXPECT_GT((a - b).lpNorm<Eigen::Infinity>(), 1e-3 * b.lpNorm<Eigen::Infinity>());
  }
}

TEST(TemperatureTables, ConstantTablesEqualPlainNumbers) {
  constexpr double kRoundOff = 1e-13;
  for (const ElementCase& c : element_cases()) {
    SCOPED_TRACE(c.name);
    const Forces tables(load_model_from_string(c.elements + kConstantTables, c.name));
    const Forces plain(load_model_from_string(c.elements + kPlain, c.name));
    const Eigen::VectorXd q = deformed(plain.assembler());
    for (const double factor : {0.0, kFactor, 1.0}) {
      const Eigen::VectorXd f = plain.force(q, kTime_s, factor);
      EXPECT_LE((tables.force(q, kTime_s, factor) - f).lpNorm<Eigen::Infinity>(), kRoundOff * f.lpNorm<Eigen::Infinity>());
      const Eigen::MatrixXd k = plain.tangent(q, kTime_s, factor);
      EXPECT_LE((tables.tangent(q, kTime_s, factor) - k).lpNorm<Eigen::Infinity>(), kRoundOff * k.lpNorm<Eigen::Infinity>());
      const Eigen::VectorXd d = plain.per_factor(q, kTime_s, factor);
      EXPECT_LE((tables.per_factor(q, kTime_s, factor) - d).lpNorm<Eigen::Infinity>(), kRoundOff * d.lpNorm<Eigen::Infinity>());
    }
    const Eigen::VectorXd rate = plain.per_time(q, kTime_s);
    EXPECT_LE((tables.per_time(q, kTime_s) - rate).lpNorm<Eigen::Infinity>(), kRoundOff * rate.lpNorm<Eigen::Infinity>());
  }
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
