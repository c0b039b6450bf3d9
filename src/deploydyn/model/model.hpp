#pragma once
// The model: what a model file describes, as plain data with every reference resolved to an
// index. Units are SI throughout (m, kg, s, N, Pa; °C for temperature differences).
// Building mechanics from it is the assembler's job; reading and writing it is io/'s.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/elements/bar/bar_element.hpp"
#include "deploydyn/elements/beam/beam_element.hpp"
#include "deploydyn/elements/cable/cable_element.hpp"
#include "deploydyn/elements/hinge/hinge_element.hpp"
#include "deploydyn/model/environment.hpp"
#include "deploydyn/model/initial_velocities.hpp"
#include "deploydyn/model/joint.hpp"
#include "deploydyn/model/member.hpp"
#include "deploydyn/model/property_table.hpp"
#include "deploydyn/model/section.hpp"
#include "deploydyn/model/time_function.hpp"
#include "deploydyn/util/name_table.hpp"

namespace deploydyn {

struct Node {
  std::string name;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // z = 0 in 2D models
  double point_mass_kg = 0.0;                             // lumped at the node, optional
};

struct Material {
  std::string name;
  double youngs_modulus_Pa = 0.0;
  double expansion_per_C = 0.0;      // α, thermal expansion coefficient (1/°C)
  std::optional<double> density_kg_m3;  // used when an element gives no mass
  // τ of Kelvin–Voigt material damping: the viscous stress τ E ε̇ on the strain rate (s; 0:
  // undamped). A damping ratio ζ at frequency f gives τ = ζ / (π f) (docs/theory.md, "Material
  // damping"); bars, cables and beams (on all their strains) use it.
  double damping_time_s = 0.0;
  // f_y: the stress (Pa) the member checks take as the material's capacity, the yield strength
  // of a metal or a composite's design strength; empty: no stress checks on its members.
  std::optional<double> yield_strength_Pa;
  // What an `environment` needs of its members' material (thermal/member_heat_balance.hpp):
  std::optional<double> specific_heat_J_kgK;  // c
  std::optional<double> absorptivity;         // α_s, solar, in [0, 1]
  std::optional<double> emissivity;           // ε, infrared, in [0, 1]
  std::optional<double> conductivity_W_mK;    // k: the section's sun-to-shade difference
  // E(T) (Pa) and α(T) (1/°C) as data-sheet tables (model/material_law.hpp; docs/theory.md,
  // "Temperature-dependent material properties"); empty: the constants above. With a table,
  // the constant is the table's value at the model's reference temperature (what the checks and
  // the studies read as the material's E or α).
  std::optional<PropertyTable> youngs_modulus_table_Pa;
  std::optional<PropertyTable> expansion_table_per_C;
};

// Ground support: the chosen coordinates of a node keep their initial values.
struct FixedNode {
  int node = 0;
  std::array<bool, 3> axes{true, true, true};  // x, y, z fixed
  bool rotation = false;  // the node's rotation unknowns fixed too (2D: rz; a beam's node)
  // 3D beam nodes (docs/theory.md, "Ball and universal joints, hinges to ground, offsets"):
  // the frame turns only about this axis (unit, global): a revolute hinge to ground.
  std::optional<Eigen::Vector3d> axis{};
  // The held point is x + R·offset (m, in the node's initial frame: the global axes at the start).
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();
};

// How a driver's profile f(t) is read.
enum class DriverReading {
  rate,   // f is the angular velocity (rad/s) or velocity (m/s); the motion is ∫f (default)
  value,  // f is the rotation (rad) or displacement (m) from the initial state
};

// Each enumeration a model file names has one NameTable (util/name_table.hpp) with its
// spellings, read by the loader, the writers and the Python module; to_string gives a name.

// Rheonomic constraint that moves the mechanism and reports the effort it needs. What each
// type constrains, exactly: docs/theory.md, "Constraints".
struct Driver {
  enum class Kind {
    bar_angle,    // turns a bar's whole direction about its pivot node (1 equation in 2D, 2 in
                  // 3D); the bar stays free to stretch
    coordinate,   // prescribes one coordinate of a node
    revolute,     // turns node B of a pin joint relative to node A about the joint's axis
                  // (nodes with rotations: beams), or a node about its hinge to ground; 1 equation
    hinge_angle,  // the angle from H→A to H→B about an axis (bars); 1 equation
    length,       // a linear actuator: the distance between two nodes; 1 equation
  };
  std::string name;
  Kind kind = Kind::bar_angle;
  int element = 0;  // bar_angle: the driven bar, an index into Model::bars
  int pivot = 0;    // bar_angle: the node it turns about (one of the bar's nodes)
  // bar_angle and hinge_angle in 3D: rotation axis (unit); z in 2D.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  int node = 0;     // coordinate: the node
  int direction = 0;  // coordinate: 0 = x, 1 = y, 2 = z
  int joint = 0;    // revolute: index into Model::joints (unused when `support` is given)
  // revolute at a hinge to ground: index into Model::supports; the support's node turns about
  // the support's axis relative to the fixed ground (docs/theory.md, "Revolute driver at a hinge
  // to ground").
  std::optional<int> support;
  std::array<int, 3> hinge_nodes{};  // hinge_angle: A, H, B
  std::array<int, 2> ends{};         // length: A, B, the actuator's two ends
  TimeFunction profile;
  DriverReading reading = DriverReading::rate;
  // The largest |effort| the actuator can give: torque (N·m) when it turns, else force (N);
  // empty: no effort check.
  std::optional<double> effort_limit;
};
// As model files spell driver types.
inline constexpr NameTable kDriverKinds{std::array{
    NamedValue<Driver::Kind>{Driver::Kind::bar_angle, "bar_angle"},
    NamedValue<Driver::Kind>{Driver::Kind::coordinate, "coordinate"},
    NamedValue<Driver::Kind>{Driver::Kind::revolute, "revolute"},
    NamedValue<Driver::Kind>{Driver::Kind::hinge_angle, "hinge_angle"},
    NamedValue<Driver::Kind>{Driver::Kind::length, "length"},
}};
// Whether a driver of this type turns something (its effort is a torque, N·m, and its profile
// an angle or angular velocity) rather than moving a coordinate or a length (a force, N).
constexpr bool drives_rotation(Driver::Kind kind) {
  return kind != Driver::Kind::coordinate && kind != Driver::Kind::length;
}

// External force on a node: force_N · factor(t); also a moment on a beam's node, times factor(t).
struct NodalLoad {
  int node = 0;
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();
  TimeFunction factor = TimeFunction::constant(1.0);
  // N·m. 2D: only z, counter-clockwise, on the node's rotation rz. 3D: fixed in space (global
  // axes), on the node's frame (assembly/frame_moments.hpp).
  Eigen::Vector3d moment_Nm = Eigen::Vector3d::Zero();
};

enum class AnalysisType { quasi_static, dynamic, continuation, modal };
inline constexpr NameTable kAnalysisTypes{std::array{
    NamedValue<AnalysisType>{AnalysisType::quasi_static, "static"},
    NamedValue<AnalysisType>{AnalysisType::dynamic, "dynamic"},
    NamedValue<AnalysisType>{AnalysisType::continuation, "continuation"},
    NamedValue<AnalysisType>{AnalysisType::modal, "modal"},
}};
inline const char* to_string(AnalysisType type) { return kAnalysisTypes.name(type).data(); }

// The parameter μ a continuation follows (solvers/parametrized_equilibrium.hpp): a scale on
// every ΔT, a factor on nodal loads and gravity, or the time t (s) of a quasi-static
// deployment, at which the drivers' positions (and ΔT(t), load factors) are read.
enum class PathParameter { thermal, load, driver };
inline constexpr NameTable kPathParameters{std::array{
    NamedValue<PathParameter>{PathParameter::thermal, "thermal"},
    NamedValue<PathParameter>{PathParameter::load, "load"},
    NamedValue<PathParameter>{PathParameter::driver, "driver"},
}};
inline const char* to_string(PathParameter parameter) { return kPathParameters.name(parameter).data(); }

// analysis.type: continuation (solvers/continuation.hpp): the static equilibrium (at t = 0
// for the thermal and load parameters) traced in μ from `start` to `end`, through limit
// points, with its stability.
struct ContinuationSettings {
  PathParameter parameter = PathParameter::thermal;
  double start = 0.0;
  double end = 1.0;        // ≠ start
  int n_eigenvalues = 3;   // lowest stability eigenvalues per point in path.csv; 0: none
  int max_steps = 2000;
  bool switch_branch = false;  // follow the first bifurcated branch (solvers/continuation.hpp)
  bool stop_at_first_event = false;  // `stop_at: first_event`: end there, completed
};
// analysis.type: modal (solvers/modal_analysis.hpp): natural frequencies and modes about the
// static equilibrium at each time (the thermal state at t = 0, then the drivers moved
// quasi-statically to the time).
struct ModalSettings {
  int n_modes = 10;                   // the lowest, per time
  std::vector<double> times_s{0.0};   // ascending, ≥ 0
  std::optional<double> shift_rad2_s2;  // σ: the modes nearest to it; empty: the lowest
};

enum class MassMatrixKind { consistent, lumped };
inline constexpr NameTable kMassMatrixKinds{std::array{
    NamedValue<MassMatrixKind>{MassMatrixKind::consistent, "consistent"},
    NamedValue<MassMatrixKind>{MassMatrixKind::lumped, "lumped"},
}};
inline const char* to_string(MassMatrixKind kind) { return kMassMatrixKinds.name(kind).data(); }

struct NewtonOptions {
  int max_iterations = 25;
  double force_tolerance = 1e-8;        // ‖r‖∞ relative to the largest force term
  double constraint_tolerance_m = 1e-10;  // ‖Φ‖∞ (m or rad·m)
  double displacement_tolerance_m = 1e-12;  // ‖Δq‖∞ that counts as converged
  // full: a new matrix and LU every iteration; reuse: modified Newton, keeping the last LU
  // (across steps too) while the residual contracts fast enough (solvers/newton.hpp);
  // automatic: reuse in the time steps of models whose matrix costs most against a residual,
  // full otherwise (solvers/newton.hpp, resolved_jacobian).
  enum class Jacobian { automatic, full, reuse };
  Jacobian jacobian = Jacobian::automatic;
};
inline constexpr NameTable kJacobianKinds{std::array{
    NamedValue<NewtonOptions::Jacobian>{NewtonOptions::Jacobian::automatic, "auto"},
    NamedValue<NewtonOptions::Jacobian>{NewtonOptions::Jacobian::full, "full"},
    NamedValue<NewtonOptions::Jacobian>{NewtonOptions::Jacobian::reuse, "reuse"},
}};
inline const char* to_string(NewtonOptions::Jacobian kind) { return kJacobianKinds.name(kind).data(); }

// Time integrator. All three are members of the generalized-α family in the form of Arnold &
// Brüls (2007) for constrained systems (solvers/generalized_alpha.hpp):
//   newmark:            β, γ as given (β = ¼, γ = ½ is the paper's trapezoidal rule)
//   hht:                Hilber–Hughes–Taylor α from ρ∞ ∈ [½, 1]
//   generalized_alpha:  Chung–Hulbert parameters from ρ∞ ∈ [0, 1]
// ρ∞ is the spectral radius at infinite frequency: 1 keeps every mode, 0 damps the highest
// at once; ρ∞ = 1 recovers the trapezoidal rule.
// The default is generalized-α with ρ∞ = 0.9: on these index-3 systems the trapezoidal rule
// leaves an undamped step-to-step zigzag in the multipliers, hence in the driver efforts
// (6× the true peak torque on the README's linkage), while ρ∞ = 0.9 removes it, keeps second
// order and changes the peak strains of the paper's linkages by less than 1e-6 of themselves
// (docs/paper-study.md, "Integrator"); a smaller ρ∞ only damps the physical modes more. The
// paper's Newmark (¼, ½) is `integrator: {type: newmark}`.
struct IntegratorOptions {
  enum class Kind { newmark, hht, generalized_alpha };
  Kind kind = Kind::generalized_alpha;
  double beta = 0.25;         // newmark only
  double gamma = 0.5;         // newmark only
  double rho_infinity = 0.9;  // hht and generalized_alpha
};
inline constexpr NameTable kIntegratorKinds{std::array{
    NamedValue<IntegratorOptions::Kind>{IntegratorOptions::Kind::newmark, "newmark"},
    NamedValue<IntegratorOptions::Kind>{IntegratorOptions::Kind::hht, "hht"},
    NamedValue<IntegratorOptions::Kind>{IntegratorOptions::Kind::generalized_alpha, "generalized_alpha"},
}};
inline const char* to_string(IntegratorOptions::Kind kind) { return kIntegratorKinds.name(kind).data(); }

// Adaptive time stepping (dynamic runs): the step grows and shrinks to keep the local error
// estimate of the integrator below `tolerance_m`, and is cut when Newton fails. Steps always
// land on the output times.
struct AdaptiveOptions {
  bool enabled = false;
  double tolerance_m = 1e-6;  // local error in the coordinates per step (m)
  double min_step_s = 1e-9;   // give up below this step
  double max_step_s = 0.0;    // 0: the output interval
};

// Back end of the Newton iteration matrix (assembly/linear_system_factory.hpp). `automatic`
// takes the fastest measured for the model's size (bench/roof_benchmark.cpp): KLU.
// `klu` orders by AMD, and large systems by two domains whose solves run on two cores
// (assembly/klu_linear_system.hpp); klu_two_domains always by two domains; klu_nested_dissection
// by METIS's nested dissection (docs/performance.md, "Faster large steps": it pays on wide grids,
// not on long roofs).
enum class LinearSolverKind { automatic, dense, klu, umfpack, klu_nested_dissection, klu_two_domains };
inline constexpr NameTable kLinearSolverKinds{std::array{
    NamedValue<LinearSolverKind>{LinearSolverKind::automatic, "automatic"},
    NamedValue<LinearSolverKind>{LinearSolverKind::dense, "dense"},
    NamedValue<LinearSolverKind>{LinearSolverKind::klu, "klu"},
    NamedValue<LinearSolverKind>{LinearSolverKind::umfpack, "umfpack"},
    NamedValue<LinearSolverKind>{LinearSolverKind::klu_nested_dissection, "klu_nested_dissection"},
    NamedValue<LinearSolverKind>{LinearSolverKind::klu_two_domains, "klu_two_domains"},
}};
inline const char* to_string(LinearSolverKind kind) { return kLinearSolverKinds.name(kind).data(); }

// When a dynamic or quasi-static run ends: at end_time, as soon as every latch of the
// model's hinges has locked (a spring-driven deployment), or once the structure has settled
// (SettlingOptions); end_time is then the limit.
enum class EndCondition { end_time, all_latched, settled };
inline constexpr NameTable kEndConditions{std::array{
    NamedValue<EndCondition>{EndCondition::end_time, "end_time"},
    NamedValue<EndCondition>{EndCondition::all_latched, "all_latched"},
    NamedValue<EndCondition>{EndCondition::settled, "settled"},
}};

// end_when: settled. The structure has settled at the first time t_s from which, for `hold_s`
// without a break, its kinetic energy stays at or below `kinetic_energy_J` and every rate
// |q̇_i| at or below `rate` (m/s for positions, 1/s for rotations and frame entries); the run
// stops at t_s + hold_s and reports t_s as the settling time (docs/theory.md, "Settling").
struct SettlingOptions {
  double kinetic_energy_J = 0.0;
  double rate = 0.0;
  double hold_s = 0.0;
  int node = -1;  // whose settled position the summary and the CLI report; -1: none named
};

// Rayleigh damping C = α M + β K (docs/theory.md, "Rayleigh damping"), on absolute rates: the
// α part also brakes rigid motion, the deployment itself. 0, 0: none.
struct RayleighDamping {
  double mass_factor_1_s = 0.0;     // α (1/s)
  double stiffness_factor_s = 0.0;  // β (s)
  // K of the β part: the tangent at the initial state, or at the current one.
  enum class Stiffness { initial, current };
  Stiffness stiffness = Stiffness::initial;
  bool any() const { return mass_factor_1_s > 0.0 || stiffness_factor_s > 0.0; }
};
inline constexpr NameTable kRayleighStiffnesses{std::array{
    NamedValue<RayleighDamping::Stiffness>{RayleighDamping::Stiffness::initial, "initial"},
    NamedValue<RayleighDamping::Stiffness>{RayleighDamping::Stiffness::current, "current"},
}};

struct AnalysisOptions {
  AnalysisType type = AnalysisType::dynamic;
  double end_time_s = 1.0;
  EndCondition end_when = EndCondition::end_time;
  SettlingOptions settling;  // end_when: settled only
  RayleighDamping rayleigh;
  double step_s = 1e-3;
  double output_interval_s = 0.0;  // 0: every step
  int load_steps = 1;              // initial thermal equilibrium: ΔT applied in this many parts
  NewtonOptions newton;
  IntegratorOptions integrator;
  AdaptiveOptions adaptive;
  MassMatrixKind mass = MassMatrixKind::consistent;
  LinearSolverKind linear_solver = LinearSolverKind::automatic;
  ContinuationSettings continuation;  // type continuation only
  ModalSettings modal;                // type modal only
};

// What history.csv holds (results/history_layout.hpp resolves it; docs/model-format.md,
// "Choosing what history.csv holds"). Each list is empty when the model does not choose, and
// then the default applies: everything for a small model, a reduced set for a large one.
struct OutputSelection {
  // Node names or glob patterns (* and ?), or one of the words "all", "moving" (every node not
  // fixed in all of its axes).
  std::vector<std::string> nodes;
  // Element names or glob patterns, or one of the words "all", "none".
  std::vector<std::string> elements;
  // Column families: position, displacement, the element quantities' keys (strain, mstrain,
  // force, stress, ...), driver, reaction, energy.
  std::vector<std::string> quantities;

