// The coupling of the members' temperatures to the mechanics (thermal/thermal_coupling.hpp):
// a member that turns changes its absorbed flux as its angle to the sun says; the heat balance
// closes over a run; the example boom's strain is α (T − T_ref) at every output, its
// temperatures cool end-on to the sun and warm broadside towards the radiative equilibrium.
// With shadows, a member that leaves another's shadow takes the sun as the geometry says; with
// section gradients, a clamped tube in the sun takes the moment E I α D / d of its sun-to-shade
// difference D.

#include "deploydyn/thermal/thermal_coupling.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <optional>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/thermal/section_temperature_difference.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"
#include "support/csv_table.hpp"

namespace deploydyn::thermal {
namespace DEPLOYDYN_FILE_SCOPE {

const std::string kBoomExample = std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/thermal/boom_out_of_eclipse.yaml";
constexpr double kSigma = 5.670374419e-8;

TEST(ThermalCoupling, TurningMemberAbsorbsAsItsAngleToTheSunSays) {
  Model model = load_model(kBoomExample, {});
  model.environment->orbit.eclipses.clear();
  ThermalCoupling coupling(model);
  const DofMap dofs(model);
  MotionState state;
  state.q = Eigen::VectorXd::Zero(dofs.n_dofs());
  const double step_s = 1.0;
  // α_s S w L |sin θ|, w = 0.02 m, L = 1 m, the sun along x.
  for (const double angle_deg : {0.0, 20.0, 45.0, 90.0, 135.0}) {
    SCOPED_TRACE(angle_deg);
    const double angle = angle_deg * std::numbers::pi / 180.0;
    state.q[dofs.index(1, 0)] = std::cos(angle);  // node B; A stays at the origin
    state.q[dofs.index(1, 1)] = std::sin(angle);
    const double before_J = coupling.tally().absorbed_J;
    coupling.before_step(state, step_s);
    coupling.after_step(state, false);
    const double absorbed_W = (coupling.tally().absorbed_J - before_J) / step_s;
    EXPECT_NEAR(absorbed_W, 0.6 * 1361.0 * 0.02 * std::abs(std::sin(angle)), 1e-12);
  }
}

TEST(ThermalCoupling, BoomLeavingEclipseCoolsEndOnAndWarmsBroadside) {
  testing::ScratchFolder folder("thermal_boom");
  Envelope envelope;
  const RunReport report = run_to_folder(load_model(kBoomExample, {}), folder.path(), {}, envelope);
  ASSERT_EQ(report.status, RunStatus::completed) << report.message;
  const testing::CsvTable temperatures = testing::read_csv_table(folder.path() / "temperatures.csv");
  const testing::CsvTable history = testing::read_csv_table(folder.path() / "history.csv");
  ASSERT_EQ(temperatures.columns, (std::vector<std::string>{"t", "T.boom"}));
  ASSERT_EQ(temperatures.rows.size(), history.rows.size());
  const double reference_K = 293.15, alpha = 2.3e-5;
  const double equilibrium_K = std::pow(0.6 * 1361.0 / (std::numbers::pi * 0.8 * kSigma) + std::pow(3.0, 4), 0.25);
  double previous_K = 0.0;
  for (std::size_t row = 0; row < temperatures.rows.size(); ++row) {
    const double t = temperatures.at(row, "t");
    const double temperature_K = temperatures.at(row, "T.boom");
    ASSERT_EQ(t, history.at(row, "t"));
    // A free bar: its Green–Lagrange strain is the thermal one, α ΔT, at the same time.
    EXPECT_NEAR(history.at(row, "strain.boom"), alpha * (temperature_K - reference_K), 1e-10) << t;
    if (row > 0 && t <= 600.0) {
      EXPECT_LT(temperature_K, previous_K) << t;  // end-on: only radiates
    }
    if (t >= 960.0) {
      EXPECT_GT(temperature_K, previous_K) << t;  // broadside: warms
    }
    EXPECT_LT(temperature_K, equilibrium_K);
    previous_K = temperature_K;
  }
  EXPECT_GT(previous_K, equilibrium_K - 5.0);  // 2700 s broadside: about 5 time constants

  const nlohmann::json summary = nlohmann::json::parse(testing::read_text(folder.path() / "summary.json"));
  const nlohmann::json& extremes = summary.at("temperatures");
  EXPECT_EQ(extremes.at("max_member"), "boom");
  EXPECT_EQ(extremes.at("max_time_s"), 3600.0);
  EXPECT_NEAR(extremes.at("max_K").get<double>(), previous_K, 1e-9);
  EXPECT_GT(extremes.at("min_time_s").get<double>(), 500.0);  // the coldest just before the turn
  EXPECT_LT(extremes.at("min_time_s").get<double>(), 700.0);
  EXPECT_EQ(summary.at("files").at("temperatures"), "temperatures.csv");
  // Stored = absorbed − emitted − convected, to the Newton tolerance of the steps.
  const double stored_J = extremes.at("stored_J");
  const double net_J = extremes.at("absorbed_J").get<double>() - extremes.at("emitted_J").get<double>() -
                       extremes.at("convected_J").get<double>();
  EXPECT_NEAR(stored_J, net_J, 1e-9 * extremes.at("absorbed_J").get<double>());
  // The stored energy is m c (T_end − T_0): the tally sums the right steps.
  const double capacity_J_K = 2700.0 * std::numbers::pi * (0.02 * 0.02 - 0.018 * 0.018) / 4.0 * 900.0;
  EXPECT_NEAR(stored_J, capacity_J_K * (previous_K - 200.0), 1e-9 * std::abs(stored_J));
}

// Two steel tubes (d = 0.02 m) 1 m long in orbit, the sun straight above (+z): `lit` at z = 0,
// `cover` 0.1 m above it.
// At rest where the model file places the nodes (3D models of point nodes).
MotionState at_file_positions(const Model& model, const DofMap& dofs) {
  MotionState state;
  state.q = Eigen::VectorXd::Zero(dofs.n_dofs());
  for (int node = 0; node < model.n_nodes(); ++node) {
    for (int k = 0; k < 3; ++k) state.q[dofs.index(node, k)] = model.nodes[node].position_m[k];
  }
  return state;
}

Model shaded_pair(const std::string& shadows) {
  return load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [1, 0, 0], C: [0, 0, 0.1], D: [1, 0, 0.1]}
materials:
  steel: {E: 2.0e11, alpha: 1.2e-5, density: 7850, specific_heat: 490, absorptivity: 0.5, emissivity: 0.8}
sections: {tube: {shape: circular_tube, outer_diameter: 0.02, wall_thickness: 0.001}}
elements:
  lit: {nodes: [A, B], section: tube, material: steel}
  cover: {nodes: [C, D], section: tube, material: steel}
supports: [{node: A}, {node: B}, {node: C}, {node: D}]
environment: {type: orbit, sun_direction: [0, 0, 1], reference_temperature: 293.15, initial_temperature: 150, )" + shadows + R"(}
analysis: {type: static, end: 100, step: 1}
)", "shaded_pair.yaml");
}

