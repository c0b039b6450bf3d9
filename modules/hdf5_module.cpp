// The HDF5 module, deploydyn_hdf5.so: history.h5 (output/hdf5_writer.hpp) for the programs that
// do not link HDF5 themselves (output/hdf5_output.hpp loads it; docs/performance.md, "A light
// start"). It holds its own copy of the writer and what the writer uses, from the static library.

#include <type_traits>

#include "deploydyn/output/hdf5_writer.hpp"

extern "C" __attribute__((visibility("default"))) deploydyn::Hdf5Output* deploydyn_open_hdf5_output(
    const std::filesystem::path& folder, const deploydyn::Model& model) {
  return new deploydyn::Hdf5Writer(folder, model);
}

// The loader finds the entry point by this name and casts it to this type.
static_assert(std::is_same_v<decltype(&deploydyn_open_hdf5_output), deploydyn::OpenHdf5Output>);