  bool empty() const { return nodes.empty() && elements.empty() && quantities.empty(); }
};

struct OutputOptions {
  std::string history_file = "history.csv";
  std::string summary_file = "summary.json";
  bool vtk = false;  // also a ParaView time series in vtk/ (output/vtk_writer.hpp)
  bool hdf5 = false;  // also history.h5 and its index history.xdmf (output/hdf5_writer.hpp)
  OutputSelection select;
};

// The file's `checks` (docs/model-format.md): what the checks of a run take that is no
// member's capacity.
struct CheckSettings {
  // The clearance watch (checks/clearance.hpp): the least distance between members along the
  // run. Off, no clearance is computed.
  bool clearance = true;
  // The least distance (m) members must keep; a closer pair fails the verdict. Empty: the
  // clearance is reported, never a failure.
  std::optional<double> required_clearance_m;
};

struct Model {
  std::string name;
  std::string description;
  int dimension = 2;  // 2 or 3
  std::vector<Node> nodes;
  std::vector<Material> materials;
  std::vector<Section> sections;  // named cross-sections that elements may take
  std::vector<BarElement> bars;
  std::vector<BeamElement> beams;
  std::vector<CableElement> cables;
  std::vector<HingeElement> hinges;
  std::vector<Member> members;  // as listed in the file; the other elements are members of their own
  std::vector<FixedNode> supports;
  std::vector<Joint> joints;
  std::vector<Driver> drivers;
  std::vector<NodalLoad> loads;
  Eigen::Vector3d gravity_m_s2 = Eigen::Vector3d::Zero();
  TimeFunction temperature_change_C;  // model-wide ΔT(t), for bars that give none
  // T_ref (°C), `thermal.reference_temperature_C`: the stress-free temperature, at which the
  // materials' temperature tables are read for ΔT = 0. Empty: the environment's, else 20 °C
  // (model/material_law.hpp, reference_temperature_C).
  std::optional<double> reference_temperature_C;
  // When given, the members' temperatures come from it, step by step (thermal/), not from ΔT.
  std::optional<Environment> environment;
  // Dynamic runs from the initial equilibrium start with these (none given: at rest).
  InitialVelocities initial_velocities;
  AnalysisOptions analysis;
  OutputOptions output;
  CheckSettings checks;

  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int n_bars() const { return static_cast<int>(bars.size()); }
  int n_beams() const { return static_cast<int>(beams.size()); }
  int n_cables() const { return static_cast<int>(cables.size()); }
};

}  // namespace deploydyn
