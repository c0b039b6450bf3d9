#pragma once
// A model file read once: its text parsed into a YAML document, not yet checked. A study builds
// every case's model from one source, each with the case's overrides (applied to a copy of the
// document), instead of reading and parsing the file again per case.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/yaml_document.hpp"

namespace deploydyn {

class ModelSource {
 public:
  // Throws InputError when the file cannot be read or is not YAML.
  static ModelSource read(const std::filesystem::path& file);
  static ModelSource from_string(const std::string& text, const std::string& source_name);
  static ModelSource from_document(io::YamlDocument document, const std::string& source_name);

  // The checked model, with `overrides` applied; throws InputError as load_model does.
  // Safe to call from several threads at once.
  Model build(const std::vector<Override>& overrides = {}) const;
  // This source with `overrides` applied before build()'s own, as if the file said so (a
  // study's `--set` for every case); an error in one names it as `--set` does.
  ModelSource with_overrides(const std::vector<Override>& overrides) const;

  const std::string& name() const { return name_; }

 private:
  ModelSource(std::shared_ptr<const io::YamlDocument> document, std::string name)
      : document_(std::move(document)), name_(std::move(name)) {}

  std::shared_ptr<const io::YamlDocument> document_;
  std::string name_;
  std::vector<Override> base_overrides_;
};

}  // namespace deploydyn
