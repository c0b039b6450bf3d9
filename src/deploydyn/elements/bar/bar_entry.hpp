#pragma once
// A bar's entry in the model file (docs/model-format.md, `elements`): its keys, and how it is
// read into Model::bars and written back.

#include <span>
#include <string>

#include "deploydyn/elements/element_entry.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn::bar {

std::span<const ElementField> entry_fields();
void read_entry(const std::string& name, const ElementEntryReader& entry, Model& model);
void write_entry(const Model& model, int bar, ElementEntryWriter& entry);

}  // namespace deploydyn::bar
