// Cable element (docs/theory.md, "Cables") through its element group, in 2D and 3D: on taut
// states the force is the gradient of the energy, the tangent the Jacobian of the force, and
// the thermal-factor and time derivatives (through ΔT(t) and a winch's L0(t)) match finite
// differences; a slack cable has no force, stiffness or energy but keeps its mass; a taut
// cable is the bar; a pretension gives the initial cable that tension.
#include "deploydyn/elements/cable/cable.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "deploydyn/elements/bar/bar_kind.hpp"
#include "deploydyn/elements/cable/cable_kind.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/elements/switching_group.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "support/finite_difference.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Step 1e-6 (m, s and thermal factor alike, on unit-sized quantities): truncation O(1e-12),
// round-off O(1e-10) relative, far below the tolerance.
constexpr double kStep = 1e-6;
constexpr double kDerivativeTolerance = 1e-6;  // relative, in the norm of the analytic value
constexpr double kMassTolerance = 1e-14;       // exact rational multiples of m: round-off only
constexpr int kConfigurations = 6;

constexpr double kYoungsModulus_Pa = 2e11;
constexpr double kArea_m2 = 1e-4;
constexpr double kAxialStiffness_N = kYoungsModulus_Pa * kArea_m2;
constexpr double kAlpha = 1.2e-5;  // 1/°C
constexpr double kMass_kg = 0.37;
// A winch that reels in from 1.0 m to 0.8 m, and heating to 150 °C, over the same 2 s: both
// enter ∂f/∂t.
const TimeFunction kRestLength_m(TimeFunction::SmoothStep{0.0, 1.0, 2.0, 0.8});
const TimeFunction kTemperatureChange_C(TimeFunction::SmoothStep{0.0, 0.0, 2.0, 150.0});

double relative_error(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& reference) {
  return (analytic - reference).norm() / reference.norm();
}

// One cable (or, for the comparison, one bar) between two nodes, bound to its unknowns.
class OneCable {
 public:
  OneCable(int dimension, const ElementKind& kind = cable_kind()) {
    model_.dimension = dimension;
    const double z = dimension == 3 ? 0.3 : 0.0;
    model_.nodes = {{"A", Eigen::Vector3d(0.1, 0.2, z), 0.0},
                    {"B", Eigen::Vector3d(0.9, 0.7, -z), 0.0}};
    Material& steel = model_.materials.emplace_back();
    steel.name = "steel";
    steel.youngs_modulus_Pa = kYoungsModulus_Pa;
    steel.expansion_per_C = kAlpha;
    model_.analysis.mass = MassMatrixKind::consistent;
    if (&kind == &cable_kind()) {
      CableElement cable;
      cable.name = "c";
      cable.node_a = 0;
      cable.node_b = 1;
      cable.area_m2 = kArea_m2;
      cable.mass_kg = kMass_kg;
      cable.rest_length_m = kRestLength_m;
      cable.rest_length_from = CableRestLength::given;
      cable.temperature_change_C = kTemperatureChange_C;
      cable.temperature_given = true;
      model_.cables.push_back(cable);
    } else {
      BarElement bar;
      bar.name = "b";
      bar.node_a = 0;
      bar.node_b = 1;
      bar.area_m2 = kArea_m2;
      bar.mass_kg = kMass_kg;
      bar.reference_length_m = kRestLength_m.value(0.0);
      bar.temperature_change_C = kTemperatureChange_C;
      bar.temperature_given = true;
      model_.bars.push_back(bar);
    }
    dofs_ = std::make_unique<DofMap>(model_);
    group_ = kind.make_group(model_, *dofs_);
  }

  int n() const { return 2 * model_.dimension; }
  const ElementGroup& group() const { return *group_; }

