#include "deploydyn/elements/cable/cable_kind.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "deploydyn/elements/cable/cable.hpp"
#include "deploydyn/elements/cable/cable_entry.hpp"
#include "deploydyn/elements/cable/cable_quantities.hpp"
#include "deploydyn/elements/heated_material.hpp"
#include "deploydyn/elements/local_element_group.hpp"
#include "deploydyn/elements/switching_group.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {
namespace {

// One cable for LocalElementGroup: node a's D coordinates, then node b's, and its constants.
template <int D>
struct CableRecord {
  static constexpr int kDofs = 2 * D;
  // Counted as a bar: a taut cable holds its length (a slack one holds nothing, which the
  // static count cannot know).
  static constexpr int kRigidBodyConditions = 1;
  using Vector = bar::ElementVector<D>;
  using Matrix = bar::ElementMatrix<D>;
  // The bar's state and the section at its time: L0 = L0(t).
  struct State {
    bar::State<D> bar;
    bar::Section section;
    double rest_length_rate_m_s = 0.0;  // L̇0: reeling, which the material damping leaves alone
    HeatedMaterial material;            // where E or α follows the temperature
  };

  std::array<int, kDofs> dofs{};
  double axial_stiffness_N = 0.0;  // EA
  double area_m2 = 0.0;            // A, for the stress N/A
  double mass_kg = 0.0;
  double expansion_per_C = 0.0;                        // α
  MaterialLaw law;                                     // E(T), ε_t(T) when tables give them
  double damping_time_s = 0.0;                         // τ of the material damping
  double initial_rest_length_m = 0.0;                  // L0(0): the length scale
  const TimeFunction* rest_length_m = nullptr;         // L0(t), in the model
  const TimeFunction* temperature_change_C = nullptr;  // ΔT(t), in the model

  double thermal_strain(double t) const { return expansion_per_C * temperature_change_C->value(t); }

