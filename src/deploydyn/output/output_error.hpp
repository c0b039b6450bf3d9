#pragma once
// Results that cannot be written: a full disk, a file-size limit, a folder without permission,
// a result folder that another run owns. what() names the file and gives the operating
// system's reason, e.g.
//   cannot write results/hot/history.csv: No space left on device
// The CLI exits with code 3 for it (solver failures exit 1, bad input 2); the Python module
// raises deploydyn.OutputError, an OSError.

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace deploydyn {

class OutputError : public std::runtime_error {
 public:
  // `action` says what failed ("cannot write", "cannot create folder"); `error_number` is the
  // errno value (0 when there is none, e.g. a folder in use: then `reason` says why).
  OutputError(const std::string& action, const std::filesystem::path& file, int error_number,
              const std::string& reason = {})
      : std::runtime_error(action + " " + file.string() + ": " +
                           (reason.empty() ? std::strerror(error_number) : reason)),
        file_(file),
        error_number_(error_number) {}

  const std::filesystem::path& file() const { return file_; }
  int error_number() const { return error_number_; }

 private:
  std::filesystem::path file_;
  int error_number_;
};

}  // namespace deploydyn