  Eigen::VectorXd force(const Eigen::VectorXd& q, double t, double factor = 1.0) const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n());
    group_->add_internal_force({q, t, factor}, f);
    return f;
  }
  // The group's iteration-matrix block with c_K = 1, c_M = 0, as a dense matrix.
  Eigen::MatrixXd tangent(const Eigen::VectorXd& q, double t, double factor = 1.0) const {
    std::vector<MatrixEntry> entries;
    group_->append_matrix_entries(entries);
    std::vector<double> values(entries.size(), 0.0);
    std::vector<int> slots(entries.size());
    for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
    const int* slot = slots.data();
    group_->add_iteration_matrix({q, t, factor}, {1.0, 0.0}, values, slot);
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n(), n());
    for (std::size_t i = 0; i < entries.size(); ++i) k(entries[i].row, entries[i].col) += values[i];
    return k;
  }
  std::vector<double> results(const Eigen::VectorXd& q, double t) const {
    std::vector<double> out(cable_kind().quantities(model_.dimension).size());
    group_->results(0, {q, t}, out);
    return out;
  }

 private:
  Model model_;
  std::unique_ptr<DofMap> dofs_;
  std::unique_ptr<ElementGroup> group_;
};

// [x_a; x_b] with the cable `stretch` times its rest length L0(t) long, in a random direction.
Eigen::VectorXd configuration(int dimension, double length_m, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::VectorXd x_a(dimension), direction(dimension);
  for (int i = 0; i < dimension; ++i) x_a[i] = unit(rng), direction[i] = unit(rng);
  Eigen::VectorXd q(2 * dimension);
  q << x_a, x_a + length_m * direction.normalized();
  return q;
}

// Taut: 2 % to 12 % longer than L0(t), far more than the thermal strain (≤ 1.8e-3), so that
// every finite-difference step stays on the smooth taut branch.
Eigen::VectorXd taut_configuration(int dimension, double t, std::mt19937& rng) {
  std::uniform_real_distribution<double> stretch(1.02, 1.12);
  return configuration(dimension, kRestLength_m.value(t) * stretch(rng), rng);
}

double time_of(int c) { return 0.3 + 0.25 * c; }  // inside the winch's and the heating's ramps

class CableGroup : public ::testing::TestWithParam<int> {};
INSTANTIATE_TEST_SUITE_P(Cable, CableGroup, ::testing::Values(2, 3),
                         [](const auto& info) { return std::to_string(info.param) + "D"; });

TEST_P(CableGroup, TautForceIsTheGradientOfStrainEnergy) {
  const int dimension = GetParam();
  const OneCable cable(dimension);
  std::mt19937 rng(20261123);
  for (int c = 0; c < kConfigurations; ++c) {
    const double t = time_of(c);
    const Eigen::VectorXd q = taut_configuration(dimension, t, rng);
    const auto energy = [&](const Eigen::VectorXd& y) { return cable.group().strain_energy({y, t}); };
    EXPECT_LT(relative_error(cable.force(q, t), testing::central_gradient(energy, q, kStep)),
              kDerivativeTolerance)
        << "t = " << t << ", q = " << q.transpose();
  }
}

TEST_P(CableGroup, TautTangentIsTheJacobianOfInternalForce) {
  const int dimension = GetParam();
  const OneCable cable(dimension);
  std::mt19937 rng(5);
  for (int c = 0; c < kConfigurations; ++c) {
    const double t = time_of(c);
    const Eigen::VectorXd q = taut_configuration(dimension, t, rng);
    const auto force = [&](const Eigen::VectorXd& y) { return cable.force(y, t); };
    EXPECT_LT(relative_error(cable.tangent(q, t), testing::central_jacobian(force, q, kStep)),
              kDerivativeTolerance)
        << "t = " << t;
  }
}

