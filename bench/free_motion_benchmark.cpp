// The diagnosis of a singular model at the canopy's size (../shared/models/canopy3d.yaml without
// the roller under its right girder's far foot: 768 coordinates, 1248 unknowns; issue 31 asks for
// < 1 s): the null vector of the singular iteration matrix by sparse inverse iteration
// (LinearSystem::null_vector, assembly/null_space.hpp) against the dense SVD it replaced, and
// check's free motions (mobility's null space of [B; K_r], grouped and fitted,
// assembly/free_motion.hpp).

#include <benchmark/benchmark.h>

#include <Eigen/SVD>
#include <algorithm>
#include <memory>

#include "deploydyn/assembly/free_motion.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/assembly/mobility.hpp"
#include "deploydyn/io/model_loader.hpp"

namespace deploydyn {
namespace {

Model canopy_without_a_support() {
  Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/assembly/models/canopy3d.yaml");
  model.supports.erase(std::find_if(model.supports.begin(), model.supports.end(),
                                    [&](const FixedNode& s) { return model.nodes[s.node].name == "Rm2b_4"; }));
  return model;
}

// The static iteration matrix [K, sBᵀ; sB, 0] at the initial state, singular by the free motion.
std::unique_ptr<LinearSystem> singular_iteration_matrix(const Assembler& assembler) {
  std::unique_ptr<LinearSystem> system = make_linear_system(assembler, LinearSolverKind::klu);
  const Eigen::VectorXd q = assembler.initial_coordinates();
  const Eigen::VectorXd lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  assembler.iteration_matrix(q, 0.0, 1.0, lambda, {0.0, 1.0, assembler.stiffness_scale(q, 0.0)}, *system);
  return system;
}

void BM_CanopyNullVectorSparse(benchmark::State& state) {
  const Model model = canopy_without_a_support();
  const Assembler assembler(model);
  const std::unique_ptr<LinearSystem> system = singular_iteration_matrix(assembler);
  Eigen::MatrixXd basis;
  for (auto _ : state) benchmark::DoNotOptimize(basis = system->null_vectors());
  state.counters["unknowns"] = system->size();
  state.counters["null_space_dimension"] = static_cast<double>(basis.cols());
  state.counters["relative_residual"] =
      (system->to_dense() * basis).colwise().norm().maxCoeff() / system->to_dense().cwiseAbs().maxCoeff();
}

// What LinearSystem::null_vectors did before (for one vector): the right singular vector of the smallest singular
// value of the dense matrix.
void BM_CanopyNullVectorDenseSvd(benchmark::State& state) {
  const Model model = canopy_without_a_support();
  const Assembler assembler(model);
  const std::unique_ptr<LinearSystem> system = singular_iteration_matrix(assembler);
  Eigen::VectorXd v;
  for (auto _ : state) {
    const Eigen::BDCSVD<Eigen::MatrixXd> svd(system->to_dense(), Eigen::ComputeFullV);
    benchmark::DoNotOptimize(v = svd.matrixV().col(svd.matrixV().cols() - 1));
  }
  state.counters["unknowns"] = system->size();
}

// check's part: the rank, the null space of [B; K_r] and the motions named.
void BM_CanopyCheckFreeMotions(benchmark::State& state) {
  const Model model = canopy_without_a_support();
  const Assembler assembler(model);
  std::string text;
  for (auto _ : state) {
    const Mobility m = mobility(assembler);
    text = describe(model, free_motions(model, assembler.dof_map(), assembler.initial_coordinates(), m.free_motions));
    benchmark::DoNotOptimize(text);
  }
  state.counters["coordinates"] = assembler.n_dofs();
}

BENCHMARK(BM_CanopyNullVectorSparse)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_CanopyNullVectorDenseSvd)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_CanopyCheckFreeMotions)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace
}  // namespace deploydyn
