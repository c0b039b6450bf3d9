#pragma once
// Optional layers in modules loaded on demand (docs/performance.md, "A light start").
//
// A library that only some runs need is not linked into the command or the Python module: it
// lives in a shared-library module of its own, opened with dlopen the first time a run asks
// for what it does. Every process otherwise pays the dynamic loader's time and memory for
// every linked library and all of theirs (HDF5 brings 36 more: curl, TLS, Kerberos, LDAP).
//
//   module            library       loaded when
//   deploydyn_hdf5    HDF5          a run writes history.h5 (`output: {hdf5: true}`)
//   deploydyn_mpi     Open MPI      `deploydyn study` was started by mpirun
//   deploydyn_umfpack UMFPACK (CHOLMOD, LAPACK, BLAS, gfortran)   `linear_solver: umfpack`
//
// Each module holds its own copy of the class it offers, from the static library, where the
// class stays for the programs that link the library (and its library) themselves. The module
// exports one entry point, a C function that returns a new object behind an interface of
// the library; the caller owns it.
//
// A module is looked for in $DEPLOYDYN_MODULE_DIR alone when it is set; else, in order, beside
// the program or library that holds this code, as installed (<dir>/../lib/deploydyn, found with
// dladdr, so the command, the Python module and a downstream program all find theirs); in the
// install prefix's lib/deploydyn; in the build tree's modules/.

#include <string>
#include <string_view>

namespace deploydyn {

// The address of `symbol` in module `name` (e.g. "deploydyn_hdf5"), loading the module the
// first time. Throws std::runtime_error naming the module, the folders looked in, the loader's
// reason and `needed_for` (what the run asked for that needs it) when it cannot.
void* optional_module_symbol(std::string_view name, const char* symbol, std::string_view needed_for);

// The entry point `symbol` of module `name` as the function type Entry.
template <class Entry>
Entry optional_module_entry(std::string_view name, const char* symbol, std::string_view needed_for) {
  return reinterpret_cast<Entry>(optional_module_symbol(name, symbol, needed_for));
}

// The folders looked in for modules, in order.
std::string optional_module_folders();

}  // namespace deploydyn
