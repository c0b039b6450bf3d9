#pragma once
// `deploydyn generate roof --units N [--trusses M] [--delta-t C] [--bearings B] [--out FILE]`
// and `deploydyn generate scissor --form F --units N [--span S] ... [--out FILE]`: write a
// generated model file (generators/roof.hpp, generators/scissor.hpp) to FILE, or to stdout.

#include <CLI/CLI.hpp>
#include <string>

#include "deploydyn/generators/roof.hpp"
#include "deploydyn/generators/scissor.hpp"

namespace deploydyn::cli {

struct GenerateArguments {
  RoofOptions roof;
  ScissorOptions scissor;
  std::string out_file;  // empty: stdout
  // Set by add_generate_command (owned by the CLI::App): tell which structure was named.
  const CLI::App* generate = nullptr;
  const CLI::App* roof_command = nullptr;
  const CLI::App* scissor_command = nullptr;
};

// Adds `generate` (with its `roof` subcommand) to `app`; parsed values land in `arguments`.
CLI::App* add_generate_command(CLI::App& app, GenerateArguments& arguments);

// Exit code: 0 written, 2 bad arguments or an output file that cannot be written.
int generate_command(const GenerateArguments& arguments);

}  // namespace deploydyn::cli
