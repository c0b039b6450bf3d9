#pragma once
// The element interface: what every element type (the bar, later beams) gives the rest of the
// program. Two halves, after the multibody and FE codes we take as models:
//
//  - ElementKind describes a type over a Model (names, nodes, result quantities, ΔT): what the
//    writers, `check` and the Python module need without building any mechanics.
//  - ElementGroup is the mechanics of all elements of one type in a model, bound to the
//    global unknowns (built by ElementKind::make_group). Like MFEM's integrator lists, the
//    assembler makes one virtual call per type and pass; the group loops over its elements
//    with fixed-size kernels (elements/local_element_group.hpp). The iteration-matrix block
//    is c_K K + c_M M, Chrono's ChElementBase::ComputeKRMmatrices(Kfactor, Rfactor, Mfactor)
//    without R (no element damping yet); each group reports its own strain energy, as Drake's
//    force elements do.
//
// An element contributes, for  M q̈ + f_int(q, t) + Bᵀλ = f_ext(t)  (docs/theory.md):
// f_int and its tangent K = ∂f_int/∂q (material + geometric), M, its weight, its strain
// energy U with f_int = ∂U/∂q, and ∂f_int/∂(thermal factor) for path following in ΔT.
// Every thermal strain is scaled by a `thermal_factor` (1 in a run). Each call gets one
// EvaluationPoint (configuration, rates, time, thermal factor, the group's history) and the
// group keeps no state between calls. A type whose elements carry modes or a history from step
// to step also implements SwitchingGroup (elements/switching_group.hpp).
//
// Adding a type: its folder elements/<type>/ with a kind and a group, one line in
// elements/element_kinds.cpp, and its storage in Model (docs/adding-an-element.md).

#include <Eigen/Core>
#include <algorithm>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "deploydyn/model/matrix_entry.hpp"
#include "deploydyn/constraints/constraint.hpp"
#include "deploydyn/elements/element_entry.hpp"
#include "deploydyn/elements/evaluation_point.hpp"
#include "deploydyn/model/time_function.hpp"

namespace deploydyn {

struct Model;
class DofMap;

// One quantity an element reports at a configuration, e.g. the bar's axial force.
struct ResultQuantity {
  std::string_view key;   // history.csv column prefix ("force.<element>"), summary.json key
  std::string_view name;  // with its unit: VTK cell array, Python ("axial_force_N")
  bool recorded = true;   // written to history, summary and VTK; false: computed on request
  // In history.csv and summary.json unless the model's output selection asks otherwise
  // (results/history_layout.hpp); envelopes.csv and VTK have every recorded quantity.
  bool by_default = true;
};

// The results of every element of one type at one configuration: the quantities of its
// ElementKind::quantities(), element after element.
struct ElementResults {
  int n_quantities = 0;
  std::vector<double> values;  // values[element · n_quantities + quantity]

  int n_elements() const {
    return n_quantities > 0 ? static_cast<int>(values.size()) / n_quantities : 0;
  }
  double at(int element, int quantity) const {
    return values[static_cast<std::size_t>(element * n_quantities + quantity)];
  }
};

// Weights of an element's iteration-matrix block c_K K + c_D D + c_M M, where D = ∂f_d/∂q̇ is
// the block of the forces f_d(q, q̇, t) that depend on the rates (dampers, friction), added
// when the evaluation point gives the rates.
struct TangentWeights {
  double stiffness = 1.0;  // c_K
  double mass = 0.0;       // c_M
  double damping = 0.0;    // c_D = ∂q̇/∂q of the integrator (γ/(β h) for Newmark)
};

// An element as a lumped body that its environment heats (thermal/): indices into
// Model::materials and Model::sections (−1: the element takes no section).
struct HeatedBody {
  int material = 0;
  int section = -1;
  // A beam's local y as the file places it (unit, ⟂ its axis): the axes its through-depth
  // gradients take; zero for an element that does not bend under one.
  Eigen::Vector3d local_y = Eigen::Vector3d::Zero();
};

// An element's own thermal load over time (°C): the ΔT of its axis and, for a type that bends
// under them (beams), the through-depth differences T(+y face) − T(−y face) and across z.
struct ElementThermalLoad {
  TimeFunction axis_C;
  std::optional<TimeFunction> across_y_C, across_z_C;  // empty: the type does not bend under them
};

class ElementGroup {
 public:
  virtual ~ElementGroup() = default;