// ∂f/∂(thermal factor) and ∂f/∂t, the latter through ΔT(t) and the winch's L0(t) together.
TEST_P(CableGroup, ThermalDerivativeAndTimeRateMatchFiniteDifferences) {
  const int dimension = GetParam();
  const OneCable cable(dimension);
  std::mt19937 rng(41);
  for (int c = 0; c < kConfigurations; ++c) {
    const double t = time_of(c);
    const Eigen::VectorXd q = taut_configuration(dimension, t, rng);
    Eigen::VectorXd by_factor = Eigen::VectorXd::Zero(cable.n()), rate = by_factor;
    cable.group().add_thermal_force_derivative({q, t, 1.0}, by_factor);
    cable.group().add_thermal_force_rate({q, t}, rate);
    const Eigen::VectorXd fd_factor =
        (cable.force(q, t, 1.0 + kStep) - cable.force(q, t, 1.0 - kStep)) / (2.0 * kStep);
    const Eigen::VectorXd fd_time = (cable.force(q, t + kStep) - cable.force(q, t - kStep)) / (2.0 * kStep);
    EXPECT_LT(relative_error(by_factor, fd_factor), kDerivativeTolerance) << "t = " << t;
    EXPECT_LT(relative_error(rate, fd_time), kDerivativeTolerance) << "t = " << t;
  }
}

// Continuation scales ΔT by a factor μ: a cable taut at μ = 0.5 may be slack at μ = 1, so the
// derivative must be taken at μ (Eq. C4), not at 1.
TEST_P(CableGroup, ThermalDerivativeIsTakenAtTheThermalFactor) {
  const int dimension = GetParam();
  const OneCable cable(dimension);
  std::mt19937 rng(23);
  constexpr double kFactor = 0.5;
  for (int c = 0; c < kConfigurations; ++c) {
    const double t = time_of(c);
    const double thermal_strain = kAlpha * kTemperatureChange_C.value(t);
    // ε = 0.7 ε_t: ε_m = 0.2 ε_t at μ = ½ (taut), −0.3 ε_t at μ = 1 (slack).
    const Eigen::VectorXd q =
        configuration(dimension, kRestLength_m.value(t) * std::sqrt(1.0 + 1.4 * thermal_strain), rng);
    Eigen::VectorXd by_factor = Eigen::VectorXd::Zero(cable.n());
    cable.group().add_thermal_force_derivative({q, t, kFactor}, by_factor);
    const Eigen::VectorXd fd =
        (cable.force(q, t, kFactor + kStep) - cable.force(q, t, kFactor - kStep)) / (2.0 * kStep);
    EXPECT_GT(fd.norm(), 0.0) << "t = " << t;
    EXPECT_LT(relative_error(by_factor, fd), kDerivativeTolerance) << "t = " << t;
  }
}

// The rest-length kernel alone (Eq. C5), at a fixed ΔT: the winch's share of ∂f/∂t.
TEST_P(CableGroup, RestLengthDerivativeMatchesFiniteDifferences) {
  const int dimension = GetParam();
  std::mt19937 rng(17);
  for (int c = 0; c < kConfigurations; ++c) {
    const Eigen::VectorXd q = taut_configuration(dimension, 0.0, rng);
    const auto force_at = [&](double rest_length_m) -> Eigen::VectorXd {
      const bar::Section section{kAxialStiffness_N, rest_length_m, bar::ForceLaw::tension_only};
      if (dimension == 2) {
        return bar::internal_force<2>(bar::evaluate<2>(q.head<2>(), q.tail<2>(), section, 1e-3), section);
      }
      return bar::internal_force<3>(bar::evaluate<3>(q.head<3>(), q.tail<3>(), section, 1e-3), section);
    };
    const double l0 = kRestLength_m.value(0.0);
    const bar::Section section{kAxialStiffness_N, l0, bar::ForceLaw::tension_only};
    const Eigen::VectorXd analytic =
        dimension == 2
            ? Eigen::VectorXd(cable::internal_force_per_rest_length<2>(
                  bar::evaluate<2>(q.head<2>(), q.tail<2>(), section, 1e-3), section))
            : Eigen::VectorXd(cable::internal_force_per_rest_length<3>(
                  bar::evaluate<3>(q.head<3>(), q.tail<3>(), section, 1e-3), section));
    const Eigen::VectorXd fd = (force_at(l0 + kStep) - force_at(l0 - kStep)) / (2.0 * kStep);
    EXPECT_LT(relative_error(analytic, fd), kDerivativeTolerance) << "configuration " << c;
  }
}

