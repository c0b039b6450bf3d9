#include "mpi_channel.hpp"

#include <cstdlib>

#include "deploydyn/util/optional_module.hpp"

namespace deploydyn::cli {
namespace {

// OpenMPI's mpirun (and PMIx launchers) set these in every process they start.
bool launched_by_mpirun() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"}) {
    if (std::getenv(variable) != nullptr) return true;
  }
  return false;
}

}  // namespace

std::unique_ptr<StudyProcesses> join_mpi_if_launched() {
  if (!launched_by_mpirun()) return nullptr;
  // MPI lives in its module (modules/mpi_module.cpp): a study without mpirun does not load it.
  const auto join = optional_module_entry<JoinMpi>(
      kMpiModuleName, kJoinMpiSymbol,
      "`deploydyn study` under mpirun, to spread the cases over the MPI processes (without mpirun the "
      "study runs as one process)");
  return std::unique_ptr<StudyProcesses>(join());
}

}  // namespace deploydyn::cli
