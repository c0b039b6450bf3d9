#pragma once
// The command line's exit codes, for scripts that run deploydyn (README, "The command line").

namespace deploydyn::cli {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitSolverFailure = 1;  // the solver gave up, or the run was interrupted
inline constexpr int kExitBadInput = 2;       // a model, study, override or option is wrong
inline constexpr int kExitOutputFailure = 3;  // results could not be written (disk full,
                                              // permissions, a folder in use by another run)

}  // namespace deploydyn::cli
