#pragma once
// Reads a study file (YAML, docs/model-format.md "Load-case studies") into a Study. Every case
// is checked by loading the model with its overrides, so that a bad study is an InputError
// naming the study file, line, column and field before any result is written.

#include <filesystem>
#include <string>

#include "deploydyn/study/study.hpp"

namespace deploydyn {

// Relative paths in the file (model, out) are relative to the file's folder. Without `out`,
// results go to results/<the study file's name without extension> in the current folder.
// `model_overrides` change the model for every case before the case's own overrides, as if
// the model file said so (`deploydyn study --set`); an error in one names its `--set`.
Study load_study(const std::filesystem::path& file, const std::vector<Override>& model_overrides = {});

// Same, from text: source_name names it in messages, and relative paths are taken from
// base_folder.
Study load_study_from_string(const std::string& text, const std::string& source_name,
                             const std::filesystem::path& base_folder,
                             const std::vector<Override>& model_overrides = {});

}  // namespace deploydyn
