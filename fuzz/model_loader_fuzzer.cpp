// libFuzzer target for the model loader and validator: any text must either load into a
// Model whose mechanics can be built, or be rejected with an InputError. Anything else — a
// crash, a sanitizer report, another exception — is a bug.
//
// Built by the `asan` CMake preset (clang, beside the sanitized tests); run by `make fuzz` with the examples and the bad
// models as seeds.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const deploydyn::Model model = deploydyn::load_model_from_string(text, "fuzz.yaml");
    const deploydyn::Assembler assembler(model);
  } catch (const deploydyn::InputError&) {
    // Rejected with a message: what bad input must get.
  } catch (const std::invalid_argument&) {
    // Mechanics that cannot be built (Assembler's documented error, reported as bad input).
  }
  return 0;
}
