#pragma once
// Runs the `deploydyn` command as a user would, for the command-line tests.

#include <fcntl.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace deploydyn::testing {

// The CLI under test is built with AddressSanitizer (the asan preset, `make sanitize`). Its
// shadow memory needs far more address space than a `prlimit --as` leaves, its allocator aborts
// where the library would throw std::bad_alloc, and LeakSanitizer reports OpenMPI's own
// allocations at exit: tests of those faults run in the release build only.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kCliUnderAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kCliUnderAddressSanitizer = true;
#else
inline constexpr bool kCliUnderAddressSanitizer = false;
#endif
#else
inline constexpr bool kCliUnderAddressSanitizer = false;
#endif

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

// A fresh, empty folder under the system's temporary folder, removed again on destruction. Its
// name carries the process id: two suites run at once (two build trees, two worktrees) would
// otherwise share it, and a run's result folder lock then fails the other's command.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("deploydyn_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
  }
  ~ScratchFolder() { std::filesystem::remove_all(path_); }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// `deploydyn` with `arguments`, started in the background, its output discarded.
inline pid_t start_cli(const std::vector<std::string>& arguments) {
  std::vector<std::string> words{DEPLOYDYN_CLI};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int error = posix_spawn(&pid, DEPLOYDYN_CLI, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  // Never a pid of -1: kill(-1, ...) would signal every process of the user.
  if (error != 0) throw std::runtime_error(std::string("cannot start ") + DEPLOYDYN_CLI);
  return pid;
}

// What a reader of the folder should conclude: the status in `status_file` (summary.json,
// window.json), or "killed" when it says "running" and no process holds the folder's lock.
inline std::string folder_status(const std::filesystem::path& folder,
                                 const std::string& status_file = "summary.json") {
  const nlohmann::json summary = nlohmann::json::parse(read_text(folder / status_file));
  const std::string status = summary["status"];
  if (status != "running") return status;
  const int fd = open((folder / ".deploydyn.lock").c_str(), O_RDWR);
  const bool owned = fd >= 0 && flock(fd, LOCK_EX | LOCK_NB) != 0;
  if (fd >= 0) close(fd);  // drops a lock this probe took
  return owned ? "running" : "killed";
}

}  // namespace deploydyn::testing