// Two aluminium tubes meeting at B in orbit, the sun along z: `lit` lies broadside along x,
// `second` along `second_axis` from B. `conduction` is the environment's conduction value and
// what follows it; with `pin` (the keys after its nodes) `second` starts at a node B2 of its
// own, joined to B by a ball joint.
Model tube_pair(const std::string& second_axis, const std::string& conduction,
                const std::optional<std::string>& pin = std::nullopt) {
  const std::string start = pin ? "B2" : "B";
  return load_model_from_string(std::string(R"(
nodes: {A: [0, 0, 0], B: [1, 0, 0], )") + (pin ? "B2: [1, 0, 0], " : "") + "C: " + second_axis + R"(}
materials:
  alu: {E: 7.0e10, alpha: 2.3e-5, density: 2700, specific_heat: 900, absorptivity: 0.6, emissivity: 0.8, conductivity: 160}
sections: {tube: {shape: circular_tube, outer_diameter: 0.02, wall_thickness: 0.001}}
elements:
  lit: {nodes: [A, B], section: tube, material: alu}
  second: {nodes: [)" + start + R"(, C], section: tube, material: alu}
supports: [{node: A}, {node: B}, {node: C}]
)" + (pin ? "joints: {pin: {type: ball, nodes: [B, B2]" + *pin + "}}\n" : "") +
                                R"(environment: {type: orbit, sun_direction: [0, 0, 1], reference_temperature: 293.15, initial_temperature: 250, conduction: )" +
                                conduction + R"(}
analysis: {type: static, end: 100, step: 1}
)", "tube_pair.yaml");
}

