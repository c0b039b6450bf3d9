// Where the tests find the sources and the command-line program.
//
// The paths are compiled into build_paths.cpp alone, so that every other test object is the
// same in every checkout and build folder and the compiler cache can share it (a path given as
// a compile definition to every file would make each worktree rebuild them all). The build
// includes this header in every test file.
#pragma once

namespace deploydyn::testing {

const char* source_dir();  // the repository's root, without a trailing '/'
const char* cli_path();    // the deploydyn program under test

}  // namespace deploydyn::testing

#define DEPLOYDYN_SOURCE_DIR (::deploydyn::testing::source_dir())
#define DEPLOYDYN_CLI (::deploydyn::testing::cli_path())