  virtual int n_elements() const = 0;
  // Equations that taking every element as rigid would add (Grübler count): 1 per bar, 3 per
  // 2D beam, 6 per 3D beam (its nodes' frame orthonormality is counted among the constraints).
  virtual int n_rigid_body_conditions() const = 0;

  // Each adds its elements' share into the global vector (which the caller has sized).
  virtual void add_internal_force(const EvaluationPoint& at, Eigen::VectorXd& f) const = 0;
  // ∂f_int/∂(thermal factor) at the point: the same at every factor where f_int is linear in
  // it (bars, beams), not for a cable, whose slack state depends on it.
  virtual void add_thermal_force_derivative(const EvaluationPoint& at, Eigen::VectorXd& f) const = 0;
  // ∂f_int/∂t at the point through the rate of ΔT(t) (a quasi-static deployment in time).
  virtual void add_thermal_force_rate(const EvaluationPoint& at, Eigen::VectorXd& f) const = 0;
  virtual void add_mass_times(const Eigen::VectorXd& a, Eigen::VectorXd& out) const = 0;
  // The elements' own weight under gravity g (m/s²).
  virtual void add_weight(const Eigen::Vector3d& gravity_m_s2, Eigen::VectorXd& f) const = 0;
  virtual double strain_energy(const EvaluationPoint& at) const = 0;
  // Largest |diagonal entry| of the elements' K at the point: a scale, not a norm.
  virtual double largest_stiffness_diagonal(const EvaluationPoint& at) const = 0;
  // How far the elements turn or deform between two configurations, as a share of their size
  // (the bar: max |Δ(x_b − x_a)| / L0): the static solver's load-step rule.
  virtual double largest_relative_change(const Eigen::VectorXd& q,
                                         const Eigen::VectorXd& q_before) const = 0;

  // The iteration-matrix block: its (row, col) pattern, appended in the order in which
  // add_iteration_matrix writes the values, one value per entry at values[*slot++].
  virtual int n_matrix_entries() const = 0;
  virtual void append_matrix_entries(std::vector<MatrixEntry>& entries) const = 0;
  // With the point's rates, also the rate forces' c_K ∂f_d/∂q + c_D ∂f_d/∂q̇.
  virtual void add_iteration_matrix(const EvaluationPoint& at, const TangentWeights& weights,
                                    std::span<double> values, const int*& slot) const = 0;

  // The quantities of ElementKind::quantities() of element `element`, in that order.
  virtual void results(int element, const EvaluationPoint& at, std::span<double> out) const = 0;
  // Reference length (m) of element `element`: a length scale for step rules and plots; 0 for
  // an element without a length of its own (a hinge between two beam nodes).
  virtual double reference_length_m(int element) const = 0;

  // Forces that depend on the rates q̇, f_d(q, q̇, t) (dampers, sliding friction, material
  // damping), added to f at a point that gives the rates. Their block goes into
  // add_iteration_matrix. Statics has none (q̇ = 0). On every group, not only the switching
  // ones: bars, beams and cables have material damping. Default: none.
  virtual bool has_rate_forces() const { return false; }
  virtual void add_rate_force(const EvaluationPoint& at, Eigen::VectorXd& f) const {
    (void)at, (void)f;
  }
};

class ElementKind {
 public:
  virtual ~ElementKind() = default;

  // As model files and messages spell the type: "bar".
  virtual std::string_view name() const = 0;
  // In a model of `dimension` 2 or 3 (a 3D beam reports more than a 2D one).
  virtual std::span<const ResultQuantity> quantities(int dimension) const = 0;

