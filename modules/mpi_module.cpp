// The MPI module, deploydyn_mpi.so: the study's processes over Open MPI, for `mpirun -n N
// deploydyn study FILE` (app/mpi_channel.cpp loads it only when mpirun started the process;
// docs/performance.md, "A light start").

#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <type_traits>
#include <string>
#include <vector>

#include <mpi.h>
#include <nlohmann/json.hpp>

#include "../app/exit_codes.hpp"
#include "../app/mpi_channel.hpp"

namespace deploydyn::cli {
namespace {

class MpiChannel final : public StudyProcesses {
 public:
  MpiChannel() {
    // Only the main thread calls MPI; process 0 runs its own cases on other threads.
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    // Who every process is, for process 0 to watch from the start (StudyChannel::identity).
    long pid = static_cast<long>(::getpid());
    std::array<char, kHostLength> host{};
    ::gethostname(host.data(), host.size() - 1);
    pids_.resize(static_cast<std::size_t>(rank_ == 0 ? size_ : 0));
    hosts_.resize(static_cast<std::size_t>(rank_ == 0 ? size_ * kHostLength : 0));
    MPI_Gather(&pid, 1, MPI_LONG, pids_.data(), 1, MPI_LONG, 0, MPI_COMM_WORLD);
    MPI_Gather(host.data(), kHostLength, MPI_CHAR, hosts_.data(), kHostLength, MPI_CHAR, 0, MPI_COMM_WORLD);
  }
  ~MpiChannel() override {
    // Leaving by an exception (bad input, a folder in use) the other processes may be waiting
    // for this one: end them all rather than wait in MPI_Finalize.
    if (std::uncaught_exceptions() > 0) MPI_Abort(MPI_COMM_WORLD, kExitBadInput);
    // MPI_Finalize waits for every process, a dead one too (mpirun --enable-recovery): with
    // every result written, process 0 ends the survivors instead.
    if (!lost_.empty()) {
      std::string ranks;
      for (const int rank : lost_) ranks += (ranks.empty() ? "" : ", ") + std::to_string(rank);
      std::fprintf(stderr, "process %s died; its case is listed as failed and every other result is "
                           "written; ending the other processes (MPI_Abort)\n", ranks.c_str());
      std::fflush(nullptr);
      MPI_Abort(MPI_COMM_WORLD, kExitSolverFailure);
    }
    MPI_Finalize();
  }
  MpiChannel(const MpiChannel&) = delete;
  MpiChannel& operator=(const MpiChannel&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  std::optional<WorkerReport> poll_report() override {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kReportTag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return std::nullopt;
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    std::string text(static_cast<std::size_t>(length), '\0');
    MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, kReportTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    const auto j = nlohmann::json::parse(text);
    WorkerReport report;
    report.rank = status.MPI_SOURCE;
    report.finished_case = j.at("case").get<long>();
    report.status = static_cast<RunStatus>(j.at("status").get<int>());
    report.ran = j.at("ran").get<bool>();
    report.message = j.at("message").get<std::string>();
    report.pid = j.at("pid").get<long>();
    report.host = j.at("host").get<std::string>();
    return report;
  }

  void assign(int rank, long case_index) override {
    MPI_Send(&case_index, 1, MPI_LONG, rank, kAssignTag, MPI_COMM_WORLD);
  }

  void lost(int rank) override { lost_.push_back(rank); }

  int agree_on_exit(int exit_code, bool& first_rank_failed) override {
    int worst = 0, first = exit_code;
    MPI_Allreduce(&exit_code, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    MPI_Bcast(&first, 1, MPI_INT, 0, MPI_COMM_WORLD);
    first_rank_failed = first != 0;
    return worst;
  }

  [[noreturn]] void end_all(int exit_code) override {
    std::fflush(nullptr);
    MPI_Abort(MPI_COMM_WORLD, exit_code);
    std::_Exit(exit_code);  // MPI_Abort does not return; the compiler cannot know
  }

  std::optional<std::pair<long, std::string>> identity(int rank) const override {
    if (rank < 0 || static_cast<std::size_t>(rank) >= pids_.size()) return std::nullopt;
    return std::make_pair(pids_[static_cast<std::size_t>(rank)],
                          std::string(hosts_.data() + static_cast<std::size_t>(rank) * kHostLength));
  }

  long report_and_wait(const WorkerReport& report) override {
    const std::string text = nlohmann::json{{"case", report.finished_case},
                                            {"status", static_cast<int>(report.status)},
                                            {"ran", report.ran},
                                            {"message", report.message},
                                            {"pid", report.pid},
                                            {"host", report.host}}
                                 .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kReportTag, MPI_COMM_WORLD);
    long case_index = -1;
    MPI_Recv(&case_index, 1, MPI_LONG, 0, kAssignTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return case_index;
  }

 private:
  static constexpr int kReportTag = 1;
  static constexpr int kAssignTag = 2;
  static constexpr int kHostLength = 256;
  int rank_ = 0;
  int size_ = 1;
  std::vector<int> lost_;
  std::vector<long> pids_;   // process 0: every process's pid
  std::vector<char> hosts_;  // and host name, kHostLength bytes each
};

}  // namespace
}  // namespace deploydyn::cli

extern "C" __attribute__((visibility("default"))) deploydyn::cli::StudyProcesses* deploydyn_join_mpi() {
  return new deploydyn::cli::MpiChannel();
}

static_assert(std::is_same_v<decltype(&deploydyn_join_mpi), deploydyn::cli::JoinMpi>);
