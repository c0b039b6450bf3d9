#pragma once
// Where each node's unknowns sit in the global vector q, and what they are called.
//
// Every node carries its position's `dimension` coordinates x, y(, z) first; an element type
// may give the nodes of its elements more unknowns (rotations, slopes:
// ElementKind::add_node_unknowns), which follow. So the map stores a first index and a list of
// unknown names per node instead of assuming q[d·i + k].

#include <string>
#include <string_view>
#include <vector>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

class DofMap {
 public:
  explicit DofMap(const Model& model);

  int n_dofs() const { return n_dofs_; }
  // Index in q of coordinate `axis` (0 = x, 1 = y, 2 = z) of node `node`.
  int index(int node, int axis) const { return first_[node] + axis; }
  // Index in q of the unknown named `unknown` ("x", "rz", ...) of `node`; −1 if it has none.
  int index(int node, std::string_view unknown) const;
  int first(int node) const { return first_[node]; }
  int count(int node) const { return static_cast<int>(unknowns(node).size()); }
  // The names of a node's unknowns, in the order of q: x, y(, z), then element-added ones.
  const std::vector<std::string>& unknowns(int node) const {
    return unknown_sets_[set_of_node_[node]];
  }
  // "y.B": the unknown's name as history.csv spells it.
  std::string label(int dof) const;

 private:
  int n_dofs_ = 0;
  std::vector<int> first_;
  std::vector<int> set_of_node_;                        // index into unknown_sets_
  std::vector<std::vector<std::string>> unknown_sets_;  // distinct lists of unknown names
  std::vector<std::string> node_names_;
};

}  // namespace deploydyn
