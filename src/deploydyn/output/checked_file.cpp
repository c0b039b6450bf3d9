#include "deploydyn/output/checked_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "deploydyn/output/output_error.hpp"

namespace deploydyn {
namespace {

// Writes all of `text` at the file's offset, resuming after interrupted or short writes;
// returns 0 or the errno of the write that failed, and the bytes written in `written`.
int write_all(int fd, std::string_view text, std::size_t& written) {
  written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;
    written += static_cast<std::size_t>(n);
  }
  return 0;
}

int open_for_writing(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError("cannot write", file, errno);
  return fd;
}

void write_and_close(const std::filesystem::path& file, int fd, std::string_view text) {
  std::size_t written = 0;
  int error = write_all(fd, text, written);
  // close() reports a write-back error that the writes did not (e.g. on NFS).
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) throw OutputError("cannot write", file, error);
}

}  // namespace

void write_file(const std::filesystem::path& file, std::string_view text) {
  write_and_close(file, open_for_writing(file), text);
}

void write_file_atomically(const std::filesystem::path& file, std::string_view text) {
  const std::filesystem::path temporary = file.string() + ".tmp";
  try {
    write_file(temporary, text);
  } catch (const OutputError&) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  if (::rename(temporary.c_str(), file.c_str()) != 0) {
    const int error = errno;
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw OutputError("cannot write", file, error);
  }
}

AppendFile::AppendFile(const std::filesystem::path& file) : path_(file), fd_(open_for_writing(file)) {}

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendFile::append(std::string_view records) {
  std::size_t written = 0;
  const int error = write_all(fd_, records, written);
  if (error == 0) {
    size_ += written;
    return;
  }
  // Part of a record may be on disk: cut the file back to the last whole one, so that the
  // rows before the failure stay readable (ftruncate needs no new space).
  const std::size_t last_newline = records.substr(0, written).rfind('\n');
  const std::size_t whole = last_newline == std::string_view::npos ? 0 : last_newline + 1;
  if (whole < written && ::ftruncate(fd_, static_cast<off_t>(size_ + whole)) == 0) {
    ::lseek(fd_, static_cast<off_t>(size_ + whole), SEEK_SET);
  }
  size_ += whole;
  throw OutputError("cannot write", path_, error);
}

}  // namespace deploydyn
