#include "deploydyn/output/hdf5_output.hpp"

#include <stdexcept>

#include "deploydyn/output/output_error.hpp"
#include "deploydyn/results/result_file_names.hpp"
#include "deploydyn/util/optional_module.hpp"

namespace deploydyn {

std::unique_ptr<Hdf5Output> open_hdf5_output(const std::filesystem::path& folder, const Model& model) {
  OpenHdf5Output open = nullptr;
  try {
    open = optional_module_entry<OpenHdf5Output>(kHdf5ModuleName, kOpenHdf5OutputSymbol,
                                                 "output.hdf5 (history.h5 is written with the HDF5 library)");
  } catch (const std::runtime_error& error) {
    // Like a folder without permission: the run's results cannot all be written (exit code 3).
    throw OutputError("cannot write", folder / kHdf5FileName, 0, error.what());
  }
  return std::unique_ptr<Hdf5Output>(open(folder, model));
}

}  // namespace deploydyn
