// Every bad model file in tests/io/bad_models/ must give an InputError that says where (file and
// line), which field and what is wrong; nothing else may escape the loader.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"

namespace deploydyn {
namespace {

struct BadModelCase {
  const char* file;     // in tests/io/bad_models/
  int line;             // 1-based; 0 when the error has no line (e.g. the file is missing)
  const char* field;    // dotted path; "" when the error is about the whole file
  const char* problem;  // a part of the message
};

// Printed by GoogleTest to name the failing case.
std::ostream& operator<<(std::ostream& out, const BadModelCase& bad) { return out << bad.file; }

const BadModelCase kBadModels[] = {
    {"unknown_key_suggestion.yaml", 7, "elements.1.aera",
     "unknown key 'aera'; did you mean 'area'?"},
    {"unknown_top_level_key.yaml", 4, "solver_settings",
     "unknown key 'solver_settings'; allowed: name,"},
    {"missing_area.yaml", 4, "elements.1.area", "required key is missing"},
    {"missing_nodes_section.yaml", 1, "nodes", "required key is missing"},
    {"area_not_a_number.yaml", 6, "elements.1.area", "expected a number (m²), got 'large'"},
    {"element_nodes_mapping.yaml", 5, "elements.1.nodes",
     "expected a list of 2 node names, got a mapping"},
    {"negative_area.yaml", 4, "elements.1.area", "must be positive (m²), got -1"},
    {"zero_youngs_modulus.yaml", 3, "materials.steel.E", "must be positive (Pa), got 0"},
    {"negative_point_mass.yaml", 3, "nodes.B.mass", "must not be negative (kg), got -0.5"},
    {"negative_element_mass.yaml", 4, "elements.1.mass", "must be positive (kg), got -2"},
    {"missing_mass_and_density.yaml", 4, "elements.1.mass", "give 'mass' (kg) here or a 'density'"},
    {"duplicate_node.yaml", 4, "nodes.A", "'A' is given twice"},
    {"unknown_node.yaml", 4, "elements.1.nodes.1", "unknown node 'Q'; nodes are A, B"},
    {"zero_length_bar.yaml", 4, "elements.1.nodes", "zero-length bar"},
    {"nan_coordinate.yaml", 3, "nodes.B.0", "must be a finite number, got .nan"},
    {"infinite_modulus.yaml", 3, "materials.steel.E", "must be a finite number, got .inf"},
    {"mixed_dimensions.yaml", 3, "nodes.B", "has 3 coordinates but node 'A' has 2"},
    {"driver_unknown_element.yaml", 7, "drivers.motor.element",
     "unknown element '7'; elements are 1"},
    {"pivot_not_on_element.yaml", 8, "drivers.motor.pivot", "node 'C' is not on element '1'"},
    {"reading_does_not_fit.yaml", 9, "drivers.motor.reading",
     "must be one of angular_velocity, angle, got 'velocity'"},
    {"axis_in_2d.yaml", 8, "drivers.motor.axis", "only allowed in 3D models"},
    {"fix_z_in_2d.yaml", 5, "supports.0.fix.1", "'z' is only allowed in 3D models"},
    {"supports_not_a_list.yaml", 5, "supports", "expected a list of supports"},
    {"step_zero.yaml", 6, "analysis.step", "must be positive (s), got 0"},
    {"step_exceeds_end.yaml", 6, "analysis.step", "must not exceed end = 1 s, got 2"},
    {"output_interval_not_multiple.yaml", 7, "analysis.output_interval",
     "must be a whole multiple of step = 0.001 s, got 0.0015 (1.5 steps)"},
    {"load_steps_not_integer.yaml", 5, "analysis.load_steps", "expected an integer, got 2.5"},
    {"beta_out_of_range.yaml", 5, "analysis.integrator.beta", "must be in (0, 0.5], got 0.7"},
    {"bad_function_type.yaml", 8, "drivers.motor.profile.type",
     "must be one of constant, smooth_step, smooth_trapezoid, paper_eq23, table, got 'sine'"},
    {"table_times_not_increasing.yaml", 10, "thermal.dT.points.2",
     "times must increase strictly, got 1 after 2"},
    {"unknown_function_name.yaml", 7, "thermal.dT", "unknown function 'wram'"},
    {"yaml_syntax_error.yaml", 4, "", "YAML syntax"},
    {"units_not_si.yaml", 1, "units", "only SI is supported"},
    {"output_file_with_folder.yaml", 5, "output.history", "must be a plain file name"},
    {"empty.yaml", 0, "", "expected a mapping with nodes, materials and elements, got nothing"},
    {"does_not_exist.yaml", 0, "", "cannot open file"},
};

class BadModel : public testing::TestWithParam<BadModelCase> {};

TEST_P(BadModel, ThrowsInputErrorNamingFileLineFieldAndProblem) {
  const BadModelCase& bad = GetParam();
  const std::string path = fmt::format("{}/tests/io/bad_models/{}", DEPLOYDYN_SOURCE_DIR, bad.file);
  try {
    load_model(path);
    FAIL() << bad.file << " loaded without error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    const std::string where =
        bad.line > 0 ? fmt::format("{}:{}:", bad.file, bad.line) : fmt::format("{}: ", bad.file);
    EXPECT_NE(message.find(where), std::string::npos) << message;
    EXPECT_EQ(error.line(), bad.line) << message;
    EXPECT_EQ(error.field(), bad.field) << message;
    EXPECT_NE(message.find(bad.problem), std::string::npos) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(Files, BadModel, testing::ValuesIn(kBadModels),
                         [](const testing::TestParamInfo<BadModelCase>& info) {
                           std::string name = info.param.file;
                           name = name.substr(0, name.find('.'));
                           return name;
                         });

// The table covers every file on disk, so that a new file cannot be left untested.
TEST(BadModel, TableListsEveryFile) {
  std::size_t n_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(
           fmt::format("{}/tests/io/bad_models", DEPLOYDYN_SOURCE_DIR))) {
    const std::string name = entry.path().filename().string();
    const auto listed = std::find_if(std::begin(kBadModels), std::end(kBadModels),
                                     [&](const BadModelCase& bad) { return name == bad.file; });
    EXPECT_NE(listed, std::end(kBadModels)) << name << " is not in the table";
    ++n_files;
  }
  EXPECT_EQ(n_files + 1, std::size(kBadModels));  // + the file that does not exist
}

}  // namespace
}  // namespace deploydyn