Model pair_at_a_node(const std::string& second_axis, bool conduction) {
  return tube_pair(second_axis, conduction ? "true" : "false");
}

// Steps of 10 s over `duration_s` at the file's configuration: the members' temperatures and
// the heat tally.
std::pair<std::vector<double>, HeatTally> heat_for(Model model, double duration_s) {
  ThermalCoupling coupling(model);
  const DofMap dofs(model);
  MotionState state = at_file_positions(model, dofs);
  for (double t = 0.0; t < duration_s; t += 10.0) {
    state.time_s = t;
    coupling.before_step(state, 10.0);
    state.time_s = t + 10.0;
    coupling.after_step(state, false);
  }
  return {coupling.temperatures_K(), coupling.tally()};
}

TEST(ThermalCoupling, ConductionWarmsTheShadedNeighbourAndClosesTheHeatBalance) {
  // `second` stands end-on to the sun (along z): alone it only radiates; through B it takes
  // heat from `lit`.
  const auto [alone_K, alone_tally] = heat_for(pair_at_a_node("[1, 0, 1]", false), 3000.0);
  const auto [joined_K, joined_tally] = heat_for(pair_at_a_node("[1, 0, 1]", true), 3000.0);
  // Through B, G = k A / L (two halves 2 k A / L in series) = 9.5e-3 W/K carries about 1 W at
  // their 100 K difference, 2.8 kJ over the run: some 19 K of a member's m c = 145 J/K, before
  // radiation takes its share back (the lit one's faster, it is warmer).
  EXPECT_GT(joined_K[1], alone_K[1] + 5.0);
  EXPECT_LT(joined_K[0], alone_K[0] - 2.0);
  EXPECT_GT(joined_K[0], joined_K[1]);  // heat flows down the difference, not past it
  const double net_J = joined_tally.absorbed_J - joined_tally.emitted_J - joined_tally.convected_J;
  EXPECT_NEAR(joined_tally.stored_J, net_J, 1e-9 * joined_tally.absorbed_J);
  EXPECT_NEAR(joined_tally.absorbed_J, alone_tally.absorbed_J, 1e-9 * alone_tally.absorbed_J);  // the same sun
}

TEST(ThermalCoupling, ConductionBetweenMembersAtOneTemperatureChangesNothing) {
  // Both broadside and alike: K T = 0, so conduction leaves their temperatures as they were.
  const auto [alone_K, alone_tally] = heat_for(pair_at_a_node("[2, 0, 0]", false), 3000.0);
  const auto [joined_K, joined_tally] = heat_for(pair_at_a_node("[2, 0, 0]", true), 3000.0);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(joined_K[i], alone_K[i], 1e-9) << i;
  EXPECT_GT(alone_K[0], 250.0 + 10.0);  // and both warmed in the sun
}

// The pair of pair_at_a_node("[1, 0, 1]", true), `second` starting at its own node B2 pinned to
// B: `contact` is the environment's joint_conductance and `own` the joint's conductance key.
Model pair_pinned(const std::string& contact, const std::string& own) {
  return tube_pair("[1, 0, 1]", "true" + contact, own);
}

TEST(ThermalCoupling, AJointConductsThroughItsContactAndClosesTheHeatBalance) {
  const auto [apart_K, apart_tally] = heat_for(pair_pinned("", ""), 3000.0);
  const auto [alone_K, alone_tally] = heat_for(pair_at_a_node("[1, 0, 1]", false), 3000.0);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(apart_K[i], alone_K[i], 1e-9) << i;  // no contact: no conduction
  // A contact far stiffer than the halves (2 k A / L = 0.019 W/K) conducts as the shared node.
  const auto [stiff_K, stiff_tally] = heat_for(pair_pinned(", joint_conductance: 1.0e6", ""), 3000.0);
  const auto [shared_K, shared_tally] = heat_for(pair_at_a_node("[1, 0, 1]", true), 3000.0);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(stiff_K[i], shared_K[i], 1e-6) << i;
  // A worn contact of 5 mW/K: some heat, less than through the shared node; the joint's own
  // value overrides the environment's.
  const auto [worn_K, worn_tally] = heat_for(pair_pinned(", joint_conductance: 0.005", ""), 3000.0);
  const auto [own_K, own_tally] = heat_for(pair_pinned(", joint_conductance: 7", ", conductance: 0.005"), 3000.0);
  EXPECT_GT(worn_K[1], alone_K[1] + 0.5);
  EXPECT_LT(worn_K[1], shared_K[1] - 0.5);
  EXPECT_GT(worn_K[0], worn_K[1]);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(own_K[i], worn_K[i]) << i;
  const double net_J = worn_tally.absorbed_J - worn_tally.emitted_J - worn_tally.convected_J;
  EXPECT_NEAR(worn_tally.stored_J, net_J, 1e-9 * worn_tally.absorbed_J);
}

