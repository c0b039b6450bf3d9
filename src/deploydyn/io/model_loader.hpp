#pragma once
// Reads a model file (YAML; JSON is accepted since it is YAML) into a validated Model.
// The format is documented in docs/model-format.md. Every error is an InputError naming the
// file, line, column and field.

#include <filesystem>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

// A command-line override `--set PATH=VALUE` of one value, e.g. thermal.dT=130 or
// analysis.step=5e-4. PATH is dotted; mapping keys by name, sequence items by index. A VALUE
// that starts with '[' or '{' is a YAML flow list or mapping (supports.1.fix=[x, y]).
struct Override {
  std::string path;
  std::string value;
};

// Parses "PATH=VALUE"; throws InputError when there is no '=' or PATH is empty.
Override parse_override(const std::string& text);
// Each of `texts` ("PATH=VALUE", as --set takes them) parsed, in order.
std::vector<Override> parse_overrides(const std::vector<std::string>& texts);

Model load_model(const std::filesystem::path& file, const std::vector<Override>& overrides = {});

// Same, from text; source_name is used in error messages in place of a file name.
Model load_model_from_string(const std::string& text, const std::string& source_name,
                             const std::vector<Override>& overrides = {});

}  // namespace deploydyn