  virtual int n_elements(const Model& model) const = 0;
  virtual const std::string& element_name(const Model& model, int element) const = 0;
  virtual int n_element_nodes() const = 0;
  virtual int element_node(const Model& model, int element, int local_node) const = 0;
  // VTK cell type of an element (3: a two-node line).
  virtual int vtk_cell_type() const = 0;
  virtual double mass_kg(const Model& model, int element) const = 0;
  virtual double temperature_change_C(const Model& model, int element, double t) const = 0;
  // Gives every element of this type the temperature change ΔT(t) (°C), as its own.
  virtual void set_temperature_change(Model& model, const TimeFunction& change_C) const = 0;
  // The element as a body an environment heats; empty for one with no body of its own (a hinge).
  virtual std::optional<HeatedBody> heated_body(const Model& model, int element) const = 0;
  // The element's own thermal load as the model holds it; empty for a type with no temperature
  // (a hinge). The deployability window reads and rescales it (solvers/window_thermal_load.hpp).
  virtual std::optional<ElementThermalLoad> thermal_load(const Model& model, int element) const = 0;
  // Replaces the functions `thermal_load` gives, and nothing else; a type with none ignores it.
  virtual void set_thermal_load(Model& model, int element, const ElementThermalLoad& load) const = 0;
  // Gives element `element` alone the temperature change ΔT(t) (°C): the environment's coupling
  // (thermal/thermal_coupling.hpp) sets it each step. A type with no temperature ignores it.
  virtual void set_element_temperature_change(Model& model, int element,
                                              const TimeFunction& change_C) const = 0;
  // Gives element `element` alone the through-depth differences T(+y face) − T(−y face) and
  // T(+z face) − T(−z face) (°C) over time, on its section's depths: the environment's
  // section gradients (thermal/section_temperature_difference.hpp). Call before the element's
  // group is made. Only beams bend under them; by default a type ignores them.
  virtual void set_element_temperature_gradients(Model& model, int element, const TimeFunction& across_y_C,
                                                 const TimeFunction& across_z_C) const {
    (void)model, (void)element, (void)across_y_C, (void)across_z_C;
  }
  // Unknowns a node of one of its elements carries beyond its position, appended by name
  // (a rotation "rz", a slope "dx/ds"); the bar adds none.
  virtual void add_node_unknowns(const Model& model,
                                 std::vector<std::vector<std::string>>& per_node) const = 0;
  // Writes the initial values of the unknowns it added into q (positions already set; the
  // rest 0 until a type writes them): the 3D beam's frames R = I. The bar writes none.
  virtual void set_initial_node_unknowns(const Model& model, const DofMap& dofs,
                                         Eigen::VectorXd& q) const = 0;
  // Constraints its elements bring (the 3D beam: the orthonormality of its nodes' frames),
  // which the assembler appends after the supports and drivers. The bar brings none.
  virtual std::vector<std::unique_ptr<Constraint>> make_constraints(const Model& model,
                                                                    const DofMap& dofs) const = 0;

  // The keys of its entries in the model file, and how it reads and writes one. `read` gets an
  // entry whose keys are among fields() and appends the element, named `name`, to `model`,
  // whose nodes, materials and model-wide ΔT are already read.
  virtual std::span<const ElementField> fields() const = 0;
  virtual void read(const std::string& name, const ElementEntryReader& entry,
                    Model& model) const = 0;
  // Every key, defaults explicit (mass and length too: a reload needs no recomputation).
  virtual void write(const Model& model, int element, ElementEntryWriter& entry) const = 0;

  // Its elements' mechanics, bound to `dofs`. Throws std::invalid_argument for elements whose
  // mechanics cannot be built.
  virtual std::unique_ptr<ElementGroup> make_group(const Model& model,
                                                   const DofMap& dofs) const = 0;
};

}  // namespace deploydyn
