#pragma once
// A position in the iteration matrix: the row and column of two unknowns as the DofMap
// (model/dof_map.hpp) numbers them, constraint rows after the coordinates. Elements list the
// entries they write (elements/element.hpp); the linear systems take the whole pattern
// (assembly/linear_system.hpp).

namespace deploydyn {

struct MatrixEntry {
  int row = 0;
  int col = 0;
};

}  // namespace deploydyn