// Shorter than L0(t): no force, stiffness, energy or thermal derivatives, reported slack; the
// mass is the cable's still (a rigid translation carries all of it).
TEST_P(CableGroup, SlackCableHasNoForceStiffnessOrEnergyButItsMass) {
  const int dimension = GetParam();
  const OneCable cable(dimension);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> shortening(0.5, 0.99);
  for (int c = 0; c < kConfigurations; ++c) {
    const double t = time_of(c);
    const Eigen::VectorXd q = configuration(dimension, kRestLength_m.value(t) * shortening(rng), rng);
    Eigen::VectorXd by_factor = Eigen::VectorXd::Zero(cable.n()), rate = by_factor;
    cable.group().add_thermal_force_derivative({q, t, 1.0}, by_factor);
    cable.group().add_thermal_force_rate({q, t}, rate);
    EXPECT_EQ(cable.force(q, t).norm(), 0.0) << "t = " << t;
    EXPECT_EQ(cable.tangent(q, t).norm(), 0.0) << "t = " << t;
    EXPECT_EQ(cable.group().strain_energy({q, t}), 0.0) << "t = " << t;
    EXPECT_EQ(by_factor.norm(), 0.0) << "t = " << t;
    EXPECT_EQ(rate.norm(), 0.0) << "t = " << t;
    const std::vector<double> r = cable.results(q, t);
    EXPECT_EQ(r[2], 0.0) << "axial force";
    EXPECT_FALSE(std::signbit(r[2])) << "a slack cable reports +0 N, not −0";
    EXPECT_EQ(r[4], 1.0) << "slack flag";
    EXPECT_LT(r[1], 0.0) << "mechanical strain";
  }
  for (int axis = 0; axis < dimension; ++axis) {
    Eigen::VectorXd translation = Eigen::VectorXd::Zero(cable.n()), momentum = translation;
    translation[axis] = translation[dimension + axis] = 1.0;
    cable.group().add_mass_times(translation, momentum);
    EXPECT_NEAR(translation.dot(momentum), kMass_kg, kMassTolerance * kMass_kg) << "axis " << axis;
  }
}

// Taut, a cable is the bar of the same rest length: the same kernels give the same numbers,
// bit for bit; the reported force is tension, the slack flag 0 and the rest length L0(t).
TEST_P(CableGroup, TautCableIsTheBar) {
  const int dimension = GetParam();
  const OneCable cable(dimension);
  const OneCable bar(dimension, bar_kind());
  std::mt19937 rng(12);
  for (int c = 0; c < kConfigurations; ++c) {
    const Eigen::VectorXd q = taut_configuration(dimension, 0.0, rng);
    const double t = 0.0;  // L0(0) is the bar's reference length
    EXPECT_EQ(cable.force(q, t), bar.force(q, t));
    EXPECT_EQ(cable.tangent(q, t), bar.tangent(q, t));
    EXPECT_EQ(cable.group().strain_energy({q, t}), bar.group().strain_energy({q, t}));
    const std::vector<double> r = cable.results(q, t);
    EXPECT_GT(r[2], 0.0) << "axial force";
    EXPECT_EQ(r[3], kRestLength_m.value(t)) << "rest length";
    EXPECT_EQ(r[4], 0.0) << "slack flag";
  }
}

