#pragma once
// Runs the `deploydyn` command as a user would, for the command-line tests.

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace deploydyn::testing {

struct CliOutcome {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs `<prefix> deploydyn <arguments>` through the shell (so arguments may hold
// redirections); `prefix` is a command that runs deploydyn, such as prlimit, or empty.
inline CliOutcome run_cli_with_prefix(const std::string& prefix, const std::string& arguments) {
  const std::string command = prefix + " " + std::string(DEPLOYDYN_CLI) + " " + arguments + " 2>&1";
  CliOutcome outcome;
  std::FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) outcome.output += buffer.data();
  const int status = pclose(pipe);
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

inline CliOutcome run_cli(const std::string& arguments) { return run_cli_with_prefix("", arguments); }

inline std::string example_path(const std::string& name) {
  return std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/" + name;
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A fresh, empty folder under the system's temporary folder, removed again on destruction.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("deploydyn_" + name)) {
    std::filesystem::remove_all(path_);
  }
  ~ScratchFolder() { std::filesystem::remove_all(path_); }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace deploydyn::testing
