#pragma once
// Reads a study file's `sampling` section (docs/model-format.md, "Sampled studies") into a
// Sampling; every error names the study file, line and field, and says what is allowed.

#include "deploydyn/io/yaml_reader.hpp"
#include "deploydyn/study/sampling.hpp"

namespace deploydyn {

Sampling read_sampling(const io::YamlValue& section);

}  // namespace deploydyn
