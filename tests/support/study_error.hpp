#pragma once
// A study file (text, as s.yaml in examples/paper/) that must be refused: the InputError names
// s.yaml, the line, the dotted field, and says `problem`.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/study/study_loader.hpp"

namespace deploydyn::testing {

inline void expect_study_error(const std::string& text, int line, const std::string& field,
                               const std::string& problem) {
  try {
    load_study_from_string(text, "s.yaml", std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "s.yaml") << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(e.problem().find(problem), std::string::npos) << e.what();
  }
}

}  // namespace deploydyn::testing
