#pragma once
// How the processes of a distributed study talk (`mpirun -n N deploydyn study FILE`). The
// study runner is written against this interface and knows nothing of MPI; the command-line
// tool implements it over MPI (app/mpi_channel.cpp), tests over threads.
//
// Scheduling is dynamic: process 0 coordinates. Every other process (a worker) sends a report
// (of the case it finished, or none at its start) and receives the next case; a case goes to
// the next process that asks. Process 0 runs cases too, on its own threads, while it answers.

#include <optional>
#include <string>
#include <utility>

#include "deploydyn/solvers/analysis.hpp"

namespace deploydyn {

// A worker's message to process 0: the case it finished (if any), and who it is, so that
// process 0 can tell when it died (study/study_runner.cpp).
struct WorkerReport {
  int rank = 0;
  long finished_case = -1;  // index into Study::cases; −1: none (the worker's first message)
  RunStatus status = RunStatus::failed;
  bool ran = false;  // the case's model was built and run: its folder holds its results
  std::string message;
  long pid = 0;
  std::string host;
};

class StudyChannel {
 public:
  virtual ~StudyChannel() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Process 0: a worker's report if one has arrived, else nothing (it does not wait).
  virtual std::optional<WorkerReport> poll_report() = 0;
  // Process 0: the case `rank` runs next; −1: no more, the worker stops.
  virtual void assign(int rank, long case_index) = 0;
  // A worker: sends its report to process 0 and waits for its next case (−1: stop).
  virtual long report_and_wait(const WorkerReport& report) = 0;
  // Process 0: worker `rank` died. The channel must not wait for it when the study ends.
  virtual void lost(int /*rank*/) {}
  // Process 0: worker `rank`'s pid and host, when the channel knows them from the start (MPI
  // gathers them as the processes start), so that a worker that dies before its first report
  // is noticed too. Empty: known from its first report.
  virtual std::optional<std::pair<long, std::string>> identity(int /*rank*/) const { return std::nullopt; }
};

}  // namespace deploydyn
