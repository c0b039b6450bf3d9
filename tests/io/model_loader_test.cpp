#include "deploydyn/io/model_loader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/io/input_error.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// The examples' coordinates are written to 15 digits; lengths agree with Table 1 to this.
constexpr double kGeometryTolerance = 1e-12;

std::string example(const std::string& name) {
  return fmt::format("{}/examples/paper/{}.yaml", DEPLOYDYN_SOURCE_DIR, name);
}

int node_index(const Model& model, const std::string& name) {
  const auto found = std::find_if(model.nodes.begin(), model.nodes.end(),
                                  [&](const Node& node) { return node.name == name; });
  return found == model.nodes.end() ? -1 : static_cast<int>(found - model.nodes.begin());
}

// A two-bar model that tests extend with one section each.
const std::string kTwoBars = R"(
nodes: {A: [0, 0], B: [3, 4], C: [6, 0]}
materials: {alu: {E: 7.0e10, alpha: 2.3e-5, density: 2700}}
elements:
  left: {nodes: [A, B], area: 2.0e-4, material: alu}
  right: {nodes: [B, C], area: 2.0e-4, material: alu, mass: 3, length: 5.5}
)";

TEST(ModelLoader, ParallelExampleLoads) {
  const Model model = load_model(example("parallel"));
  EXPECT_EQ(model.name, "parallel four-bar linkage");
  EXPECT_EQ(model.dimension, 2);
  ASSERT_EQ(model.n_nodes(), 4);
  EXPECT_EQ(model.nodes[0].name, "A");
  EXPECT_EQ(model.nodes[1].name, "B");
  EXPECT_EQ(model.nodes[2].name, "C");
  EXPECT_EQ(model.nodes[3].name, "D");
  ASSERT_EQ(model.n_bars(), 3);
  EXPECT_EQ(model.bars[1].name, "2");
  EXPECT_NEAR(model.bars[1].reference_length_m, 0.357, kGeometryTolerance);
  EXPECT_FALSE(model.bars[1].length_given);
  EXPECT_EQ(model.bars[1].mass_kg, 0.357);
  EXPECT_EQ(model.materials[model.bars[1].material].youngs_modulus_Pa, 1.5e11);
  ASSERT_EQ(model.supports.size(), 2u);
  EXPECT_EQ(model.supports[1].node, node_index(model, "D"));
  EXPECT_EQ(model.supports[1].axes, (std::array<bool, 3>{true, true, false}));

  ASSERT_EQ(model.drivers.size(), 1u);
  const Driver& motor = model.drivers[0];
  EXPECT_EQ(motor.name, "motor");
  EXPECT_EQ(motor.kind, Driver::Kind::bar_angle);
  EXPECT_EQ(motor.element, 2);
  EXPECT_EQ(motor.pivot, node_index(model, "D"));
  EXPECT_EQ(motor.reading, DriverReading::rate);
  EXPECT_NEAR(motor.profile.integral(5.0), 1.46, 1e-12);

  EXPECT_EQ(model.analysis.type, AnalysisType::dynamic);
  EXPECT_EQ(model.analysis.step_s, 1e-3);
  EXPECT_EQ(model.analysis.output_interval_s, 5e-3);
  EXPECT_EQ(model.output.history_file, "history.csv");
}

TEST(ModelLoader, GeneralExampleLoads) {
  const Model model = load_model(example("general"));
  EXPECT_EQ(model.dimension, 2);
  ASSERT_EQ(model.n_nodes(), 4);
  EXPECT_EQ(model.nodes[3].name, "D");
  ASSERT_EQ(model.n_bars(), 3);
  EXPECT_NEAR(model.bars[1].reference_length_m, 0.9, 1e-9);  // C is given to 15 digits
  EXPECT_EQ(model.materials[model.bars[1].material].youngs_modulus_Pa, 5.0e6);
  ASSERT_EQ(model.drivers.size(), 1u);
  EXPECT_EQ(model.drivers[0].element, 0);
  EXPECT_EQ(model.drivers[0].pivot, node_index(model, "A"));
  EXPECT_NEAR(model.drivers[0].profile.integral(5.0), 1.46, 1e-12);
}

