#pragma once
// Picks and prepares the back end for a model's iteration matrix: analysed with the
// assembler's pattern, ready for Assembler::iteration_matrix.

#include <memory>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system.hpp"

namespace deploydyn {

// Up to this many unknowns (q and λ) dense LU beats KLU on the iteration matrix of our bar
// models (bench/linear_solver_benchmark.cpp: planar roofs, KLU refactorization vs dense LU).
constexpr int kLargestDenseSystem = 100;

// `automatic` resolved by size; the others as they are.
LinearSolverKind choose_linear_solver(LinearSolverKind requested, int n_unknowns);

std::unique_ptr<LinearSystem> make_linear_system(const Assembler& assembler, LinearSolverKind kind);
// With the model's own choice (analysis.linear_solver).
std::unique_ptr<LinearSystem> make_linear_system(const Assembler& assembler);

}  // namespace deploydyn
