#pragma once
// Writes a Model as a model file (YAML) that load_model reads back to an equal Model: every
// value explicit (masses, reference lengths), functions inline, numbers in the shortest form
// that reads back exactly.

#include <iosfwd>
#include <string>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

void save_model(const Model& model, std::ostream& out);

// The same text. Written by io/yaml_emitter.hpp's PlainYamlEmitter, or by yaml-cpp when the
// model holds text that may need quotes: the same bytes as yaml-cpp's emitter either way.
std::string model_yaml(const Model& model);

// The text as yaml-cpp's emitter writes it: what model_yaml is tested against.
std::string model_yaml_with_yaml_cpp(const Model& model);

}  // namespace deploydyn
