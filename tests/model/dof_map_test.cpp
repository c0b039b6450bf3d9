// Where each node's unknowns sit (model/dof_map.hpp): positions first, named as history.csv
// spells them.
#include "deploydyn/model/dof_map.hpp"

#include <gtest/gtest.h>

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

Model three_nodes(int dimension) {
  Model model;
  model.dimension = dimension;
  for (const char* name : {"A", "B", "C"}) model.nodes.push_back({.name = name});
  return model;
}

TEST(DofMap, PositionsOfEveryNodeInNodeOrder) {
  for (const int dimension : {2, 3}) {
    const DofMap dofs(three_nodes(dimension));
    ASSERT_EQ(dofs.n_dofs(), 3 * dimension);
    for (int node = 0; node < 3; ++node) {
      EXPECT_EQ(dofs.first(node), dimension * node);
      EXPECT_EQ(dofs.count(node), dimension);
      EXPECT_EQ(dofs.index(node, 1), dimension * node + 1);
      EXPECT_EQ(dofs.index(node, "y"), dimension * node + 1);
    }
    EXPECT_EQ(dofs.index(0, "z"), dimension == 3 ? 2 : -1);
    EXPECT_EQ(dofs.index(0, "rz"), -1);
  }
}

TEST(DofMap, LabelsNameTheUnknownAndItsNode) {
  const DofMap dofs(three_nodes(3));
  EXPECT_EQ(dofs.label(0), "x.A");
  EXPECT_EQ(dofs.label(4), "y.B");
  EXPECT_EQ(dofs.label(8), "z.C");
}

}  // namespace
}  // namespace deploydyn
