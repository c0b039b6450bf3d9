// The model's constraints built apart from the Assembler (assembly/model_constraints.hpp), as the
// model loader counts them: on every example model with constraints of each kind (supports with
// axes and clamps, pin, ball and universal joints, every driver type, 3D beam frames, hinges),
// the same rows in the same order as the Assembler's, which adds only the hinge locks after them.
#include <gtest/gtest.h>

#include <string>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/model_constraints.hpp"
#include "deploydyn/io/model_loader.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

TEST(ModelConstraints, TheAssemblersRowsInTheAssemblersOrderBeforeTheHingeLocks) {
  int n_with_locks = 0, n_with_element_constraints = 0;
  for (const char* example : {"paper/parallel", "paper/general", "beams/frame3d", "boom/boom", "cables/guyed_mast",
                              "joints/cardan_shaft", "petal/petal", "scissor/arch", "scissor/ring",
                              "tutorial/bascule", "checks/luffing_boom", "checks/arm_clash"}) {
    SCOPED_TRACE(example);
    const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/" + example + ".yaml");
    const Assembler assembler(model);
    const DofMap dofs(model);
    const ModelConstraints built = make_model_constraints(model, dofs);
    ASSERT_EQ(built.n_equations(), assembler.n_equations() - assembler.n_switched_equations());
    ASSERT_EQ(built.support_constraint.size(), model.supports.size());
    ASSERT_EQ(built.driver_constraint.size(), model.drivers.size());
    int row = 0;
    for (const auto& c : built.constraints) {
      for (int k = 0; k < c->n_equations(); ++k, ++row) ASSERT_EQ(c->describe(k), assembler.describe_equation(row)) << row;
    }
    n_with_locks += assembler.n_switched_equations() > 0 ? 1 : 0;
    n_with_element_constraints += built.n_element_constraints > 0 ? 1 : 0;
  }
  EXPECT_GT(n_with_locks, 0) << "no example with hinge locks: the order after them is untested";
  EXPECT_GT(n_with_element_constraints, 0) << "no example with 3D beam frames";
}

// The loader's bound on the modes counts the constraints without the hinge locks: a hinge that
// is free leaves its motion to vibrate.
TEST(ModelConstraints, TheModalBoundLeavesOutHingeLocks) {
  const std::string chain = std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/assembly/models/hinge_chain_modal.yaml";
  EXPECT_EQ(load_model(chain).analysis.modal.n_modes, 3);
  try {
    load_model(chain, parse_overrides({"analysis.modes=4"}));
    FAIL() << "4 modes of 3 free motions accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("6 coordinates and 3 constraint equations: at most 3 modes, got 4"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
