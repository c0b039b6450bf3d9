#pragma once
// The names a run gives the files of its result folder (docs/model-format.md, "Result folders"),
// in one header with no dependencies: the model loader (io/) refuses an output.history or
// output.summary name that one of them already takes, without including the writers.
// history.csv and summary.json are not here: the model chooses them (output.history,
// output.summary; model/model.hpp holds their defaults).

namespace deploydyn {

// Whoever owns the folder holds a lock on this file (runs/result_folder.hpp).
inline constexpr const char* kLockFileName = ".deploydyn.lock";
// The model as run (overrides applied), in a run's folder.
inline constexpr const char* kRunModelFileName = "model.yaml";
inline constexpr const char* kEnvelopeFileName = "envelopes.csv";
inline constexpr const char* kHdf5FileName = "history.h5";
inline constexpr const char* kXdmfFileName = "history.xdmf";
inline constexpr const char* kTemperatureFileName = "temperatures.csv";
// The states a time history may be restarted from (output/state_file.hpp).
inline constexpr const char* kStateFileName = "states.bin";
inline constexpr const char* kVtkFolderName = "vtk";  // in a run's result folder
inline constexpr const char* kVtkCollectionFileName = "deploydyn.pvd";  // in kVtkFolderName
// analysis.type: continuation's and modal's tables.
inline constexpr const char* kPathFileName = "path.csv";
inline constexpr const char* kModesFileName = "modes.csv";
// `deploydyn window --out`'s folder.
inline constexpr const char* kWindowStatusFileName = "window.json";
inline constexpr const char* kWindowSamplesFileName = "window.csv";

}  // namespace deploydyn