TEST(ModelLoader, DefaultsFillWhatTheFileLeavesOut) {
  const Model model = load_model_from_string(kTwoBars, "two_bars");
  const BarElement& left = model.bars[0];
  EXPECT_DOUBLE_EQ(left.reference_length_m, 5.0);
  EXPECT_DOUBLE_EQ(left.mass_kg, 2700 * 2.0e-4 * 5.0);  // density · area · L0
  EXPECT_FALSE(left.mass_given);
  const BarElement& right = model.bars[1];
  EXPECT_EQ(right.reference_length_m, 5.5);
  EXPECT_TRUE(right.length_given);
  EXPECT_EQ(right.mass_kg, 3.0);
  EXPECT_EQ(left.temperature_change_C.value(1.0), 0.0);
  EXPECT_FALSE(left.temperature_given);

  const AnalysisOptions defaults;
  EXPECT_EQ(model.analysis.type, AnalysisType::dynamic);
  EXPECT_EQ(model.analysis.end_time_s, 1.0);
  EXPECT_EQ(model.analysis.step_s, defaults.step_s);
  EXPECT_EQ(model.analysis.output_interval_s, defaults.step_s);
  // The default integrator (model.hpp, docs/model-format.md): generalized-α, ρ∞ = 0.9.
  EXPECT_EQ(model.analysis.integrator.kind, IntegratorOptions::Kind::generalized_alpha);
  EXPECT_EQ(model.analysis.integrator.rho_infinity, 0.9);
  EXPECT_EQ(model.analysis.newton.max_iterations, defaults.newton.max_iterations);
  EXPECT_EQ(model.output.summary_file, "summary.json");
}

TEST(ModelLoader, ReadsFunctionsDriversLoadsAndAnalysis) {
  const Model model = load_model_from_string(kTwoBars + R"(
functions:
  warm: {type: smooth_step, t0: 0, v0: 0, t1: 2, v1: 40}
  ramp: {type: table, points: [[0, 0], [1, 2]]}
thermal: {dT: warm}
supports:
  - {node: A}
  - {node: C, fix: [y]}
drivers:
  lift: {type: coordinate, node: B, direction: y, profile: ramp, reading: displacement}
loads:
  - {node: B, force: [0, -10], factor: {type: paper_eq23, amplitude: 2}}
gravity: [0, -9.81]
analysis:
  type: static
  end: 2
  step: 0.01
  output_interval: 0.05
  load_steps: 4
  mass: lumped
  integrator: {type: newmark, beta: 0.3025, gamma: 0.6}
  newton: {max_iterations: 8, tol_force: 1e-6}
output: {history: h.csv, summary: s.json}
)",
                                             "full");
  EXPECT_EQ(model.temperature_change_C.value(2.0), 40.0);
  EXPECT_EQ(model.bars[1].temperature_change_C, model.temperature_change_C);
  EXPECT_EQ(model.supports[1].axes, (std::array<bool, 3>{false, true, false}));
  const Driver& lift = model.drivers.at(0);
  EXPECT_EQ(lift.kind, Driver::Kind::coordinate);
  EXPECT_EQ(lift.node, 1);
  EXPECT_EQ(lift.direction, 1);
  EXPECT_EQ(lift.reading, DriverReading::value);
  EXPECT_EQ(lift.profile.value(0.5), 1.0);
  EXPECT_EQ(model.loads.at(0).force_N, Eigen::Vector3d(0, -10, 0));
  EXPECT_EQ(model.loads.at(0).factor.value(2.0), 2.0);
  EXPECT_EQ(model.gravity_m_s2, Eigen::Vector3d(0, -9.81, 0));
  EXPECT_EQ(model.analysis.type, AnalysisType::quasi_static);
  EXPECT_EQ(model.analysis.output_interval_s, 0.05);
  EXPECT_EQ(model.analysis.load_steps, 4);
  EXPECT_EQ(model.analysis.mass, MassMatrixKind::lumped);
  EXPECT_EQ(model.analysis.integrator.kind, IntegratorOptions::Kind::newmark);
  EXPECT_EQ(model.analysis.integrator.beta, 0.3025);
  EXPECT_EQ(model.analysis.integrator.gamma, 0.6);
  EXPECT_EQ(model.analysis.newton.max_iterations, 8);
  EXPECT_EQ(model.analysis.newton.force_tolerance, 1e-6);
  EXPECT_EQ(model.output.history_file, "h.csv");
}

TEST(ModelLoader, ReadsThreeDimensionalModelsAndJson) {
  const Model model = load_model_from_string(R"({
    "nodes": {"1": [0, 0, 0], "2": {"at": [0, 0, 2], "mass": 0.5}},
    "materials": {"steel": {"E": 2e11}},
    "elements": {"post": {"nodes": [1, 2], "area": 1e-4, "material": "steel", "mass": 1,
                          "dT": 20}},
    "drivers": {"tilt": {"type": "bar_angle", "element": "post", "pivot": 1,
                         "axis": [0, 3, 0], "profile": 0.1}}
  })",
                                             "json");
  EXPECT_EQ(model.dimension, 3);
  EXPECT_EQ(model.nodes[1].point_mass_kg, 0.5);
  EXPECT_TRUE(model.bars[0].temperature_given);
  EXPECT_EQ(model.bars[0].temperature_change_C.value(0.0), 20.0);
  EXPECT_EQ(model.drivers[0].axis, Eigen::Vector3d::UnitY());
}

