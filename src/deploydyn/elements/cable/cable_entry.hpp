#pragma once
// A cable's entry in the model file (docs/model-format.md, `elements`, type `cable`): its keys,
// and how it is read into Model::cables and written back.

#include <span>
#include <string>

#include "deploydyn/elements/element_entry.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn::cable {

std::span<const ElementField> entry_fields();
void read_entry(const std::string& name, const ElementEntryReader& entry, Model& model);
void write_entry(const Model& model, int cable, ElementEntryWriter& entry);

}  // namespace deploydyn::cable
