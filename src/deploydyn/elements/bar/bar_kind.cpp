#include "deploydyn/elements/bar/bar_kind.hpp"

#include <array>
#include <cmath>

#include "deploydyn/elements/bar/bar.hpp"
#include "deploydyn/elements/bar/bar_entry.hpp"
#include "deploydyn/elements/bar/bar_quantities.hpp"
#include "deploydyn/elements/heated_material.hpp"
#include "deploydyn/elements/local_element_group.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {
namespace {

// One bar for LocalElementGroup: node a's D coordinates, then node b's, and its constants.
template <int D>
struct BarRecord {
  static constexpr int kDofs = 2 * D;
  static constexpr int kRigidBodyConditions = 1;  // its length
  using Vector = bar::ElementVector<D>;
  using Matrix = bar::ElementMatrix<D>;
  // The bar's state, and its material's where E or α follows the temperature.
  struct State : bar::State<D> {
    HeatedMaterial material;
  };

  std::array<int, kDofs> dofs{};
  bar::Section section;
  double mass_kg = 0.0;
  double expansion_per_C = 0.0;                        // α
  MaterialLaw law;                                     // E(T), ε_t(T) when tables give them
  double area_m2 = 0.0;                                // A, for the stress N/A
  const TimeFunction* temperature_change_C = nullptr;  // ΔT(t), in the model

  double thermal_strain(double t) const { return expansion_per_C * temperature_change_C->value(t); }