// end_step: the slack state at the end of each step is the history; a flip is an event, with
// the mechanical strain; before the first step the start's state is read from q_before.
TEST(CableHistory, SlackAndTautFlipsAreEvents) {
  const OneCable cable(2);
  const auto* switching = dynamic_cast<const SwitchingGroup*>(&cable.group());
  ASSERT_NE(switching, nullptr);  // a cable keeps its slack state
  const SwitchingGroup& group = *switching;
  ASSERT_EQ(group.n_history(), 1);
  std::vector<double> start(1), after(1);
  group.initial_history(start);
  Eigen::VectorXd taut(4), slack(4);
  const double l0 = kRestLength_m.value(0.0);
  taut << 0.0, 0.0, 1.05 * l0, 0.0;
  slack << 0.0, 0.0, 0.95 * l0, 0.0;
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(4), lambda;
  std::vector<ElementEvent> events;
  // The first step, taut to taut: nothing happens, the history says taut.
  EXPECT_EQ(group.end_step({0.0, 0.0, taut, v, taut, v, lambda}, start, after, events), StepVerdict::accept);
  EXPECT_TRUE(events.empty());
  EXPECT_EQ(after[0], 0.0);
  // Taut to slack, then slack to slack, then back to taut.
  std::vector<double> before = after;
  group.end_step({0.0, 0.0, taut, v, slack, v, lambda}, before, after, events);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, ElementEventKind::slack);
  EXPECT_LT(events[0].value, 0.0);
  EXPECT_EQ(after[0], 1.0);
  before = after;
  group.end_step({0.0, 0.0, slack, v, slack, v, lambda}, before, after, events);
  EXPECT_EQ(events.size(), 1u);
  before = after;
  group.end_step({0.0, 0.0, slack, v, taut, v, lambda}, before, after, events);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[1].kind, ElementEventKind::taut);
  EXPECT_GT(events[1].value, 0.0);
  EXPECT_EQ(after[0], 0.0);
  // A run that starts slack and stays so reports nothing.
  events.clear();
  group.end_step({0.0, 0.0, slack, v, slack, v, lambda}, start, after, events);
  EXPECT_TRUE(events.empty());
  EXPECT_EQ(after[0], 1.0);
}

// The rest length of a pretension T0 (Eq. C6): the cable at its initial length carries the
// true axial force N = EA ε l/L0 = T0, to round-off; no pretension leaves it at l.
TEST(CablePretension, RestLengthGivesTheInitialCableItsTension) {
  constexpr double kLength_m = 1.7;
  // The strain (l² − L0²)/(2 L0²) cancels to a few ulps of 1 whatever T0, so N = EA ε r is
  // known to a few ulps of EA: 8 ulps · EA = 3.6e-8 N here (2.4e-9 N measured at T0 = 1 N).
  constexpr double kForceRoundOff_N = 8.0 * std::numeric_limits<double>::epsilon() * kAxialStiffness_N;
  for (const double tension_N : {1.0, 1e3, 2e5, 1e6}) {
    const double l0 = cable::rest_length_for_pretension(kLength_m, kAxialStiffness_N, tension_N);
    const bar::Section section{kAxialStiffness_N, l0, bar::ForceLaw::tension_only};
    const bar::State<2> s = bar::evaluate<2>(Eigen::Vector2d::Zero(), Eigen::Vector2d(kLength_m, 0.0), section, 0.0);
    EXPECT_NEAR(s.axial_force_N, tension_N, kForceRoundOff_N) << "T0 = " << tension_N;
  }
  EXPECT_EQ(cable::rest_length_for_pretension(kLength_m, kAxialStiffness_N, 0.0), kLength_m);
}

TEST(CableKind, IsListedWithItsQuantities) {
  const auto kinds = element_kinds();
  EXPECT_NE(std::find(kinds.begin(), kinds.end(), &cable_kind()), kinds.end());
  const ElementKind& kind = cable_kind();
  EXPECT_EQ(kind.name(), "cable");
  for (const int dimension : {2, 3}) {
    EXPECT_EQ(quantity_index(kind, dimension, "axial_force_N"), 2);
    EXPECT_EQ(quantity_index(kind, dimension, "rest_length_m"), 3);
    EXPECT_EQ(quantity_index(kind, dimension, "slack"), 4);
  }
}

}  // namespace
}  // namespace deploydyn
