// KLU with and without its block triangular form (BTF) on the iteration matrix of 3D beams
// (assembly/klu_linear_system.hpp, KluBlocks; docs/performance.md, "3D beams"): the canopy of
// ../shared/models/canopy3d.yaml (50 3D beams, 12 bars, 16 pins, 1250 unknowns).

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/frame_eliminating_linear_system.hpp"
#include "deploydyn/assembly/klu_linear_system.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/random_vector.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::random_vector;

Model canopy() {
  return load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/assembly/models/canopy3d.yaml");
}

// The canopy's iteration matrix at its initial state as generalized-α's step of 5 ms weighs it
// (c_M = 1/(β h²), β = 0.25 … ; the exact weights do not matter here), factorized by `system`.
void factorize_canopy_matrix(const Assembler& assembler, KluLinearSystem& system) {
  system.analyze(assembler.n_unknowns(), assembler.matrix_entries());
  const Eigen::VectorXd q = assembler.initial_coordinates();
  const Eigen::VectorXd lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  Assembler::MatrixWeights weights;
  weights.mass = 1.0 / (0.25 * 0.005 * 0.005);
  weights.constraint_scale = assembler.stiffness_scale(q, 0.0);
  assembler.iteration_matrix(q, 0.0, 1.0, lambda, weights, system);
  ASSERT_TRUE(system.factorize().ok);
}

// BTF's matching puts constraint rows on the multipliers' diagonal; AMD's order of that pattern
// costs 6 × the operations (measured 1.06e7 against 1.65e6). The solutions agree.
TEST(KluBlocks, ThreeDBeamsFactorWithAFractionOfTheOperationsWithoutBtf) {
  const Model model = canopy();
  const Assembler assembler(model);
  KluLinearSystem triangular(KluOrdering::amd, KluBlocks::triangular);
  KluLinearSystem whole(KluOrdering::amd, KluBlocks::whole);
  factorize_canopy_matrix(assembler, triangular);
  factorize_canopy_matrix(assembler, whole);
  EXPECT_LT(whole.factor_operations(), 0.3 * triangular.factor_operations());
  EXPECT_LT(whole.factor_nonzeros(), 0.6 * triangular.factor_nonzeros());
  const Eigen::VectorXd b = random_vector(assembler.n_unknowns(), 3);
  Eigen::VectorXd x_triangular = b, x_whole = b;
  triangular.solve(x_triangular);
  whole.solve(x_whole);
  EXPECT_LT((x_whole - x_triangular).lpNorm<Eigen::Infinity>(), 1e-8 * x_triangular.lpNorm<Eigen::Infinity>());
}

// The default back end orders 3D beam models without BTF, every other model with it (their
// results unchanged bit for bit).
TEST(KluBlocks, OnlyThreeDBeamModelsLeaveBtfOut) {
  const Model beams = canopy();
  RoofOptions options;
  options.n_units = 3;
  options.n_trusses = 3;
  const Model bars = make_roof(options);
  for (const Model* model : {&beams, &bars}) {
    const Assembler assembler(*model);
    const auto system = make_linear_system(assembler);
    // 3D beams: KLU factors the matrix with the frames eliminated (frame_eliminating_linear_system.hpp).
    const KluLinearSystem* klu = factoring_klu(*system);
    ASSERT_NE(klu, nullptr);
    EXPECT_EQ(klu->blocks(), model == &beams ? KluBlocks::whole : KluBlocks::triangular) << model->name;
  }
}

}  // namespace
}  // namespace deploydyn
