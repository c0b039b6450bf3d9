// The stability analysis of one path point (solvers/continuation.hpp) on 3D roofs of 10
// trusses on pinned bearings at ΔT = 0: the dense route (Zᵀ K_T Z from a QR of Bᵀ, every
// eigenvalue; solvers/constrained_stiffness.hpp) against the sparse route (the lowest k by
// shift-invert Lanczos; solvers/lowest_constrained_stiffness.hpp), the latter at a first point
// (no expected eigenvalue) and along a path (σ and start vectors from the point before, here
// the same point). Counter `refactorizations`: the time as a multiple of one refactorization of
// the model's bordered matrix, the unit a corrector iteration costs about 1.5 of.

#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/solvers/constrained_stiffness.hpp"
#include "deploydyn/solvers/lowest_constrained_stiffness.hpp"
#include "support/cold_roof.hpp"

namespace deploydyn {
namespace {

constexpr int kTrusses = 10;

struct Roof {
  Model model;
  std::unique_ptr<Assembler> assembler;
  std::unique_ptr<LinearSystem> system;
  Eigen::VectorXd q, lambda;
  double scale = 1.0;
  double refactorization_s = 0.0;

  explicit Roof(int units) : model(bench::cold_pinned_roof(units, kTrusses)) {
    assembler = std::make_unique<Assembler>(model);
    system = make_linear_system(*assembler, LinearSolverKind::klu);
    q = assembler->initial_coordinates();
    lambda = Eigen::VectorXd::Zero(assembler->n_equations());
    scale = assembler->stiffness_scale(q, 0.0);
    assemble();
    refactorization_s = bench::median_refactorization_s(*system);
  }
  void assemble() { assembler->iteration_matrix(q, 0.0, 1.0, lambda, {0.0, 1.0, scale}, *system); }
};

void report(benchmark::State& state, const Roof& roof, double seconds_per_point) {
  state.counters["dofs"] = roof.assembler->n_dofs();
  state.counters["refactorizations"] = seconds_per_point / roof.refactorization_s;
}

void BM_DenseStability(benchmark::State& state) {
  Roof roof(static_cast<int>(state.range(0)));
  const int n = roof.assembler->n_dofs(), m = roof.assembler->n_equations();
  double total_s = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    roof.assemble();
    const Eigen::MatrixXd dense = roof.system->to_dense();
    const ConstraintNullSpace null_space = constraint_null_space(dense.bottomLeftCorner(m, n));
    const ConstrainedSpectrum spectrum = constrained_spectrum(dense.topLeftCorner(n, n), null_space.basis);
    benchmark::DoNotOptimize(spectrum.eigenvalues.data());
    total_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  report(state, roof, total_s / static_cast<double>(state.iterations()));
}

// range(1): k; range(2): 1 along a path (the previous point's lowest eigenvalue and modes).
void BM_SparseStability(benchmark::State& state) {
  Roof roof(static_cast<int>(state.range(0)));
  const LowestConstrainedStiffness lowest(*roof.assembler, *roof.system);
  LowestStiffnessRequest request;
  request.n_values = static_cast<int>(state.range(1));
  request.stiffness_scale_N_m = roof.scale;
  if (state.range(2) != 0) {
    roof.assemble();
    const ConstrainedSpectrum previous = lowest.compute(*roof.system, request);
    request.expected_lowest_N_m = previous.eigenvalues[0];
    request.expected_modes = previous.modes;
  }
  const int solves_before = lowest.n_solves(), factorizations_before = lowest.n_factorizations();
  double total_s = 0.0;
  ConstrainedSpectrum spectrum;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    roof.assemble();
    spectrum = lowest.compute(*roof.system, request);
    total_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (spectrum.eigenvalues.size() == 0) state.SkipWithError("no eigenvalues");
  }
  const auto n_points = static_cast<double>(state.iterations());
  report(state, roof, total_s / n_points);
  state.counters["solves"] = (lowest.n_solves() - solves_before) / n_points;
  state.counters["factorizations"] = (lowest.n_factorizations() - factorizations_before) / n_points;
  state.counters["lowest_N_m"] = spectrum.eigenvalues.size() > 0 ? spectrum.eigenvalues[0] : 0.0;
}

// 10 × 3, 10 × 8, 10 × 26 units: 240, 540, 1 620 coordinates (133, 363, 1 007 bars).
BENCHMARK(BM_DenseStability)->ArgName("units")->Arg(3)->Arg(8)->Arg(26)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SparseStability)
    ->ArgNames({"units", "k", "path"})
    ->ArgsProduct({{3, 8, 26, 263, 2630}, {1, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace deploydyn
