#pragma once
// history.h5 for a run, through the HDF5 module (modules/hdf5_module.cpp, deploydyn_hdf5.so):
// the command and the Python module do not link HDF5 and its 36 libraries; a run that asks for
// `output: {hdf5: true}` loads them (util/optional_module.hpp). The writer itself is
// output/hdf5_writer.hpp, in this library too for programs that link HDF5 themselves.

#include <filesystem>
#include <memory>

#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn {

// A sink that writes history.h5 and its index; finish() before destruction, to see errors.
class Hdf5Output : public RecordSink {
 public:
  // Flushes the file and writes history.xdmf. Throws OutputError.
  virtual void finish() = 0;
};

// The HDF5 module's writer (Hdf5Writer) into `folder`, keeping a reference to `model`. Throws
// OutputError when the file cannot be made or the module cannot be loaded.
std::unique_ptr<Hdf5Output> open_hdf5_output(const std::filesystem::path& folder, const Model& model);

// The module's entry point: a new Hdf5Writer (the caller owns it).
using OpenHdf5Output = Hdf5Output* (*)(const std::filesystem::path& folder, const Model& model);
inline constexpr const char* kHdf5ModuleName = "deploydyn_hdf5";
inline constexpr const char* kOpenHdf5OutputSymbol = "deploydyn_open_hdf5_output";

}  // namespace deploydyn
