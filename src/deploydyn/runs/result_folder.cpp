#include "deploydyn/runs/result_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>
#include <thread>

#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/output_error.hpp"

namespace deploydyn {
namespace {

// A reader that asks whether a run is alive holds the lock for an instant: try a little while
// before calling the folder taken.
constexpr int kLockAttempts = 20;
constexpr auto kLockRetryInterval = std::chrono::milliseconds(25);

nlohmann::json read_status(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return nullptr;
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
}

// "pid 4711 on host node3, started 2026-11-23T10:15:00Z", from a running status file.
std::string describe_owner(const std::filesystem::path& status_file) {
  const nlohmann::json status = read_status(status_file);
  if (!status.is_object() || !status.contains("pid")) return "";
  std::string text = " (pid " + status["pid"].dump();
  if (status.contains("host") && status["host"].is_string()) text += " on " + status["host"].get<std::string>();
  if (status.contains("started") && status["started"].is_string()) {
    text += ", started " + status["started"].get<std::string>();
  }
  return text + ")";
}

// A name the previous status file lists, if it is a plain entry of the folder (never a path
// that leads out of it).
bool is_plain_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}

// A moment as UTC ISO 8601, e.g. "2026-11-23T10:15:00Z".
std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// `status` (a JSON object) with its "files" cut to those in `folder`: a run that stopped early
// never wrote some (envelopes.csv after a failed write), and the status must not claim them.
// `indent` as nlohmann::json::dump.
std::string with_existing_files(const std::filesystem::path& folder, nlohmann::ordered_json status, int indent) {
  if (status.contains("files") && status["files"].is_object()) {
    nlohmann::ordered_json existing = nlohmann::ordered_json::object();
    for (const auto& [role, file] : status["files"].items()) {
      std::error_code error;
      if (file.is_string() && std::filesystem::exists(folder / file.get<std::string>(), error)) existing[role] = file;
    }
    status["files"] = std::move(existing);
  }
  return status.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

// The same for a status as text; text that is not a JSON object is kept as it is.
std::string with_existing_files(const std::filesystem::path& folder, std::string_view status, int indent) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(status, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return std::string(status);
  return with_existing_files(folder, std::move(j), indent);
}

// create_directories says only "File exists" when the folder, or a folder above it, is a
// symbolic link to nothing: name that link instead. Empty when there is none.
std::string dangling_link(const std::filesystem::path& folder) {
  for (std::filesystem::path p = folder; !p.empty(); p = p.parent_path()) {
    std::error_code error;
    if (std::filesystem::is_symlink(p, error) && !std::filesystem::exists(p, error)) {
      const std::string link = "a dangling symbolic link (to " + std::filesystem::read_symlink(p, error).string() + ")";
      return p == folder ? "it is " + link : p.string() + " is " + link;
    }
    if (p == p.parent_path()) break;
  }
  return "";
}

}  // namespace

std::string host_name() {
  char name[256] = {};
  return ::gethostname(name, sizeof name - 1) == 0 ? name : "";
}


bool folder_in_use(const std::filesystem::path& folder) {
  const int fd = ::open((folder / kLockFileName).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;  // no lock file: no run ever owned it
  // Taken and dropped at once: a run starting into the folder retries its lock meanwhile.
  const bool owned = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return owned;
}

ResultFolder::ResultFolder(std::filesystem::path folder, std::string status_file_name)
    : folder_(std::move(folder)), status_file_name_(std::move(status_file_name)) {
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error) throw OutputError("cannot create folder", folder_, error.value(), dangling_link(folder_));
  const std::filesystem::path lock_file = folder_ / kLockFileName;
  lock_fd_ = ::open(lock_file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) throw OutputError("cannot write", lock_file, errno);
  for (int attempt = 1;; ++attempt) {
    if (::flock(lock_fd_, LOCK_EX | LOCK_NB) == 0) return;
    const int reason = errno;
    if (reason == EWOULDBLOCK && attempt < kLockAttempts) {
      std::this_thread::sleep_for(kLockRetryInterval);
      continue;
    }
    ::close(lock_fd_);
    if (reason != EWOULDBLOCK) throw OutputError("cannot lock", lock_file, reason);
    throw OutputError("cannot write to", folder_, 0,
                      "the folder is in use by another deploydyn run" + describe_owner(status_file()) +
                          "; choose another result folder or wait until that run ends");
  }
}

ResultFolder::~ResultFolder() {
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the lock
}

void ResultFolder::start(const std::string& name_key, const std::string& name, const Files& files,
                         const std::vector<std::string>& also_stale) {
  std::vector<std::string> stale = also_stale;
  for (const auto& [role, file] : files) stale.push_back(file);
  const nlohmann::json previous = read_status(status_file());
  if (previous.is_object() && previous.contains("files") && previous["files"].is_object()) {
    for (const auto& [role, file] : previous["files"].items()) {
      if (file.is_string()) stale.push_back(file.get<std::string>());
    }
  }
  nlohmann::ordered_json running;
  running[name_key] = name;
  running["status"] = "running";
  running["message"] = std::string("running; if no process holds ") + kLockFileName +
                       ", the run was killed";
  running["pid"] = static_cast<long>(::getpid());
  running["host"] = host_name();
  running["started"] = utc_now();
  running["files"] = nlohmann::ordered_json::object();
  for (const auto& [role, file] : files) running["files"][role] = file;
  std::string text = running.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  text.resize(std::max(text.size() + 1, kReservedStatusBytes - 1), ' ');
  text += '\n';
  write_file_atomically(status_file(), text);
  for (const std::string& name : stale) {
    if (!is_plain_name(name) || name == status_file_name_ || name == kLockFileName) continue;
    // A folder may hold the user's own files too: its writer removes what it wrote.
    if (std::filesystem::is_directory(folder_ / name)) continue;
    std::error_code error;
    std::filesystem::remove(folder_ / name, error);
    if (error) throw OutputError("cannot remove the earlier run's", folder_ / name, error.value());
  }
}

void ResultFolder::finish(std::string_view final_status, std::string_view short_status) {
  finish_with([&] { return with_existing_files(folder_, final_status, 2); },
              [&] { return with_existing_files(folder_, short_status, -1); });
}

void ResultFolder::finish_json(nlohmann::ordered_json final_status, nlohmann::ordered_json short_status) {
  finish_with([&] { return with_existing_files(folder_, std::move(final_status), 2); },
              [&] { return with_existing_files(folder_, std::move(short_status), -1); });
}

void ResultFolder::finish_json(nlohmann::ordered_json final_status, const std::string& short_status) {
  finish_with([&] { return with_existing_files(folder_, std::move(final_status), 2); },
              [&] { return with_existing_files(folder_, std::string_view(short_status), -1); });
}

void ResultFolder::finish_with(const std::function<std::string()>& final_text,
                               const std::function<std::string()>& short_text) {
  try {
    write_file_atomically(status_file(), final_text() + '\n');
    return;
  } catch (const OutputError& error) {
    if (write_short_status(short_text())) throw;
    throw OutputError("cannot write", status_file(), 0,
                      std::string(std::strerror(error.error_number())) +
                          ", not even a short status: the folder has no final status (a running one is stale)");
  }
}

bool ResultFolder::write_short_status(const std::string& text) {
  // Overwriting bytes the file already has needs no new space (a full disk).
  const int fd = ::open(status_file().c_str(), O_WRONLY | O_CLOEXEC);
  struct stat info {};
  bool written = false;
  if (fd >= 0 && ::fstat(fd, &info) == 0 && text.size() < static_cast<std::size_t>(info.st_size)) {
    std::string padded = text;
    padded.resize(static_cast<std::size_t>(info.st_size) - 1, ' ');
    padded += '\n';
    written = ::pwrite(fd, padded.data(), padded.size(), 0) == static_cast<ssize_t>(padded.size());
  }
  if (fd >= 0) ::close(fd);
  if (written) return true;
  try {
    // No running status to overwrite (it did not fit a file-size limit): a small new file may.
    write_file_atomically(status_file(), text + '\n');
    return true;
  } catch (const OutputError&) {
    return false;
  }
}

}  // namespace deploydyn
