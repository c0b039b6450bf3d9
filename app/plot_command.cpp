#include "plot_command.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "exit_codes.hpp"

namespace deploydyn::cli {
namespace {

// The Python with numpy and matplotlib (python3-numpy, python3-matplotlib): Debian's, not the
// first python3 on PATH, which may be another one.
constexpr const char* kPython = "/usr/bin/python3";

CLI::App* add_script_command(CLI::App& app, const char* name, const char* description) {
  CLI::App* command = app.add_subcommand(name, description);
  command->prefix_command();   // every word after the command is the script's
  command->set_help_flag();    // --help too: the script's own
  return command;
}

// Where the scripts are, in the order tried; the first that holds `script` is used.
std::vector<std::filesystem::path> script_folders() {
  std::vector<std::filesystem::path> folders;
  if (const char* given = std::getenv("DEPLOYDYN_SCRIPTS_DIR"); given != nullptr && *given != '\0') {
    folders.emplace_back(given);
    return folders;
  }
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) folders.push_back(self.parent_path().parent_path() / "share" / "deploydyn" / "scripts");
  folders.emplace_back(DEPLOYDYN_SOURCE_SCRIPTS_DIR);  // a binary of the build tree
  return folders;
}

}  // namespace

CLI::App* add_plot_command(CLI::App& app) {
  return add_script_command(app, "plot",
                            "Plot result folders (runs, studies' cases, modes, continuation paths): "
                            "deploydyn plot FOLDER... [--out DIR] [--what ...]; `deploydyn plot --help` for all options");
}

CLI::App* add_animate_command(CLI::App& app) {
  return add_script_command(app, "animate",
                            "Animate a run's deployment as MP4 or GIF: deploydyn animate FOLDER [--out FILE]; "
                            "`deploydyn animate --help` for all options");
}

int run_plot_script(const std::string& script, const std::vector<std::string>& arguments) {
  std::filesystem::path found;
  const std::vector<std::filesystem::path> folders = script_folders();
  for (const std::filesystem::path& folder : folders) {
    if (std::filesystem::is_regular_file(folder / script)) {
      found = folder / script;
      break;
    }
  }
  if (found.empty()) {
    std::string tried;
    for (const std::filesystem::path& folder : folders) tried += (tried.empty() ? "" : ", ") + folder.string();
    fmt::print(stderr, "error: {} not found in {}; install deploydyn (cmake --install) or set DEPLOYDYN_SCRIPTS_DIR "
                       "to the scripts/ folder of its source\n", script, tried);
    return kExitBadInput;
  }
  std::vector<std::string> words{kPython, found.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  execv(kPython, argv.data());
  fmt::print(stderr, "error: cannot start {} for {}: {} (install python3-matplotlib and python3-numpy)\n", kPython,
             script, std::strerror(errno));
  return kExitBadInput;
}

}  // namespace deploydyn::cli
