#pragma once
// Files whose every write is checked: a failure throws OutputError with the operating system's
// reason (output/output_error.hpp) and never leaves half a record behind.
//   - write_file / write_file_atomically: a whole small file (summary.json, a VTK frame).
//     The atomic one writes FILE.tmp and renames it over FILE, so a reader sees the old or the
//     new text, never part of one; on failure the temporary file is removed.
//   - AppendFile: a growing file (history.csv) written in whole records. A write that fails
//     part-way (disk full, file-size limit) is cut back to the last whole record before
//     OutputError is thrown, so what is on disk stays row-complete. Records are lines.

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace deploydyn {

void write_file(const std::filesystem::path& file, std::string_view text);
void write_file_atomically(const std::filesystem::path& file, std::string_view text);

class AppendFile {
 public:
  // Creates or empties `file`. Throws OutputError when it cannot.
  explicit AppendFile(const std::filesystem::path& file);
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  // Appends `records`: whole lines, each ending in '\n' (one write(2) call where the kernel
  // allows: a signal between two appends never splits a line).
  void append(std::string_view records);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::size_t size_ = 0;  // bytes of whole records on disk
};

}  // namespace deploydyn