TEST(ThermalCoupling, AMemberLeavingAnothersShadowTakesTheSunAsTheGeometrySays) {
  Model model = shaded_pair("shadows: {every: 1, samples_along: 4, samples_across: 8}");
  ThermalCoupling coupling(model);
  ASSERT_TRUE(coupling.has_shadows());
  EXPECT_EQ(coupling.shadowed_fractions(), (std::vector<double>{1.0, 0.0}));  // at t = 0
  const DofMap dofs(model);
  MotionState state = at_file_positions(model, dofs);
  // The cover slides sideways at 1 mm/s: its shadow leaves the lit tube's strip |y| ≤ r after
  // 2 r / v = 20 s. Shadows are cast from the step's start, the sun taken over the step.
  const double speed_m_s = 1e-3, radius_m = 0.01, full_W = 0.5 * 1361.0 * 0.02 * 1.0;
  double previous_K = coupling.temperatures_K()[0];
  for (int step = 0; step < 30; ++step) {
    const double offset_m = speed_m_s * step;
    const double overlap = std::max(0.0, 2.0 * radius_m - offset_m) / (2.0 * radius_m);
    const double before_J = coupling.tally().absorbed_J;
    state.time_s = step;
    coupling.before_step(state, 1.0);
    state.time_s = step + 1.0;
    for (const int node : {2, 3}) state.q[dofs.index(node, 1)] = speed_m_s * (step + 1);
    coupling.after_step(state, false);  // the tally of the step, then the shadows at its end
    const double lit_W = (coupling.tally().absorbed_J - before_J) - full_W;  // the cover is in full sun
    EXPECT_NEAR(lit_W / full_W, 1.0 - overlap, 1.0 / 8 + 1e-12) << "offset " << offset_m;
    if (offset_m >= 2.0 * radius_m) {
      EXPECT_NEAR(lit_W, full_W, 1e-9);  // out of the shadow
    }
    if (offset_m == 0.0) {
      EXPECT_NEAR(lit_W, 0.0, 1e-9);  // fully shadowed: no direct light
    }
    const double now_K = coupling.temperatures_K()[0];
    // In full shadow it only radiates; once the sun reaches it, it warms.
    if (offset_m == 0.0) {
      EXPECT_LT(now_K, previous_K);
    }
    if (offset_m >= radius_m) {
      EXPECT_GT(now_K, previous_K) << "offset " << offset_m;
    }
    previous_K = now_K;
  }
  EXPECT_EQ(coupling.most_shadowed().temperature_K, 1.0);
  EXPECT_EQ(coupling.member_names()[static_cast<std::size_t>(coupling.most_shadowed().member)], "lit");
}

TEST(ThermalCoupling, ShadowsEveryNStepsKeepTheLastFractionsBetween) {
  Model model = shaded_pair("shadows: {every: 5}");
  ThermalCoupling coupling(model);
  const DofMap dofs(model);
  MotionState state = at_file_positions(model, dofs);
  for (const int node : {2, 3}) state.q[dofs.index(node, 1)] = 1.0;  // the cover moved far away
  for (int step = 1; step <= 5; ++step) {
    coupling.before_step(state, 1.0);
    coupling.after_step(state, false);
    EXPECT_EQ(coupling.shadowed_fractions()[0], step < 5 ? 1.0 : 0.0) << step;
  }
}

