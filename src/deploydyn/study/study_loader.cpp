#include "deploydyn/study/study_loader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_keys.hpp"
#include "deploydyn/io/text_file.hpp"
#include "deploydyn/io/yaml_reader.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/study/sampling_loader.hpp"

namespace deploydyn {
namespace {

using io::YamlValue;

// A case's name is also its folder's name, next to study.csv.
void check_case_name(const std::string& name, const YamlValue& value) {
  if (const std::string problem = io::name_problem(name); !problem.empty()) {
    value.fail(fmt::format("case '{}': {}", name, problem));
  }
  if (name == "." || name == ".." || name.find_first_of("/\\") != std::string::npos) {
    value.fail(fmt::format("'{}' cannot name a folder; use letters, digits, '_', '-', '.'", name));
  }
  for (const char* reserved : {kStudyTableFileName, kStudyStatusFileName, kLockFileName}) {
    if (name == reserved) value.fail(fmt::format("'{}' is a file of the study's folder", name));
  }
}

struct CaseSpec {
  StudyCase study_case;
  YamlValue value;                 // the case's mapping, for messages
  std::vector<YamlValue> setters;  // one per override, same order
};

CaseSpec read_case(const std::string& name, const YamlValue& value) {
  check_case_name(name, value);
  if (!value.is_map()) {
    value.fail(
        "expected a mapping of overrides PATH: VALUE, e.g. {thermal.dT: 130}, or {} for "
        "the model as it is; got " +
        value.description());
  }
  CaseSpec spec{{name, {}, {}}, value, {}};
  for (const auto& [path, setting] : value.entries()) {
    if (setting.description() == "nothing") setting.fail("expected a value to set, got nothing");
    // A list or mapping is set as --set takes it, in YAML flow form.
    spec.study_case.overrides.push_back({path, setting.flow_text()});
    spec.setters.push_back(setting);
  }
  return spec;
}

// thermal.dT set to the number 0: the usual reference for shapes.
bool sets_zero_temperature_change(const StudyCase& c) {
  for (const Override& o : c.overrides) {
    if (o.path != "thermal.dT") continue;
    double value = 1.0;
    const auto [end, error] =
        std::from_chars(o.value.data(), o.value.data() + o.value.size(), value);
    if (error == std::errc() && end == o.value.data() + o.value.size() && value == 0.0) return true;
  }
  return false;
}

// The model file, read and parsed once for every case; an error in it names its own file,
// except that it is missing (named at the study's `model` line).
std::shared_ptr<const ModelSource> read_model_source(const std::filesystem::path& model_file,
                                                     const YamlValue& model_value,
                                                     const std::vector<Override>& model_overrides) {
  try {
    return std::make_shared<const ModelSource>(ModelSource::read(model_file).with_overrides(model_overrides));
  } catch (const InputError& e) {
    if (e.source() == model_file.string() && e.line() == 0) {
      model_value.fail(fmt::format("{}: {}", model_file.string(), e.problem()));
    }
    throw;  // the model itself is wrong: its own file and line say where
  }
}

// Builds the model under every case's overrides; an error caused by an override is reported at
// that override's line in the study file.
void check_cases(const ModelSource& source, const std::vector<CaseSpec>& specs) {
  source.build();
  for (const CaseSpec& spec : specs) {
    const auto& overrides = spec.study_case.overrides;
    try {
      source.build(overrides);
    } catch (const InputError& e) {
      for (std::size_t i = 0; i < overrides.size(); ++i) {
        if (e.source() == fmt::format("--set {}={}", overrides[i].path, overrides[i].value)) {
          spec.setters[i].fail(e.problem());
        }
      }
      spec.value.fail(fmt::format("the model with this case's overrides: {}", e.what()));
    }
  }
}

Study read_study(const YamlValue& root, const std::string& source_name,
                 const std::filesystem::path& base_folder, const std::vector<Override>& model_overrides) {
  if (!root.is_map()) root.fail("expected a study: a mapping with model and cases");
  root.expect_keys(model_keys::kStudy);

  Study study;
  const YamlValue model_value = root.at("model");
  study.model_file = base_folder / model_value.text();
  if (const auto description = root.find("description")) description->text();
  study.out_folder = std::filesystem::path("results") / std::filesystem::path(source_name).stem();
  if (const auto out = root.find("out")) {
    study.out_folder = base_folder / out->text();
    study.out_named = true;
  }
  if (const auto jobs = root.find("jobs")) study.jobs = jobs->integer(0);

  if (const auto sampling = root.find("sampling")) {
    if (root.find("cases")) {
      root.at("cases").fail("a study either lists its cases or samples them: give cases or sampling, not both");
    }
    if (root.find("reference")) root.at("reference").fail("a sampled study's reference is its nominal case");
    study.sampling = read_sampling(*sampling);
    study.model_source = read_model_source(study.model_file, model_value, model_overrides);
    try {
      study.drawn = std::make_shared<const SampledCases>(*study.sampling, study.model_source->build());
    } catch (const std::invalid_argument& e) {
      sampling->fail(e.what());
    }
    study.cases.push_back({"nominal", {}, {}});
    // Every drawn case sets the same paths the same way: the first one stands for all.
    const StudyCase first = study.case_at(1);
    try {
      study.model_source->build(first.overrides);
    } catch (const InputError& e) {
      sampling->fail(fmt::format("the model with {}'s drawn values: {}", first.name, e.what()));
    }
    return study;
  }

  const YamlValue cases = root.at("cases");
  std::vector<CaseSpec> specs;
  for (const auto& [name, value] : cases.entries()) specs.push_back(read_case(name, value));
  if (specs.empty()) cases.fail("expected at least one case, e.g. hot: {thermal.dT: 130}");
  std::vector<std::string> names;
  for (const CaseSpec& spec : specs) {
    names.push_back(spec.study_case.name);
    study.cases.push_back(spec.study_case);
  }

  if (const auto reference = root.find("reference")) {
    const std::string name = reference->text();
    const auto match = std::find(names.begin(), names.end(), name);
    if (match == names.end()) {
      reference->fail(fmt::format("must name a case ({}), got '{}'{}", io::join_names(names), name,
                                  io::did_you_mean(name, names)));
    }
    study.reference = static_cast<std::size_t>(match - names.begin());
  } else {
    const auto zero =
        std::find_if(study.cases.begin(), study.cases.end(), sets_zero_temperature_change);
    study.reference =
        zero == study.cases.end() ? 0 : static_cast<std::size_t>(zero - study.cases.begin());
  }

  study.model_source = read_model_source(study.model_file, model_value, model_overrides);
  check_cases(*study.model_source, specs);
  return study;
}

}  // namespace

Study load_study_from_string(const std::string& text, const std::string& source_name,
                             const std::filesystem::path& base_folder,
                             const std::vector<Override>& model_overrides) {
  const io::YamlSource source(source_name);
  io::YamlDocument document;
  try {
    document = io::YamlDocument::parse(text);
  } catch (const io::YamlSyntaxError& error) {
    io::throw_input_error(source_name, error.mark, "", "YAML syntax: " + error.message);
  }
  return read_study(YamlValue(document, document.root(), source), source_name, base_folder, model_overrides);
}

Study load_study(const std::filesystem::path& file, const std::vector<Override>& model_overrides) {
  return load_study_from_string(io::read_input_file(file), file.string(), file.parent_path(), model_overrides);
}

}  // namespace deploydyn