TEST(ModelLoader, ErrorNamesSourceLineAndField) {
  try {
    load_model_from_string(kTwoBars + "analysis: {end: -2}\n", "inline.yaml");
    FAIL() << "a negative end time loaded";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "inline.yaml");
    EXPECT_EQ(error.line(), 7);
    EXPECT_EQ(error.field(), "analysis.end");
    EXPECT_EQ(error.problem(), "must be positive (s), got -2");
  }
}

TEST(Override, ParsesPathAndValueAtTheFirstEqualsSign) {
  const Override parsed = parse_override("output.history=a=b.csv");
  EXPECT_EQ(parsed.path, "output.history");
  EXPECT_EQ(parsed.value, "a=b.csv");
  EXPECT_THROW(parse_override("thermal.dT"), InputError);
  EXPECT_THROW(parse_override("=130"), InputError);
}

TEST(Override, ThermalDTChangesEveryBarOfBothExamples) {
  for (const std::string name : {"parallel", "general"}) {
    const Model model = load_model(example(name), {parse_override("thermal.dT=130")});
    for (const BarElement& bar : model.bars) {
      EXPECT_EQ(bar.temperature_change_C.value(0.0), 130.0) << name << " bar " << bar.name;
      EXPECT_FALSE(bar.temperature_given);
    }
  }
}

TEST(Override, ReplacesAndAddsScalars) {
  const Model model = load_model(example("parallel"), {{"analysis.step", "5e-4"},
                                                       {"analysis.load_steps", "3"},
                                                       {"analysis.newton.max_iterations", "4"},
                                                       {"supports.1.node", "C"},
                                                       {"drivers.motor.reading", "angle"}});
  EXPECT_EQ(model.analysis.step_s, 5e-4);
  EXPECT_EQ(model.analysis.output_interval_s, 5e-3);
  EXPECT_EQ(model.analysis.load_steps, 3);
  EXPECT_EQ(model.analysis.newton.max_iterations, 4);  // the file has no newton section
  EXPECT_EQ(model.supports[1].node, 2);
  EXPECT_EQ(model.drivers[0].reading, DriverReading::value);
}

// A VALUE that starts with '[' or '{' is a YAML flow list or mapping: it replaces a list, a
// mapping or a single value, or adds a key, and is checked like the file's own.
TEST(Override, FlowValuesReplaceListsMappingsAndScalars) {
  const Model model = load_model(example("general"), {{"supports.1.fix", "[y]"},
                                                      {"analysis.integrator", "{type: newmark}"},
                                                      {"thermal.dT", "{type: smooth_step, t0: 0, v0: 0, t1: 2, v1: 130}"},
                                                      {"analysis.adaptive", " {tolerance: 1e-7}"},
                                                      {"gravity", "[0, -9.81]"}});
  EXPECT_EQ(model.supports[1].axes, (std::array<bool, 3>{false, true, false}));
  EXPECT_EQ(model.analysis.integrator.kind, IntegratorOptions::Kind::newmark);  // the file's rho_inf is gone
  EXPECT_EQ(model.analysis.integrator.beta, 0.25);
  EXPECT_EQ(model.temperature_change_C.value(1.0), 65.0);
  EXPECT_TRUE(model.analysis.adaptive.enabled);
  EXPECT_EQ(model.analysis.adaptive.tolerance_m, 1e-7);
  EXPECT_EQ(model.gravity_m_s2, Eigen::Vector3d(0, -9.81, 0));
  // Text that does not start a flow collection stays one scalar, as before.
  EXPECT_EQ(load_model(example("general"), {{"drivers.motor.profile", "0.2"}}).drivers[0].profile.value(3.0), 0.2);
}

// An error inside a flow value names the --set that gave it, with the item's own path.
TEST(Override, ErrorInAFlowValueNamesTheOverride) {
  const struct {
    Override override;
    const char* field;
    const char* problem;
  } kCases[] = {
      {{"supports.1.fix", "[x, w]"}, "supports.1.fix.1", "must be one of x, y, z, got 'w'"},
      {{"thermal.dT", "{type: smooth_step, t0: 0, v0: 0, t1: 2}"}, "thermal.dT.v1", "required"},
      {{"analysis.integrator", "{type: newmark, rho_inf: 0.9}"}, "analysis.integrator.rho_inf",
       "applies to hht and generalized_alpha"},
  };
  for (const auto& c : kCases) {
    SCOPED_TRACE(c.override.value);
    try {
      load_model(example("general"), {c.override});
      ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(error.source(), fmt::format("--set {}={}", c.override.path, c.override.value));
      EXPECT_EQ(error.line(), 0);
      EXPECT_EQ(error.field(), c.field);
      EXPECT_NE(error.problem().find(c.problem), std::string::npos) << error.what();
    }
  }
}