// every: auto. The cover slides sideways at 0.1 mm a step: the shadows are cast again only
// after it has moved across the sun by more than δ = r / n_across = 1.25 mm since the last
// update (every 13th step), so the lit tube's shadowed fraction is never more than one sample
// column (1/8) plus its sampling error (1/8) from the geometric overlap; a motion along the sun
// (towards the lit tube) casts no new rays.
TEST(ThermalCoupling, ShadowsOnMotionFollowTheCoverWithinOneSampleColumn) {
  Model model = shaded_pair("shadows: {every: auto, samples_along: 4, samples_across: 8}");
  ASSERT_TRUE(model.environment->shadows->on_motion);
  ThermalCoupling coupling(model);
  const DofMap dofs(model);
  MotionState state = at_file_positions(model, dofs);
  const double step_m = 1e-4, radius_m = 0.01, tolerance_m = radius_m / 8;
  const int n_steps = 250;  // 25 mm: out of the shadow
  for (int step = 1; step <= n_steps; ++step) {
    coupling.before_step(state, 1.0);
    for (const int node : {2, 3}) state.q[dofs.index(node, 1)] = step_m * step;
    coupling.after_step(state, false);
    const double overlap = std::max(0.0, 2.0 * radius_m - step_m * step) / (2.0 * radius_m);
    EXPECT_NEAR(coupling.shadowed_fractions()[0], overlap, 2.0 / 8 + 1e-12) << "step " << step;
  }
  // An update when the motion since the last exceeds δ: at steps 13, 26, … (t = 0's included).
  const long expected = 1 + static_cast<long>(std::floor(n_steps / (std::floor(tolerance_m / step_m) + 1)));
  EXPECT_EQ(coupling.n_shadow_updates(), expected);
  EXPECT_EQ(coupling.shadowed_fractions()[0], 0.0);
  // Moving the cover along the sun's direction (z) changes no shadow: no update.
  const long before = coupling.n_shadow_updates();
  for (int step = 1; step <= 20; ++step) {
    coupling.before_step(state, 1.0);
    for (const int node : {2, 3}) state.q[dofs.index(node, 2)] = 0.1 + 0.01 * step;
    coupling.after_step(state, false);
  }
  EXPECT_EQ(coupling.n_shadow_updates(), before);
}

// A clamped 2D tube broadside to the sun, its sun-to-shade difference on: at every output its
// bending moment is E I α D / d with D from temperatures.csv (the beam's curvature α D / d
// held at zero); and D approaches the closed form D*.
TEST(ThermalCoupling, AClampedTubeInTheSunTakesTheMomentOfItsSectionDifference) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], M: [0.5, 0], B: [1, 0]}
materials:
  alu: {E: 7.0e10, alpha: 2.3e-5, density: 2700, specific_heat: 900, absorptivity: 0.6, emissivity: 0.8, conductivity: 10}
sections: {tube: {shape: circular_tube, outer_diameter: 0.02, wall_thickness: 0.001}}
elements:
  left: {type: beam, nodes: [A, M], section: tube, material: alu}
  right: {type: beam, nodes: [M, B], section: tube, material: alu}
supports: [{node: A, fix: [x, y, rotation]}, {node: B, fix: [x, y, rotation]}]
environment: {type: orbit, sun_direction: [0, 1, 0], reference_temperature: 293.15, section_gradients: true}
analysis: {type: static, end: 3000, step: 10, output_interval: 100}
)", "clamped_tube.yaml");
  testing::ScratchFolder folder("thermal_section_gradient");
  const RunReport report = run_to_folder(model, folder.path());
  ASSERT_EQ(report.status, RunStatus::completed) << report.message;
  const testing::CsvTable temperatures = testing::read_csv_table(folder.path() / "temperatures.csv");
  const testing::CsvTable history = testing::read_csv_table(folder.path() / "history.csv");
  ASSERT_EQ(temperatures.columns,
            (std::vector<std::string>{"t", "T.left", "T.right", "dT_section.left", "dT_section.right"}));
  const double d = 0.02, e = 7.0e10, alpha = 2.3e-5;
  const double inertia = std::numbers::pi / 64.0 * (std::pow(d, 4) - std::pow(d - 0.002, 4));
  ASSERT_EQ(temperatures.rows.size(), history.rows.size());
  for (std::size_t row = 1; row < temperatures.rows.size(); ++row) {
    const double t = temperatures.at(row, "t");
    for (const std::string beam : {"left", "right"}) {
      const double difference_K = temperatures.at(row, "dT_section." + beam);
      EXPECT_GT(difference_K, 0.0) << t;
      EXPECT_NEAR(std::abs(history.at(row, "moment." + beam)), e * inertia * alpha * difference_K / d,
                  1e-6 * e * inertia * alpha * difference_K / d) << beam << " at " << t;
    }
  }
  // After ≫ τ: the steady D* at the final mean temperature.
  const std::size_t last = temperatures.rows.size() - 1;
  RoundSectionBody tube{0.01, 0.001, 10.0, 2700.0 * 900.0, 0.6, 0.8};
  const SectionDifferenceLaw law = section_difference_law(tube, 1361.0, temperatures.at(last, "T.left"), 0.0);
  EXPECT_NEAR(temperatures.at(last, "dT_section.left"), law.steady_K, 1e-3 * law.steady_K);
  const nlohmann::json summary = nlohmann::json::parse(testing::read_text(folder.path() / "summary.json"));
  EXPECT_NEAR(summary.at("temperatures").at("section_difference_max_K").get<double>(),
              temperatures.at(last, "dT_section.left"), 0.05);
}

