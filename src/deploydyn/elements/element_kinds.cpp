#include "deploydyn/elements/element_kinds.hpp"

#include "deploydyn/elements/bar/bar_kind.hpp"
#include "deploydyn/elements/beam/beam_kind.hpp"
#include "deploydyn/elements/cable/cable_kind.hpp"
#include "deploydyn/elements/hinge/hinge_kind.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

std::span<const ElementKind* const> element_kinds() {
  static const ElementKind* const kKinds[] = {
      &bar_kind(),
      &beam_kind(),
      &cable_kind(),
      &hinge_kind(),
  };
  return kKinds;
}

std::vector<ElementRef> all_elements(const Model& model) {
  std::vector<ElementRef> elements;
  elements.reserve(static_cast<std::size_t>(n_elements(model)));
  for (const ElementKind* kind : element_kinds()) {
    for (int e = 0; e < kind->n_elements(model); ++e) elements.push_back({kind, e});
  }
  return elements;
}

int n_elements(const Model& model) {
  int n = 0;
  for (const ElementKind* kind : element_kinds()) n += kind->n_elements(model);
  return n;
}

std::vector<std::string> element_names(const Model& model) {
  std::vector<std::string> names;
  for (const ElementRef& e : all_elements(model))
    names.push_back(e.kind->element_name(model, e.index));
  return names;
}

std::vector<std::string> element_names(const Model& model, std::string_view quantity) {
  std::vector<std::string> names;
  for (const ElementKind* kind : element_kinds()) {
    if (quantity_index(*kind, model.dimension, quantity) < 0) continue;
    for (int e = 0; e < kind->n_elements(model); ++e) names.push_back(kind->element_name(model, e));
  }
  return names;
}

int quantity_index(const ElementKind& kind, int dimension, std::string_view name) {
  const auto quantities = kind.quantities(dimension);
  for (std::size_t k = 0; k < quantities.size(); ++k) {
    if (quantities[k].name == name) return static_cast<int>(k);
  }
  return -1;
}

}  // namespace deploydyn
