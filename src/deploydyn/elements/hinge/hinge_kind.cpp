#include "deploydyn/elements/hinge/hinge_kind.hpp"

#include "deploydyn/elements/hinge/hinge_entry.hpp"
#include "deploydyn/elements/hinge/hinge_group.hpp"
#include "deploydyn/elements/hinge/hinge_quantities.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {
namespace {

class HingeKind final : public ElementKind {
 public:
  std::string_view name() const override { return "hinge"; }
  std::span<const ResultQuantity> quantities(int) const override { return hinge::kQuantityTable; }
  int n_elements(const Model& model) const override { return static_cast<int>(model.hinges.size()); }
  const std::string& element_name(const Model& model, int element) const override {
    return model.hinges[static_cast<std::size_t>(element)].name;
  }
  int n_element_nodes() const override { return 3; }
  int element_node(const Model& model, int element, int local_node) const override {
    return model.hinges[static_cast<std::size_t>(element)].nodes[static_cast<std::size_t>(local_node)];
  }
  int vtk_cell_type() const override { return 4; }  // VTK_POLY_LINE: A–H–B
  double mass_kg(const Model&, int) const override { return 0.0; }
  // A hinge has no temperature of its own; its friction feels ΔT through the bar A–H.
  double temperature_change_C(const Model&, int, double) const override { return 0.0; }
  void set_temperature_change(Model&, const TimeFunction&) const override {}
  std::optional<ElementThermalLoad> thermal_load(const Model&, int) const override { return std::nullopt; }
  void set_thermal_load(Model&, int, const ElementThermalLoad&) const override {}
  std::optional<HeatedBody> heated_body(const Model&, int) const override { return std::nullopt; }
  void set_element_temperature_change(Model&, int, const TimeFunction&) const override {}
  void add_node_unknowns(const Model&, std::vector<std::vector<std::string>>&) const override {}
  void set_initial_node_unknowns(const Model&, const DofMap&, Eigen::VectorXd&) const override {}
  std::vector<std::unique_ptr<Constraint>> make_constraints(const Model&, const DofMap&) const override {
    return {};  // its locks are the group's (SwitchingGroup::make_switched_constraints)
  }
  std::span<const ElementField> fields() const override { return hinge::entry_fields(); }
  void read(const std::string& name, const ElementEntryReader& entry, Model& model) const override {
    hinge::read_entry(name, entry, model);
  }
  void write(const Model& model, int element, ElementEntryWriter& entry) const override {
    hinge::write_entry(model, element, entry);
  }
  std::unique_ptr<ElementGroup> make_group(const Model& model, const DofMap& dofs) const override {
    return make_hinge_group(model, dofs);
  }
};

}  // namespace

const ElementKind& hinge_kind() {
  static const HingeKind kind;
  return kind;
}

}  // namespace deploydyn
