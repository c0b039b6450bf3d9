#pragma once
// UMFPACK's back end (assembly/umfpack_linear_system.hpp) from the UMFPACK module
// (modules/umfpack_module.cpp, deploydyn_umfpack.so): UMFPACK brings CHOLMOD, LAPACK, BLAS and
// gfortran, which no other back end needs, so the command and the Python module load them only
// for `linear_solver: umfpack` (util/optional_module.hpp; docs/performance.md, "A light start").

#include <memory>

#include "deploydyn/assembly/linear_system.hpp"

namespace deploydyn {

// A new UmfpackLinearSystem of the module. Throws std::runtime_error when the module cannot be
// loaded.
std::unique_ptr<LinearSystem> umfpack_from_module();

using MakeUmfpackLinearSystem = LinearSystem* (*)();
inline constexpr const char* kUmfpackModuleName = "deploydyn_umfpack";
inline constexpr const char* kMakeUmfpackSymbol = "deploydyn_make_umfpack_linear_system";

}  // namespace deploydyn
