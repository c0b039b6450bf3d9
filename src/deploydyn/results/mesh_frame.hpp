#pragma once
// The structure as a mesh at an output time, as the writers that draw it see it (VTK frames,
// output/vtk_writer.hpp; the HDF5 file and its XDMF index, output/hdf5_writer.hpp): point i is
// node i at its current position (z = 0 in 2D); cell i is element i in the order of
// elements/element_kinds.hpp, between its nodes; and per cell one value of every cell array:
// each recorded result quantity of the model's element types, by name (types that share a
// quantity, such as the axial force, share the array; others get NaN there), then the element's
// temperature change.

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn {

class MeshLayout {
 public:
  explicit MeshLayout(const Model& model);  // keeps a reference to `model`

  int n_points() const { return model_.n_nodes(); }
  int n_cells() const { return static_cast<int>(cells_.size()); }
  const std::vector<ElementRef>& cells() const { return cells_; }
  // The cells' nodes one after the other, and where each cell's end (VTK's two arrays).
  const std::vector<std::int64_t>& connectivity() const { return connectivity_; }
  const std::vector<std::int64_t>& offsets() const { return offsets_; }

  // Names of the cell arrays: the recorded quantities, then "temperature_change_C".
  const std::vector<std::string>& cell_arrays() const { return cell_arrays_; }
  double cell_value(const StepRecord& record, std::size_t array, int cell) const;

  // Component `axis` (0..2) of node `node` in the global vector x (0 beyond the dimension).
  double nodal(const Eigen::VectorXd& x, int node, int axis) const {
    return axis < model_.dimension ? x[dofs_.index(node, axis)] : 0.0;
  }
  // Whether the record holds the whole state and every element's results (else it cannot be
  // drawn): make_step_record's records do.
  bool fits(const StepRecord& record) const;

 private:
  const Model& model_;
  DofMap dofs_;
  std::vector<ElementRef> cells_;
  std::vector<int> group_of_cell_;  // its type's place in element_kinds(): record.elements[group]
  std::vector<std::int64_t> connectivity_, offsets_;
  std::vector<std::string> cell_arrays_;
  std::vector<std::vector<int>> index_in_kind_;  // per array, per type: the quantity's index or −1
};

}  // namespace deploydyn