  State evaluate(const Vector& q, double t, double thermal_factor) const {
    if (!law.varies()) {
      return {bar::evaluate<D>(q.template head<D>(), q.template tail<D>(), section,
                               thermal_factor * thermal_strain(t)),
              {}};
    }
    const HeatedMaterial m = HeatedMaterial::read(law, *temperature_change_C, t, thermal_factor);
    bar::Section at_temperature = section;
    at_temperature.axial_stiffness_N = m.at.youngs_modulus_Pa * area_m2;
    return {bar::evaluate<D>(q.template head<D>(), q.template tail<D>(), at_temperature, m.at.thermal_strain), m};
  }
  Vector internal_force(const State& s) const { return bar::internal_force<D>(s, section); }
  // ∂f/∂T: through ε_t, and through E(T) with a table.
  Vector force_per_temperature(const State& s) const {
    return bar::internal_force_per_temperature<D>(s, section, s.material.at.expansion_per_C,
                                                  s.material.at.youngs_modulus_slope_Pa_C * area_m2);
  }
  // The thermal strain of the factor is factor · ε_t: chain rule through ∂f/∂ε_t; with tables,
  // through ∂f/∂T and ∂T/∂λ = ΔT(t).
  Vector thermal_force_derivative(const State& s, double t) const {
    if (law.varies()) return temperature_change_C->value(t) * force_per_temperature(s);
    return thermal_strain(t) * bar::internal_force_per_thermal_strain<D>(s, section);
  }
  // ∂f/∂t through ε_t(t) = α ΔT(t); with tables, through ∂f/∂T and ∂T/∂t.
  Vector thermal_force_rate(const State& s, double t) const {
    if (law.varies()) return s.material.temperature_rate_C_s(*temperature_change_C, t) * force_per_temperature(s);
    return expansion_per_C * temperature_change_C->derivative(t) *
           bar::internal_force_per_thermal_strain<D>(s, section);
  }
  Matrix tangent(const State& s) const { return bar::tangent<D>(s, section); }
  bool damped() const { return section.damping_time_s > 0.0; }
  Vector damping_force(const State& s, const Vector& v) const { return bar::damping_force<D>(s, section, v); }
  Matrix damping_tangent(const State& s, const Vector& v, double c_q, double c_v) const {
    return bar::damping_tangent<D>(s, section, v, c_q, c_v);
  }
  Matrix mass(MassMatrixKind kind) const { return bar::mass_matrix<D>(mass_kg, kind); }
  // The bar's weight is shared equally by its two nodes (docs/theory.md).
  Vector weight(const Eigen::Vector3d& gravity_m_s2) const {
    Vector f;
    for (int i = 0; i < kDofs; ++i) f[i] = 0.5 * mass_kg * gravity_m_s2[i % D];
    return f;
  }
  double strain_energy(const State& s) const { return bar::strain_energy<D>(s, section); }
  // |Δ(x_b − x_a)| / L0: how far the bar turned or stretched.
  double relative_change(const Vector& q, const Vector& q_before) const {
    double change2 = 0.0;
    for (int axis = 0; axis < D; ++axis) {
      const double change = (q[D + axis] - q[axis]) - (q_before[D + axis] - q_before[axis]);
      change2 += change * change;
    }
    return std::sqrt(change2) / section.reference_length_m;
  }
  // At the slots of bar_quantities.hpp.
  void results(const State& s, std::span<double> out) const {
    out[bar::kStrain] = s.strain;
    out[bar::kMechanicalStrain] = s.mechanical_strain;
    out[bar::kAxialForce] = s.axial_force_N;
    out[bar::kStress] = s.axial_force_N / area_m2;
    out[bar::kLength] = s.length_m;
  }
  double reference_length_m() const { return section.reference_length_m; }
};

template <int D>
std::unique_ptr<ElementGroup> make_bars(const Model& model, const DofMap& dofs) {
  std::vector<BarRecord<D>> records;
  records.reserve(model.bars.size());
  const double reference_C = reference_temperature_C(model);
  for (const BarElement& e : model.bars) {
    const Material& material = model.materials[e.material];
    BarRecord<D>& bar = records.emplace_back();
    for (int axis = 0; axis < D; ++axis) {
      bar.dofs[axis] = dofs.index(e.node_a, axis);
      bar.dofs[D + axis] = dofs.index(e.node_b, axis);
    }
    bar.section = {material.youngs_modulus_Pa * e.area_m2, e.reference_length_m, bar::ForceLaw::linear,
                   material.damping_time_s};
    bar.mass_kg = e.mass_kg;
    bar.expansion_per_C = material.expansion_per_C;
    bar.law = MaterialLaw(material, reference_C);
    bar.area_m2 = e.area_m2;
    bar.temperature_change_C = &e.temperature_change_C;
  }
  return std::make_unique<LocalElementGroup<BarRecord<D>>>(std::move(records), model.analysis.mass);
}

class BarKind final : public ElementKind {
 public:
  std::string_view name() const override { return "bar"; }
  std::span<const ResultQuantity> quantities(int) const override { return bar::kQuantityTable; }
  int n_elements(const Model& model) const override { return model.n_bars(); }
  const std::string& element_name(const Model& model, int element) const override {
    return model.bars[element].name;
  }
  int n_element_nodes() const override { return 2; }
  int element_node(const Model& model, int element, int local_node) const override {
    return local_node == 0 ? model.bars[element].node_a : model.bars[element].node_b;
  }
  int vtk_cell_type() const override { return 3; }  // VTK_LINE
  double mass_kg(const Model& model, int element) const override {
    return model.bars[element].mass_kg;
  }
  double temperature_change_C(const Model& model, int element, double t) const override {
    return model.bars[element].temperature_change_C.value(t);
  }
  void set_temperature_change(Model& model, const TimeFunction& change_C) const override {
    for (BarElement& bar : model.bars) bar.temperature_change_C = change_C;
  }
  std::optional<ElementThermalLoad> thermal_load(const Model& model, int element) const override {
    return ElementThermalLoad{model.bars[element].temperature_change_C, {}, {}};
  }
  void set_thermal_load(Model& model, int element, const ElementThermalLoad& load) const override {
    model.bars[element].temperature_change_C = load.axis_C;
  }
  std::optional<HeatedBody> heated_body(const Model& model, int element) const override {
    return HeatedBody{model.bars[element].material, model.bars[element].section};
  }
  void set_element_temperature_change(Model& model, int element, const TimeFunction& change_C) const override {
    model.bars[element].temperature_change_C = change_C;
  }
  void add_node_unknowns(const Model&, std::vector<std::vector<std::string>>&) const override {}
  void set_initial_node_unknowns(const Model&, const DofMap&, Eigen::VectorXd&) const override {}
  std::vector<std::unique_ptr<Constraint>> make_constraints(const Model&,
                                                            const DofMap&) const override {
    return {};
  }
  std::span<const ElementField> fields() const override { return bar::entry_fields(); }
  void read(const std::string& name, const ElementEntryReader& entry, Model& model) const override {
    bar::read_entry(name, entry, model);
  }
  void write(const Model& model, int element, ElementEntryWriter& entry) const override {
    bar::write_entry(model, element, entry);
  }
  std::unique_ptr<ElementGroup> make_group(const Model& model, const DofMap& dofs) const override {
    return model.dimension == 2 ? make_bars<2>(model, dofs) : make_bars<3>(model, dofs);
  }
};

}  // namespace

const ElementKind& bar_kind() {
  static const BarKind kind;
  return kind;
}

}  // namespace deploydyn
