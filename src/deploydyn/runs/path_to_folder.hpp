#pragma once
// A continuation run (analysis.type: continuation, solvers/continuation.hpp) with its results
// on disk: summary.json saying "running", model.yaml (the model as run) (runs/run_folder.hpp),
// path.csv (one row per converged point, appended in whole rows as each point is reached, so
// that a run stopped, failed or killed part-way keeps every point it reached) and summary.json
// again (how it ended, and the events). What run_to_folder does for this type.
//
// path.csv columns:
//   mu                      the parameter μ
//   dT_C | load_N           thermal: μ × the model-wide ΔT(0); load: μ × the largest nodal
//                           force entry of the loads and gravity
//   displacement_norm_m     ‖q − q_initial‖₂
//   eigenvalue_1_N_m …      lowest eigenvalues of Zᵀ K_T Z (analysis.eigenvalues of them)
//   n_negative              negative ones: 0 is a stable equilibrium
//   event                   limit_point, bifurcation, singular_constraints, or empty
//   x.<node>, force.<el> …  the columns history.csv would hold at the point, output.select
//                           applied, but for t and the energies (results/path_quantities.hpp)

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "deploydyn/solvers/analysis.hpp"
#include "deploydyn/solvers/continuation.hpp"

namespace deploydyn {

struct Verdict;

// In a folder it owns, as run_to_folder (runs/result_folder.hpp). Throws
// std::invalid_argument when the model's mechanics cannot be built (before any file is
// touched), OutputError when the folder is in use or a file cannot be written (summary.json
// then says "failed" and why, and path.csv keeps the rows written before).
RunReport run_path_to_folder(const Model& model, const std::filesystem::path& folder,
                             const RunControl& control = {});

class FolderRun;
// The same as the driver's part (runs/run_folder.hpp), for the table of analysis types; the
// path's verdict (its member checks at every point) is left in `verdict` when given.
std::unique_ptr<FolderRun> make_path_run(const Model& model, std::optional<Verdict>* verdict = nullptr);

// The continuation that the model's analysis section asks for, from its initial state at t = 0.
ContinuationOptions path_options(const Model& model);

// `verdict`: summary.json's `verdict`, when given.
std::string path_summary_json(const Assembler& assembler, const ContinuationResult& result,
                              const RunReport& report, const Verdict* verdict = nullptr);

}  // namespace deploydyn
