#pragma once
// The keys a model file (and a study file) may hold, section by section. The loaders reject
// every other key with exactly these lists (io/model_loader.cpp, study/study_loader.cpp), and
// tests/io/model_keys_test.cpp checks them against docs/model-format.md: its "Key reference"
// table lists each section's keys, and the section of the document it names explains each key.
// The keys of an element type are its field table (ElementKind::fields()), tested the same way
// in tests/elements/element_kinds_test.cpp.

#include <array>
#include <span>
#include <string_view>

namespace deploydyn::model_keys {

using Keys = std::span<const std::string_view>;

inline constexpr std::array<std::string_view, 20> kTopLevel{
    "name",    "description", "units",   "nodes",   "materials", "sections", "elements", "members", "thermal",
    "environment", "supports", "joints", "drivers", "loads", "gravity", "functions", "analysis", "output",
    "checks", "initial_velocities"};
inline constexpr std::array<std::string_view, 2> kNode{"at", "mass"};
inline constexpr std::array<std::string_view, 9> kMaterial{"E",       "alpha",         "density",      "yield_strength",
                                                          "damping", "specific_heat", "absorptivity", "emissivity",
                                                          "conductivity"};
inline constexpr std::array<std::string_view, 4> kMaterialDamping{"ratio", "loss_factor", "frequency", "time"};
inline constexpr std::array<std::string_view, 3> kCircularTubeSection{"shape", "outer_diameter", "wall_thickness"};
inline constexpr std::array<std::string_view, 4> kRectangularTubeSection{"shape", "width", "height",
                                                                         "wall_thickness"};
inline constexpr std::array<std::string_view, 2> kCircleSection{"shape", "diameter"};
inline constexpr std::array<std::string_view, 3> kRectangleSection{"shape", "width", "height"};
inline constexpr std::array<std::string_view, 3> kMember{"elements", "buckling_length_factor", "slack"};
inline constexpr std::array<std::string_view, 2> kThermal{"dT", "reference_temperature_C"};
// A material's E or alpha given at temperatures (model/property_table.hpp)
inline constexpr std::array<std::string_view, 2> kPropertyTable{"temperature_C", "value"};
inline constexpr std::array<std::string_view, 12> kOrbitEnvironment{
    "type", "reference_temperature", "initial_temperature", "sun_direction", "solar_constant", "sink_temperature",
    "eclipses", "penumbra", "shadows", "section_gradients", "conduction", "joint_conductance"};
inline constexpr std::array<std::string_view, 18> kGroundEnvironment{
    "type",       "reference_temperature", "initial_temperature", "latitude",      "longitude",
    "start",      "utc_offset",            "up",                  "north",         "direct_normal",
    "diffuse",    "sky_temperature",       "air_temperature",     "convection",    "shadows",
    "section_gradients", "conduction", "joint_conductance"};
inline constexpr std::array<std::string_view, 3> kShadows{"every", "samples_along", "samples_across"};
inline constexpr std::array<std::string_view, 4> kSupport{"node", "fix", "axis", "offset"};
inline constexpr std::array<std::string_view, 6> kJoint{"type", "nodes", "axis", "arms", "offsets", "conductance"};
inline constexpr std::array<std::string_view, 7> kBarAngleDriver{"type", "element", "pivot", "axis",
                                                                  "profile", "reading", "torque_limit"};
inline constexpr std::array<std::string_view, 6> kHingeAngleDriver{"type", "nodes", "axis", "profile",
                                                                   "reading", "torque_limit"};
inline constexpr std::array<std::string_view, 6> kRevoluteDriver{"type", "joint", "support", "profile",
                                                                 "reading", "torque_limit"};
inline constexpr std::array<std::string_view, 6> kCoordinateDriver{"type", "node", "direction",
                                                                   "profile", "reading", "force_limit"};
inline constexpr std::array<std::string_view, 5> kLengthDriver{"type", "nodes", "profile", "reading",
                                                               "force_limit"};
inline constexpr std::array<std::string_view, 4> kLoad{"node", "force", "moment", "factor"};
inline constexpr std::array<std::string_view, 2> kInitialVelocities{"spin", "nodes"};
inline constexpr std::array<std::string_view, 3> kSpin{"rate", "centre", "axis"};
inline constexpr std::array<std::string_view, 2> kNodeVelocity{"node", "velocity"};
inline constexpr std::array<std::string_view, 13> kAnalysis{
    "type", "end", "end_when", "step", "output_interval", "load_steps", "mass", "integrator", "newton",
    "adaptive", "linear_solver", "rayleigh", "settle"};
inline constexpr std::array<std::string_view, 5> kRayleigh{"alpha", "beta", "ratios", "frequencies", "stiffness"};
inline constexpr std::array<std::string_view, 4> kSettle{"kinetic_energy", "rate", "hold", "node"};
inline constexpr std::array<std::string_view, 4> kIntegrator{"type", "beta", "gamma", "rho_inf"};
inline constexpr std::array<std::string_view, 3> kAdaptive{"tolerance", "min_step", "max_step"};
inline constexpr std::array<std::string_view, 5> kNewton{"max_iterations", "tol_force",
                                                         "tol_constraint", "tol_displacement", "jacobian"};
inline constexpr std::array<std::string_view, 10> kContinuation{
    "type", "parameter", "start", "end", "eigenvalues", "max_steps", "switch_branch", "stop_at", "newton",
    "linear_solver"};
inline constexpr std::array<std::string_view, 8> kModal{"type", "modes", "at", "shift",
                                                        "load_steps", "mass", "newton", "linear_solver"};
inline constexpr std::array<std::string_view, 5> kOutput{"history", "summary", "vtk", "hdf5", "select"};
inline constexpr std::array<std::string_view, 3> kOutputSelect{"nodes", "elements", "quantities"};
inline constexpr std::array<std::string_view, 2> kChecks{"clearance", "clearance_m"};
inline constexpr std::array<std::string_view, 2> kConstantFunction{"type", "value"};
// smooth_step, cosine_ramp and cycloidal: ramps that differ in their shape only
inline constexpr std::array<std::string_view, 5> kRamp{"type", "t0", "v0", "t1", "v1"};
// smooth_trapezoid (every key required) and paper_eq23 (every key optional)
inline constexpr std::array<std::string_view, 4> kSmoothTrapezoid{"type", "amplitude", "rise", "fall"};
inline constexpr std::array<std::string_view, 2> kTableFunction{"type", "points"};
inline constexpr std::array<std::string_view, 3> kPolynomialFunction{"type", "coefficients", "interval"};
inline constexpr std::array<std::string_view, 5> kHarmonicFunction{"type", "amplitude", "frequency", "phase",
                                                                   "offset"};
inline constexpr std::array<std::string_view, 2> kPiecewiseFunction{"type", "pieces"};
inline constexpr std::array<std::string_view, 3> kPiece{"from", "to", "function"};
inline constexpr std::array<std::string_view, 2> kSumFunction{"type", "terms"};
inline constexpr std::array<std::string_view, 7> kStudy{"model", "description", "out", "jobs",
                                                        "reference", "cases", "sampling"};
inline constexpr std::array<std::string_view, 7> kSampling{"method", "cases", "seed", "length_error",
                                                           "temperature", "material", "limits"};
inline constexpr std::array<std::string_view, 3> kLengthError{"elements", "normal", "uniform"};
inline constexpr std::array<std::string_view, 3> kSampledTemperature{"dT", "gradient", "scatter"};
inline constexpr std::array<std::string_view, 2> kTemperatureGradient{"direction", "dT"};
inline constexpr std::array<std::string_view, 2> kMaterialScatter{"E", "alpha"};
inline constexpr std::array<std::string_view, 3> kSamplingLimits{"force", "torque", "shape_error"};

// One mapping of the file and where docs/model-format.md explains its keys.
struct Section {
  std::string_view where;    // e.g. "analysis.integrator", "drivers.NAME (type: bar_angle)"
  std::string_view heading;  // the heading of docs/model-format.md that explains them
  Keys keys;
};

inline constexpr std::array<Section, 52> kSections{{
    {"top level", "### Top level", kTopLevel},
    {"nodes.NAME", "### `nodes`", kNode},
    {"materials.NAME", "### `materials`", kMaterial},
    {"materials.NAME.damping", "### `materials`", kMaterialDamping},
    {"materials.NAME.E, materials.NAME.alpha (a table)", "### `materials`", kPropertyTable},
    {"sections.NAME (shape: circular_tube)", "### `sections`", kCircularTubeSection},
    {"sections.NAME (shape: rectangular_tube)", "### `sections`", kRectangularTubeSection},
    {"sections.NAME (shape: circle)", "### `sections`", kCircleSection},
    {"sections.NAME (shape: rectangle)", "### `sections`", kRectangleSection},
    {"members.NAME", "### `members`", kMember},
    {"thermal", "### `thermal`", kThermal},
    {"environment (type: orbit)", "### `environment`", kOrbitEnvironment},
    {"environment (type: ground)", "### `environment`", kGroundEnvironment},
    {"environment.shadows", "### `environment`", kShadows},
    {"supports.N", "### `supports`", kSupport},
    {"joints.NAME", "### `joints`", kJoint},
    {"drivers.NAME (type: bar_angle)", "### `drivers`", kBarAngleDriver},
    {"drivers.NAME (type: hinge_angle)", "### `drivers`", kHingeAngleDriver},
    {"drivers.NAME (type: revolute)", "### `drivers`", kRevoluteDriver},
    {"drivers.NAME (type: coordinate)", "### `drivers`", kCoordinateDriver},
    {"drivers.NAME (type: length)", "### `drivers`", kLengthDriver},
    {"loads.N", "### `loads`", kLoad},
    {"analysis (type: static or dynamic)", "### `analysis`", kAnalysis},
    {"analysis.integrator", "#### `integrator`", kIntegrator},
    {"analysis.adaptive", "#### `adaptive`", kAdaptive},
    {"analysis.newton", "#### `newton`", kNewton},
    {"analysis.rayleigh", "#### `rayleigh`", kRayleigh},
    {"analysis.settle", "#### `settle`", kSettle},
    {"analysis (type: continuation)", "#### `type: continuation`", kContinuation},
    {"analysis (type: modal)", "#### `type: modal`", kModal},
    {"output", "### `output`", kOutput},
    {"output.select", "#### `select`: what history.csv holds", kOutputSelect},
    {"checks", "### `checks`", kChecks},
    {"initial_velocities", "### `initial_velocities`", kInitialVelocities},
    {"initial_velocities.spin", "### `initial_velocities`", kSpin},
    {"initial_velocities.nodes.N", "### `initial_velocities`", kNodeVelocity},
    {"function (type: constant)", "## Functions of time", kConstantFunction},
    {"function (type: smooth_step, cosine_ramp or cycloidal)", "## Functions of time", kRamp},
    {"function (type: smooth_trapezoid or paper_eq23)", "## Functions of time", kSmoothTrapezoid},
    {"function (type: table)", "## Functions of time", kTableFunction},
    {"function (type: polynomial)", "## Functions of time", kPolynomialFunction},
    {"function (type: harmonic)", "## Functions of time", kHarmonicFunction},
    {"function (type: piecewise)", "## Functions of time", kPiecewiseFunction},
    {"function (type: piecewise), pieces.N", "## Functions of time", kPiece},
    {"function (type: sum)", "## Functions of time", kSumFunction},
    {"study file (top level)", "## Load-case studies: `deploydyn study`", kStudy},
    {"sampling", "### Sampled studies", kSampling},
    {"sampling.length_error.N", "### Sampled studies", kLengthError},
    {"sampling.temperature", "### Sampled studies", kSampledTemperature},
    {"sampling.temperature.gradient", "### Sampled studies", kTemperatureGradient},
    {"sampling.material", "### Sampled studies", kMaterialScatter},
    {"sampling.limits", "### Sampled studies", kSamplingLimits},
}};

}  // namespace deploydyn::model_keys
