#pragma once
// The element types a model may hold, in the order every listing uses: the assembler's
// groups, history.csv columns, summary.json, VTK cells, `check`, the Python module. Within a
// type, elements keep model order. Adding a type is one line in element_kinds.cpp.

#include <span>
#include <string>
#include <vector>

#include "deploydyn/elements/element.hpp"

namespace deploydyn {

std::span<const ElementKind* const> element_kinds();

// Every element of `model` over all types, as (kind, index within the kind).
struct ElementRef {
  const ElementKind* kind = nullptr;
  int index = 0;
};
std::vector<ElementRef> all_elements(const Model& model);
int n_elements(const Model& model);
std::vector<std::string> element_names(const Model& model);
// The names of the elements whose type reports quantity `name`, in the same order as
// Assembler::element_quantity gives its values.
std::vector<std::string> element_names(const Model& model, std::string_view quantity);

// Index of the quantity named `name` (ResultQuantity::name) of `kind` in a model of
// `dimension`, or −1.
int quantity_index(const ElementKind& kind, int dimension, std::string_view name);

}  // namespace deploydyn
