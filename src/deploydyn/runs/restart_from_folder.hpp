#pragma once
// Restart (docs/model-format.md, "Restart"): a run that starts from a state an earlier run of
// the same model kept in its result folder's states.bin (output/state_file.hpp), read and
// checked against the model it is to start: same unknowns (coordinates, constraint equations,
// element histories), a time that run kept, a time before this run's end. Every error names
// the option (the CLI's --restart-from and --at; `modes --from`) and says what is allowed.

#include <filesystem>
#include <optional>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/solvers/restart_state.hpp"

namespace deploydyn {

// How a time history starts and what it keeps for a later restart, besides its model.
struct RestartOptions {
  std::filesystem::path from_folder;  // a run's result folder; empty: the model's initial equilibrium
  std::optional<double> time_s;       // a time that run kept (s); empty: its last state
  bool keep_every_output = false;     // states.bin keeps every output time's state, not only the last

  bool restart() const { return !from_folder.empty(); }
};

// Throws std::invalid_argument when the folder holds no state this model can start from, or the
// model gives initial_velocities (a restart continues the kept velocities).
RestartState restart_state_for(const Model& model, const Assembler& assembler, const RestartOptions& options);

// Where a time history begins: the state a restart takes on, or the model's initial velocities,
// or neither (the model's initial equilibrium, at rest).
struct RunOrigin {
  std::optional<RestartState> kept;
  std::optional<Eigen::VectorXd> velocities;

  RunStart start() const { return {kept ? &*kept : nullptr, velocities ? &*velocities : nullptr}; }
};
// Throws std::invalid_argument as restart_state_for, and for initial velocities the model's
// elements cannot take (a spin of 3D beams).
RunOrigin run_origin(const Model& model, const Assembler& assembler, const RestartOptions& restart);

// run_to_folder (runs/run_to_folder.hpp) for a time history that starts from a state an earlier
// run kept, or keeps every output time's state; a modal analysis takes the modes of that state.
// Throws std::invalid_argument, before any file is touched, when the state does not fit.
RunReport run_to_folder(const Model& model, const std::filesystem::path& folder, const RunControl& control,
                        Envelope& envelope, std::optional<Verdict>* verdict, const RestartOptions& restart);

}  // namespace deploydyn