// The steady field of one environment state (ThermalCoupling::settle): the cover in full sun
// sits at its radiative equilibrium T⁴ = α_s S d L / (ε σ π d L) + T_sink⁴, the member it
// shades wholly at the sink's temperature; the copy carries them as constant ΔT = T − T_ref
// and has no environment.
TEST(ThermalCoupling, TheSteadyFieldIsEachMembersRadiativeEquilibrium) {
  const Model model = shaded_pair("shadows: true");
  const Model settled = with_steady_temperatures(model, 0.0);
  EXPECT_FALSE(settled.environment.has_value());
  const double sink_K = 3.0, reference_K = 293.15;
  const double cover_K = std::pow(0.5 * 1361.0 / (0.8 * kStefanBoltzmann_W_m2K4 * std::numbers::pi) + std::pow(sink_K, 4), 0.25);
  const std::map<std::string, double> expected_C{{"cover", cover_K - reference_K}, {"lit", sink_K - reference_K}};
  for (const ElementRef& ref : all_elements(settled)) {
    const std::string& name = ref.kind->element_name(settled, ref.index);
    SCOPED_TRACE(name);
    const std::optional<ElementThermalLoad> load = ref.kind->thermal_load(settled, ref.index);
    ASSERT_TRUE(load.has_value());
    for (const double t : {0.0, 0.5, 100.0}) EXPECT_NEAR(load->axis_C.value(t), expected_C.at(name), 1e-9 * reference_K);
  }
  // The coupling's own view: the same temperatures, stored as the last state.
  Model coupled = model;
  ThermalCoupling coupling(coupled);
  coupling.settle(0.0);
  EXPECT_NEAR(coupling.temperatures_K()[1], cover_K, 1e-9 * cover_K);
  EXPECT_EQ(coupling.shadowed_fractions()[0], 1.0);

  // In the dark with a sink at 0 K nothing settles (T = 0 is a double root): a clear error.
  Model dark = model;
  dark.environment->orbit.sink_temperature_K = 0.0;
  dark.environment->orbit.eclipses = {{0.0, 100.0}};
  try {
    (void)with_steady_temperatures(dark, 0.0);
    ADD_FAILURE() << "a dark member at a 0 K sink settled";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("sink_temperature above 0 K"), std::string::npos) << error.what();
  }
}

TEST(ThermalCoupling, RunsWithoutAnEnvironmentAreUntouched) {
  // The same boom with a given ΔT: no temperatures.csv, no "temperatures" in the summary.
  Model model = load_model(kBoomExample, {});
  model.environment.reset();
  model.analysis.end_time_s = 60.0;
  testing::ScratchFolder folder("thermal_none");
  ASSERT_EQ(run_to_folder(model, folder.path()).status, RunStatus::completed);
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "temperatures.csv"));
  const nlohmann::json summary = nlohmann::json::parse(testing::read_text(folder.path() / "summary.json"));
  EXPECT_FALSE(summary.contains("temperatures"));
}

}  // namespace
}  // namespace deploydyn::thermal