  State evaluate(const Vector& q, double t, double thermal_factor) const {
    if (law.varies()) {
      const HeatedMaterial m = HeatedMaterial::read(law, *temperature_change_C, t, thermal_factor);
      const bar::Section section{m.at.youngs_modulus_Pa * area_m2, rest_length_m->value(t),
                                 bar::ForceLaw::tension_only, damping_time_s};
      return {bar::evaluate<D>(q.template head<D>(), q.template tail<D>(), section, m.at.thermal_strain),
              section, rest_length_m->derivative(t), m};
    }
    const bar::Section section{axial_stiffness_N, rest_length_m->value(t), bar::ForceLaw::tension_only,
                               damping_time_s};
    return {bar::evaluate<D>(q.template head<D>(), q.template tail<D>(), section,
                             thermal_factor * thermal_strain(t)),
            section, rest_length_m->derivative(t), {}};
  }
  // ∂f/∂T with tables: through ε_t and E(T), as the bar's.
  Vector force_per_temperature(const State& s) const {
    return bar::internal_force_per_temperature<D>(s.bar, s.section, s.material.at.expansion_per_C,
                                                  s.material.at.youngs_modulus_slope_Pa_C * area_m2);
  }
  bool damped() const { return damping_time_s > 0.0; }
  Vector damping_force(const State& s, const Vector& v) const {
    return bar::damping_force<D>(s.bar, s.section, v, s.rest_length_rate_m_s);
  }
  Matrix damping_tangent(const State& s, const Vector& v, double c_q, double c_v) const {
    return bar::damping_tangent<D>(s.bar, s.section, v, c_q, c_v, s.rest_length_rate_m_s);
  }
  Vector internal_force(const State& s) const { return bar::internal_force<D>(s.bar, s.section); }
  // As the bar's: the factor scales ε_t (theory.md, "Cables", Eq. C4).
  Vector thermal_force_derivative(const State& s, double t) const {
    if (law.varies()) return temperature_change_C->value(t) * force_per_temperature(s);
    return thermal_strain(t) * bar::internal_force_per_thermal_strain<D>(s.bar, s.section);
  }
  // ∂f/∂t through ε_t(t) = α ΔT(t) and through L0(t) (Eq. C5).
  Vector thermal_force_rate(const State& s, double t) const {
    if (law.varies()) {
      return s.material.temperature_rate_C_s(*temperature_change_C, t) * force_per_temperature(s) +
             rest_length_m->derivative(t) * cable::internal_force_per_rest_length<D>(s.bar, s.section);
    }
    return expansion_per_C * temperature_change_C->derivative(t) *
               bar::internal_force_per_thermal_strain<D>(s.bar, s.section) +
           rest_length_m->derivative(t) *
               cable::internal_force_per_rest_length<D>(s.bar, s.section);
  }
  Matrix tangent(const State& s) const { return bar::tangent<D>(s.bar, s.section); }
  Matrix mass(MassMatrixKind kind) const { return bar::mass_matrix<D>(mass_kg, kind); }
  // Shared equally by its two nodes, as a bar's.
  Vector weight(const Eigen::Vector3d& gravity_m_s2) const {
    Vector f;
    for (int i = 0; i < kDofs; ++i) f[i] = 0.5 * mass_kg * gravity_m_s2[i % D];
    return f;
  }
  double strain_energy(const State& s) const { return bar::strain_energy<D>(s.bar, s.section); }
  // |Δ(x_b − x_a)| / L0(0).
  double relative_change(const Vector& q, const Vector& q_before) const {
    const Vector change = q - q_before;
    return (change.template tail<D>() - change.template head<D>()).norm() / initial_rest_length_m;
  }
  // At the slots of cable_quantities.hpp.
  void results(const State& s, std::span<double> out) const {
    out[cable::kStrain] = s.bar.strain;
    out[cable::kMechanicalStrain] = s.bar.mechanical_strain;
    out[cable::kAxialForce] = s.bar.axial_force_N;
    out[cable::kRestLength] = s.section.reference_length_m;
    out[cable::kIsSlack] = s.bar.slack ? 1.0 : 0.0;
    out[cable::kStress] = s.bar.axial_force_N / area_m2;
    out[cable::kLength] = s.bar.length_m;
  }
  double reference_length_m() const { return initial_rest_length_m; }
};

// The cables' history (docs/theory.md, "Cables", Events): per cable 1 if it was slack at the end
// of the last converged step, 0 if taut, kNotYetSeen before the first step (the state at its
// start, the initial equilibrium, is then read from q_before). A flip appends a "slack" or
// "taut" event with the mechanical strain at the step's end. The slack state is not a mode of
// the residual (the law reads the state), so a step is never redone for it.
template <int D>
class CableGroup final : public LocalElementGroup<CableRecord<D>>, public SwitchingGroup {
 public:
  using LocalElementGroup<CableRecord<D>>::LocalElementGroup;

  int n_history() const override { return this->n_elements(); }
  void initial_history(std::span<double> history) const override {
    std::fill(history.begin(), history.end(), kNotYetSeen);
  }
  StepVerdict end_step(const StepEnds& ends, std::span<const double> before,
                       std::span<double> after, std::vector<ElementEvent>& events) const override {
    for (int e = 0; e < this->n_elements(); ++e) {
      const CableRecord<D>& cable = this->elements()[static_cast<std::size_t>(e)];
      const auto i = static_cast<std::size_t>(e);
      const bool was_slack =
          before[i] == kNotYetSeen
              ? cable.evaluate(this->gather(cable, ends.q_before), ends.time_before_s, 1.0)
                    .bar.slack
              : before[i] == kSlack;
      const bar::State<D> now =
          cable.evaluate(this->gather(cable, ends.q_after), ends.time_after_s, 1.0).bar;
      after[i] = now.slack ? kSlack : kTaut;
      if (now.slack != was_slack) {
        events.push_back(
            {ends.time_after_s, e, now.slack ? ElementEventKind::slack : ElementEventKind::taut,
             now.mechanical_strain});
      }
    }
    return StepVerdict::accept;
  }

