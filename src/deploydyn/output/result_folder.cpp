#include "deploydyn/output/result_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
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

std::string host_name() {
  char name[256] = {};
  return ::gethostname(name, sizeof name - 1) == 0 ? name : "";
}

}  // namespace

ResultFolder::ResultFolder(std::filesystem::path folder, std::string status_file_name)
    : folder_(std::move(folder)), status_file_name_(std::move(status_file_name)) {
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error) throw OutputError("cannot create folder", folder_, error.value());
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
  try {
    write_file_atomically(status_file(), std::string(final_status) + '\n');
  } catch (const OutputError&) {
    // Overwriting bytes the file already has needs no new space.
    const int fd = ::open(status_file().c_str(), O_WRONLY | O_CLOEXEC);
    struct stat info {};
    if (fd >= 0 && ::fstat(fd, &info) == 0 && short_status.size() < static_cast<std::size_t>(info.st_size)) {
      std::string text(short_status);
      text.resize(static_cast<std::size_t>(info.st_size) - 1, ' ');
      text += '\n';
      [[maybe_unused]] const ssize_t ignored = ::pwrite(fd, text.data(), text.size(), 0);
    }
    if (fd >= 0) ::close(fd);
    throw;
  }
}

}  // namespace deploydyn
