#include "support/build_paths.hpp"

namespace deploydyn::testing {

const char* source_dir() { return DEPLOYDYN_SOURCE_DIR_PATH; }
const char* cli_path() { return DEPLOYDYN_CLI_PATH; }

}  // namespace deploydyn::testing