 private:
  static constexpr double kTaut = 0.0, kSlack = 1.0, kNotYetSeen = -1.0;
};

template <int D>
std::unique_ptr<ElementGroup> make_cables(const Model& model, const DofMap& dofs) {
  std::vector<CableRecord<D>> records;
  records.reserve(model.cables.size());
  const double reference_C = reference_temperature_C(model);
  for (const CableElement& e : model.cables) {
    const Material& material = model.materials[e.material];
    CableRecord<D>& cable = records.emplace_back();
    for (int axis = 0; axis < D; ++axis) {
      cable.dofs[axis] = dofs.index(e.node_a, axis);
      cable.dofs[D + axis] = dofs.index(e.node_b, axis);
    }
    cable.axial_stiffness_N = material.youngs_modulus_Pa * e.area_m2;
    cable.area_m2 = e.area_m2;
    cable.mass_kg = e.mass_kg;
    cable.expansion_per_C = material.expansion_per_C;
    cable.law = MaterialLaw(material, reference_C);
    cable.damping_time_s = material.damping_time_s;
    cable.initial_rest_length_m = e.rest_length_m.value(0.0);
    cable.rest_length_m = &e.rest_length_m;
    cable.temperature_change_C = &e.temperature_change_C;
  }
  return std::make_unique<CableGroup<D>>(std::move(records), model.analysis.mass);
}

class CableKind final : public ElementKind {
 public:
  std::string_view name() const override { return "cable"; }
  std::span<const ResultQuantity> quantities(int) const override { return cable::kQuantityTable; }
  int n_elements(const Model& model) const override { return model.n_cables(); }
  const std::string& element_name(const Model& model, int element) const override {
    return model.cables[element].name;
  }
  int n_element_nodes() const override { return 2; }
  int element_node(const Model& model, int element, int local_node) const override {
    return local_node == 0 ? model.cables[element].node_a : model.cables[element].node_b;
  }
  int vtk_cell_type() const override { return 3; }  // VTK_LINE
  double mass_kg(const Model& model, int element) const override {
    return model.cables[element].mass_kg;
  }
  double temperature_change_C(const Model& model, int element, double t) const override {
    return model.cables[element].temperature_change_C.value(t);
  }
  void set_temperature_change(Model& model, const TimeFunction& change_C) const override {
    for (CableElement& cable : model.cables) cable.temperature_change_C = change_C;
  }
  std::optional<ElementThermalLoad> thermal_load(const Model& model, int element) const override {
    return ElementThermalLoad{model.cables[element].temperature_change_C, {}, {}};
  }
  void set_thermal_load(Model& model, int element, const ElementThermalLoad& load) const override {
    model.cables[element].temperature_change_C = load.axis_C;
  }
  std::optional<HeatedBody> heated_body(const Model& model, int element) const override {
    return HeatedBody{model.cables[element].material, model.cables[element].section};
  }
  void set_element_temperature_change(Model& model, int element, const TimeFunction& change_C) const override {
    model.cables[element].temperature_change_C = change_C;
  }
  void add_node_unknowns(const Model&, std::vector<std::vector<std::string>>&) const override {}
  void set_initial_node_unknowns(const Model&, const DofMap&, Eigen::VectorXd&) const override {}
  std::vector<std::unique_ptr<Constraint>> make_constraints(const Model&,
                                                            const DofMap&) const override {
    return {};
  }
  std::span<const ElementField> fields() const override { return cable::entry_fields(); }
  void read(const std::string& name, const ElementEntryReader& entry, Model& model) const override {
    cable::read_entry(name, entry, model);
  }
  void write(const Model& model, int element, ElementEntryWriter& entry) const override {
    cable::write_entry(model, element, entry);
  }
  std::unique_ptr<ElementGroup> make_group(const Model& model, const DofMap& dofs) const override {
    return model.dimension == 2 ? make_cables<2>(model, dofs) : make_cables<3>(model, dofs);
  }
};

}  // namespace

const ElementKind& cable_kind() {
  static const CableKind kind;
  return kind;
}

}  // namespace deploydyn
