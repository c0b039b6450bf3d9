#pragma once
// Picks and prepares the back end for a model's iteration matrix: analysed with the
// assembler's pattern, ready for Assembler::iteration_matrix.

#include <memory>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system.hpp"

namespace deploydyn {

// `automatic` is KLU at every size: measured (bench/roof_benchmark.cpp, BM_SmallRoofStep), a
// time step with KLU takes 0.65× the dense LU's time already at 13 unknowns (one roof unit,
// the paper's linkage) and 0.03× at 187. Dense LU stays as an explicit choice and as the
// reference the sparse back ends are tested against. The others as they are.
LinearSolverKind choose_linear_solver(LinearSolverKind requested, int n_unknowns);

std::unique_ptr<LinearSystem> make_linear_system(const Assembler& assembler, LinearSolverKind kind);
// With the model's own choice (analysis.linear_solver).
std::unique_ptr<LinearSystem> make_linear_system(const Assembler& assembler);

class KluLinearSystem;
// The KLU that factors `system` in the end, through the eliminations of frames and local
// multipliers; null when the back end is not KLU. For benchmarks, tests and reports.
const KluLinearSystem* factoring_klu(const LinearSystem& system);

}  // namespace deploydyn
