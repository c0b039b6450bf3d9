#include "deploydyn/assembly/linear_system_factory.hpp"

#include "deploydyn/assembly/dense_linear_system.hpp"
#include "deploydyn/assembly/frame_eliminating_linear_system.hpp"
#include "deploydyn/assembly/klu_linear_system.hpp"
#include "deploydyn/assembly/multiplier_eliminating_linear_system.hpp"
#include "deploydyn/assembly/umfpack_from_module.hpp"

namespace deploydyn {
namespace {

// From this many unknowns on, the pins' and drivers' multipliers are eliminated behind the frames
// (multiplier_eliminating_linear_system.hpp): on the 4 × 8 canopy (6 400 unknowns) KLU's
// operations fall 9 × and the step 2.4 ×; on the 50-beam canopy (1 250) the smaller LU saves less
// than the elimination costs. docs/performance.md, "3D beams".
constexpr int kMultiplierEliminationUnknowns = 3000;

}  // namespace

LinearSolverKind choose_linear_solver(LinearSolverKind requested, int /*n_unknowns*/) {
  return requested == LinearSolverKind::automatic ? LinearSolverKind::klu : requested;
}

std::unique_ptr<LinearSystem> make_linear_system(const Assembler& assembler, LinearSolverKind kind) {
  // Elements that bring constraints of their own are 3D beams, six frame multipliers a node: KLU
  // orders their matrix as it is, without BTF's matching (klu_linear_system.hpp, KluBlocks), and
  // factors it with the frames eliminated (frame_eliminating_linear_system.hpp). Other models
  // keep BTF, and their results bit for bit. Behind the frames of large models, the pins' and
  // revolute drivers' multipliers are eliminated too (multiplier_eliminating_linear_system.hpp).
  const KluBlocks blocks =
      assembler.mass_definite_on_constraints_only() ? KluBlocks::whole : KluBlocks::triangular;
  std::unique_ptr<KluLinearSystem> klu;
  std::unique_ptr<LinearSystem> system;
  switch (choose_linear_solver(kind, assembler.n_unknowns())) {
    case LinearSolverKind::klu: klu = std::make_unique<KluLinearSystem>(KluOrdering::automatic, blocks); break;
    case LinearSolverKind::klu_nested_dissection:
      klu = std::make_unique<KluLinearSystem>(KluOrdering::nested_dissection, blocks);
      break;
    case LinearSolverKind::klu_two_domains: klu = std::make_unique<KluLinearSystem>(KluOrdering::two_domains); break;
    case LinearSolverKind::umfpack: system = umfpack_from_module(); break;  // loads UMFPACK on demand
    default: system = std::make_unique<DenseLinearSystem>(); break;
  }
  if (klu) {
    std::vector<FrameUnknowns> frames = assembler.frame_unknowns();
    if (frames.empty()) system = std::move(klu);
    else if (assembler.n_unknowns() < kMultiplierEliminationUnknowns) {
      system = std::make_unique<FrameEliminatingLinearSystem>(std::move(frames), std::move(klu));
    } else {
      system = std::make_unique<FrameEliminatingLinearSystem>(
          std::move(frames), std::make_unique<MultiplierEliminatingLinearSystem>(std::move(klu)));
    }
  }
  system->analyze(assembler.n_unknowns(), assembler.matrix_entries());
  return system;
}

std::unique_ptr<LinearSystem> make_linear_system(const Assembler& assembler) {
  return make_linear_system(assembler, assembler.model().analysis.linear_solver);
}

const KluLinearSystem* factoring_klu(const LinearSystem& system) {
  if (const auto* klu = dynamic_cast<const KluLinearSystem*>(&system)) return klu;
  if (const auto* frames = dynamic_cast<const FrameEliminatingLinearSystem*>(&system)) {
    return factoring_klu(frames->reduced());
  }
  if (const auto* multipliers = dynamic_cast<const MultiplierEliminatingLinearSystem*>(&system)) {
    return &multipliers->factored();
  }
  return nullptr;
}

}  // namespace deploydyn
