#pragma once
// Writes a Model as a model file (YAML) that load_model reads back to an equal Model: every
// value explicit (masses, reference lengths), functions inline, numbers in the shortest form
// that reads back exactly.

#include <iosfwd>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

void save_model(const Model& model, std::ostream& out);

}  // namespace deploydyn
