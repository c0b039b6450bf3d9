#pragma once
// A hinge's entry in the model file: its keys (the table docs/model-format.md shows) and how it
// is read and written.

#include <span>
#include <string>

#include "deploydyn/elements/element_entry.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn::hinge {

std::span<const ElementField> entry_fields();
void read_entry(const std::string& name, const ElementEntryReader& entry, Model& model);
void write_entry(const Model& model, int index, ElementEntryWriter& entry);

}  // namespace deploydyn::hinge
