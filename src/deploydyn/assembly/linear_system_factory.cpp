#include "deploydyn/assembly/linear_system_factory.hpp"

#include "deploydyn/assembly/dense_linear_system.hpp"
#include "deploydyn/assembly/klu_linear_system.hpp"
#include "deploydyn/assembly/umfpack_from_module.hpp"

namespace deploydyn {

LinearSolverKind choose_linear_solver(LinearSolverKind requested, int /*n_unknowns*/) {
  return requested == LinearSolverKind::automatic ? LinearSolverKind::klu : requested;
}

std::unique_ptr<LinearSystem> make_linear_system(const Assembler& assembler, LinearSolverKind kind) {
  std::unique_ptr<LinearSystem> system;
  switch (choose_linear_solver(kind, assembler.n_unknowns())) {
    case LinearSolverKind::klu: system = std::make_unique<KluLinearSystem>(KluOrdering::automatic); break;
    case LinearSolverKind::klu_nested_dissection:
      system = std::make_unique<KluLinearSystem>(KluOrdering::nested_dissection);
      break;
    case LinearSolverKind::klu_two_domains:
      system = std::make_unique<KluLinearSystem>(KluOrdering::two_domains);
      break;
    case LinearSolverKind::umfpack: system = umfpack_from_module(); break;  // loads UMFPACK on demand
    default: system = std::make_unique<DenseLinearSystem>(); break;
  }
  system->analyze(assembler.n_unknowns(), assembler.matrix_entries());
  return system;
}

std::unique_ptr<LinearSystem> make_linear_system(const Assembler& assembler) {
  return make_linear_system(assembler, assembler.model().analysis.linear_solver);
}

}  // namespace deploydyn
