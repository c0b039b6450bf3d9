#pragma once
// A result folder owned by one run (or one study) at a time, so that it never claims what its
// files do not show (docs/model-format.md, "Result folders"):
//   - the owner holds an exclusive flock(2) on FOLDER/.deploydyn.lock for its whole life; a
//     second run into the folder is refused, and since the kernel drops the lock when a process
//     dies, a reader can tell a live run ("running") from a killed one (status "running", lock
//     free);
//   - start() first replaces the status file (summary.json, study.json) atomically by one that
//     says "running", then removes the previous run's outputs: at no moment does an old
//     "completed" stand beside new, partial results;
//   - finish() replaces it with the final status. When even that cannot be written (a full
//     disk), a short status is written in place over room that start() reserved, or else
//     (no running status: it did not fit a file-size limit) as a new small file.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#include "deploydyn/results/result_file_names.hpp"

namespace deploydyn {

// Room the running status reserves on disk (it is padded with spaces to this size): the most a
// short final status may take when the disk is full.
inline constexpr std::size_t kReservedStatusBytes = 4096;

// Whether a live process owns `folder` (holds its lock): a run still writing it. A status file
// that says "running" in a folder nobody owns is a killed run's.
bool folder_in_use(const std::filesystem::path& folder);

// This machine's name, as a folder's status records who runs in it; empty if it cannot be told.
std::string host_name();

class ResultFolder {
 public:
  // Creates `folder` if needed and takes its lock. Throws OutputError when the folder cannot
  // be made or another process owns it (the message says which, from its status file).
  ResultFolder(std::filesystem::path folder, std::string status_file_name);
  ~ResultFolder();  // releases the lock
  ResultFolder(const ResultFolder&) = delete;
  ResultFolder& operator=(const ResultFolder&) = delete;

  const std::filesystem::path& path() const { return folder_; }
  std::filesystem::path status_file() const { return folder_ / status_file_name_; }

  // Writes the status file as {name_key: name, "status": "running", "pid", "host", "started",
  // "files": {role: file name}}, then removes what a previous run left: `files`, the files
  // that the previous status file listed, and `also_stale` (outputs this run does not write).
  // Folders among them are left to their writers (output/vtk_writer.hpp).
  using Files = std::vector<std::pair<std::string, std::string>>;
  void start(const std::string& name_key, const std::string& name, const Files& files,
             const std::vector<std::string>& also_stale = {});
  // Replaces the status file by `final_status`. If that fails, writes `short_status` (a JSON
  // object of at most kReservedStatusBytes) in place of the running status or else as a new
  // small file, and rethrows; if even that fails, throws an OutputError that says the folder has
  // no final status. Either status lists under "files" only the files that exist.
  void finish(std::string_view final_status, std::string_view short_status);
  // The same for a status made as JSON, which is then not parsed again: a study's lists 10⁵
  // cases, and an ordered_json object of n keys is parsed in n² key comparisons.
  void finish_json(nlohmann::ordered_json final_status, nlohmann::ordered_json short_status);
  // The final status as JSON, the short one as text (parsed only if it is needed).
  void finish_json(nlohmann::ordered_json final_status, const std::string& short_status);

 private:
  // finish() with the status texts made when they are needed.
  void finish_with(const std::function<std::string()>& final_text, const std::function<std::string()>& short_text);
  bool write_short_status(const std::string& text);  // false: not written

  std::filesystem::path folder_;
  std::string status_file_name_;
  int lock_fd_ = -1;
};

}  // namespace deploydyn
