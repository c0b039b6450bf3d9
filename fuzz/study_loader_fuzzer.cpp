// libFuzzer target for study files, listed and sampled (study/study_loader.hpp): any text must
// either load into a Study whose cases can be drawn and built, or be rejected with an
// InputError. Anything else — a crash, a sanitizer report, another exception, a hang or memory
// that grows with `sampling.cases` — is a bug.
//
// The study's model is read from examples/paper (the fuzzed text names general.yaml or
// parallel.yaml there); nothing is written. Built by the `asan` CMake preset (clang); run by
// `make fuzz` with the examples' study files and fuzz/seeds/study as seeds.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/study/study_loader.hpp"

namespace {

const std::filesystem::path kModelFolder = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper";

// A few cases, as the runner would take them: the first, the second and the last.
void draw_some_cases(const deploydyn::Study& study) {
  const std::size_t n = study.n_cases();
  for (const std::size_t i : {std::size_t{0}, std::size_t{1}, n - 1}) {
    if (i >= n) continue;
    try {
      study.case_model(i);
    } catch (const deploydyn::InputError&) {
      // A listed case is checked at load, a drawn case like the first: a bad one fails alone.
    } catch (const std::invalid_argument&) {
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const deploydyn::Study study = deploydyn::load_study_from_string(text, "fuzz_study.yaml", kModelFolder);
    draw_some_cases(study);
  } catch (const deploydyn::InputError&) {
    // Rejected with a message: what bad input must get.
  }
  return 0;
}