// Each bad override must name itself as the source and its path as the field.
TEST(Override, BadOverrideNamesItself) {
  const struct {
    const char* text;
    const char* problem;
  } kBadOverrides[] = {
      {"analysiz.step=1", "no key 'analysiz' in the top level; did you mean 'analysis'?"},
      {"elements.9.area=1", "no key '9' in 'elements'; keys there: 1, 2, 3"},
      {"analysis.newton.max_iter=1", "unknown key 'max_iter'; did you mean 'max_iterations'?"},
      {"analysis.stpe=1", "unknown key 'stpe'; did you mean 'step'?"},
      {"analysis.integrator=3", "'analysis.integrator' is a mapping; a single value cannot replace it, a YAML "
                                "flow mapping can (e.g. analysis.integrator={key: value, ...})"},
      {"supports.1=x", "'supports.1' is a mapping; a single value cannot replace it"},
      {"drivers.motor.profile.x=1", "'drivers.motor.profile' is a single value; it has no 'x'"},
      {"supports.1.fix=[x, y", "VALUE starts a YAML flow list [...] but does not parse"},
      {"thermal={dT: 1, dT: 2}", "'dT' is given twice"},
      {"supports.5.node=A", "is a list of 2 items; expected an index from 0 to 1, got '5'"},
      {"thermal.dT.x=1", "'thermal.dT' is a single value; it has no 'x'"},
      {"thermal.dT=abc", "unknown function 'abc'"},
      {"analysis.step=-1", "must be positive (s), got -1"},
      {"analysis..step=1", "empty key in the path"},
  };
  for (const auto& bad : kBadOverrides) {
    const Override override = parse_override(bad.text);
    try {
      load_model(example("parallel"), {override});
      ADD_FAILURE() << bad.text << " was accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(error.source(), fmt::format("--set {}", bad.text));
      EXPECT_EQ(error.line(), 0);
      EXPECT_EQ(error.field(), override.path);
      EXPECT_NE(error.problem().find(bad.problem), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace deploydyn

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// The petal example: its hinge_angle drivers read with their nodes and unit axes.
TEST(ModelLoader, PetalExampleLoadsHingeAngleDrivers) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/petal/petal.yaml");
  ASSERT_EQ(model.drivers.size(), 2u);
  const Driver& open = model.drivers[0];
  EXPECT_EQ(open.kind, Driver::Kind::hinge_angle);
  const auto index = [&](const char* name) {
    for (int i = 0; i < model.n_nodes(); ++i) {
      if (model.nodes[i].name == name) return i;
    }
    return -1;
  };
  EXPECT_EQ(open.hinge_nodes, (std::array<int, 3>{index("B4"), index("B1"), index("P1")}));
  EXPECT_EQ(open.axis, Eigen::Vector3d::UnitX());
  EXPECT_EQ(model.drivers[1].axis, -Eigen::Vector3d::UnitX());
  EXPECT_EQ(open.reading, DriverReading::value);
  EXPECT_TRUE(drives_rotation(open.kind));
}

// A 2D pin joint between bar nodes, and a hinge_angle whose axis (z) is implied; the joints'
// equations join the constraint count.
TEST(ModelLoader, PinJointIn2DKeepsPositionsOnly) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], H: [1, 0], B: [1, 1], C: [1, 1], D: [2, 1]}
materials: {steel: {E: 2.0e11}}
elements:
  crank: {nodes: [H, B], area: 1.0e-4, material: steel, mass: 1}
  link: {nodes: [C, D], area: 1.0e-4, material: steel, mass: 1}
supports: [{node: A}, {node: H}, {node: D, fix: [y]}]
joints: {knee: {type: pin, nodes: [B, C]}}
drivers: {arm: {type: hinge_angle, nodes: [A, H, B], profile: 0.1}}
)",
                                             "knee");
  ASSERT_EQ(model.joints.size(), 1u);
  EXPECT_EQ(model.joints[0].nodes, (std::array<int, 2>{2, 3}));
  EXPECT_EQ(model.drivers[0].hinge_nodes, (std::array<int, 3>{0, 1, 2}));
  const Assembler assembler(model);
  EXPECT_EQ(assembler.n_equations(), 2 + 2 + 1 + 2 + 1);  // supports, joint, driver
  EXPECT_EQ(assembler.rigid_mobility(), 0);
}

}  // namespace
}  // namespace deploydyn
