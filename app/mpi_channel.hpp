#pragma once
// The processes of `mpirun -n N deploydyn study FILE` (OpenMPI from Debian), as the study
// runner's channel (study/study_channel.hpp). Without MPI at build time, or when mpirun did
// not start this process, there is no channel and `study` runs as one process.

#include <memory>

#include "deploydyn/study/study_channel.hpp"

namespace deploydyn::cli {

// The channel when mpirun started this process (its environment says so), else nullptr.
// Throws std::runtime_error when mpirun started it but this build has no MPI.
std::unique_ptr<StudyChannel> join_mpi_if_launched();

}  // namespace deploydyn::cli
