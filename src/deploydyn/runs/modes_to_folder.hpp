#pragma once
// A modal analysis (analysis.type: modal, solvers/modal_analysis.hpp; docs/theory.md, "Natural
// frequencies and modes"): the natural frequencies and modes about the static equilibrium at
// each time of analysis.at (the thermal state at t = 0, then the drivers moved quasi-statically
// to the time). What run_to_folder does for this
// type, and what `deploydyn modes` and the Python module's Model.modes / Model.run compute.
//
// In a result folder (runs/run_folder.hpp): summary.json saying "running", model.yaml, then
// per time, as soon as its modes are found, its rows of modes.csv and its frames of the mode
// shapes' ParaView series vtk/deploydyn.pvd (a run stopped part-way keeps every time it
// finished), and summary.json at the end: status, the frequencies per time, the files.
//
// modes.csv, one row per time and mode:
//   frame              the row's frame in vtk/deploydyn.pvd (the frame's "time" field)
//   t                  s, where the drivers stand
//   mode               1, 2, … in ascending ω²
//   omega2             ω² (rad²/s²); < 0: the equilibrium is unstable
//   frequency          f = ω / 2π (Hz); nan where ω² < 0
//   dT_C               the model-wide ΔT(t) (°C)
//   position.<driver>  the driver's motion from the initial state at t: rad (the turning
//                      drivers: bar_angle, revolute, hinge_angle) or m (coordinate)
// A time without modes (no equilibrium found) has no rows, and summary.json says why.
// Frame k is the equilibrium moved along the mode of row k until its largest nodal displacement
// is a tenth of the shortest bar; its vector field velocity_m_s holds the M-orthonormal mode.

#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/analysis.hpp"
#include "deploydyn/solvers/hinge_poses.hpp"
#include "deploydyn/solvers/restart_state.hpp"
#include "deploydyn/solvers/modal_analysis.hpp"
#include "deploydyn/results/result_file_names.hpp"

namespace deploydyn {

// A mode is drawn as the equilibrium moved along it until its largest coordinate is this share
// of the shortest element: visible, and still small enough to read as a linear mode. The report
// takes it back off to find the equilibrium (report/modal_view.hpp).
inline constexpr double kDrawnModeShare = 0.1;

// One time's outcome, as summary.json lists it.
struct ModesSummary {
  double time_s = 0.0;
  Eigen::VectorXd omega2_rad2_s2;  // empty when no modes were found
  std::string failure;             // why not, or empty
};

struct ModalRun {
  RunReport report;  // completed; failed when a time has no modes (the others are still done);
                     // interrupted when `control` stopped it
  std::vector<ModesSummary> times;
};

using EachModes = std::function<void(const EquilibriumModes&)>;

// The modes at every time of the model's analysis.modal, handing each time's to `each` as it
// is found (may be empty). Throws std::invalid_argument when the model's mechanics cannot be
// built.
ModalRun compute_modes(const Assembler& assembler, const RunControl& control, const EachModes& each);
// The same with the hinges held as `hinges` says (solvers/hinge_poses.hpp), or, given a state
// a run kept, the modes of that state at its time (the model's times are not used).
ModalRun compute_modes(const Assembler& assembler, const RunControl& control, const RestartState* kept,
                       HingeHold hinges, const EachModes& each);

// Where a modal analysis starts besides its model: what holds the hinges, or a run's result
// folder whose last state it takes (runs/restart_from_folder.hpp).
struct ModesStart {
  HingeHold hinges = HingeHold::free;
  std::filesystem::path from_folder;
};

// The same in a folder it owns, as run_to_folder. Throws std::invalid_argument as above
// (before any file is touched), OutputError when the folder is in use or a file cannot be
// written (summary.json then says "failed" and why, and the files keep what was written).
RunReport run_modes_to_folder(const Model& model, const std::filesystem::path& folder,
                              const RunControl& control = {}, const EachModes& each = {},
                              const ModesStart& start = {});

class FolderRun;
// The same as the driver's part (runs/run_folder.hpp), for the table of analysis types.
std::unique_ptr<FolderRun> make_modes_run(const Model& model, EachModes each, const ModesStart& start = {});

std::vector<std::string> modes_columns(const Model& model);
// The rows of one time (none when it has no modes), in the order of modes_columns, the first
// numbered `first_frame`.
void append_modes_rows(const Assembler& assembler, const EquilibriumModes& at, int first_frame,
                       std::vector<double>& values);
std::string modes_summary_json(const Model& model, const ModalRun& run);

}  // namespace deploydyn
