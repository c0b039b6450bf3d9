#pragma once
// The processes of `mpirun -n N deploydyn study FILE` (OpenMPI from Debian), as the study
// runner's channel (study/study_channel.hpp). When mpirun did not start this process there is
// no channel and `study` runs as one process. MPI itself is in the module deploydyn_mpi
// (modules/mpi_module.cpp), loaded only under mpirun (util/optional_module.hpp).

#include <memory>

#include "deploydyn/study/study_channel.hpp"

namespace deploydyn::cli {

// The study's processes, besides the cases: how they end together on an error, so that its
// message is printed once and the processes exit cleanly rather than in MPI_Abort's banner.
class StudyProcesses : public StudyChannel {
 public:
  // Every process calls this with its own error's exit code (0: none). Returns the largest,
  // and in `first_rank_failed` whether process 0 has one (then it alone tells it).
  virtual int agree_on_exit(int exit_code, bool& first_rank_failed) = 0;
  // Ends every process with `exit_code`, for an error only this process knows of; its
  // message must be printed and flushed before.
  [[noreturn]] virtual void end_all(int exit_code) = 0;
};

// The processes when mpirun started this one (its environment says so), else nullptr.
// Throws std::runtime_error when mpirun started it but the MPI module cannot be loaded (this
// build has no MPI, or the module is missing).
std::unique_ptr<StudyProcesses> join_mpi_if_launched();

// The MPI module's entry point: joins the processes (MPI_Init); the caller owns the result.
using JoinMpi = StudyProcesses* (*)();
inline constexpr const char* kMpiModuleName = "deploydyn_mpi";
inline constexpr const char* kJoinMpiSymbol = "deploydyn_join_mpi";

}  // namespace deploydyn::cli
