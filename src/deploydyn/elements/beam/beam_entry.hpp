#pragma once
// A beam's entry in the model file (docs/model-format.md, `elements`, `type: beam`): its keys,
// and how it is read into Model::beams and written back. Keys marked "3D only" are an error in
// a 2D model.

#include <span>
#include <string>

#include "deploydyn/elements/element_entry.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn::beam {

std::span<const ElementField> entry_fields();
void read_entry(const std::string& name, const ElementEntryReader& entry, Model& model);
void write_entry(const Model& model, int beam, ElementEntryWriter& entry);

}  // namespace deploydyn::beam
