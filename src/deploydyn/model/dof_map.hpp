#pragma once
// Where each node's unknowns sit in the global vector q.
//
// Today every node carries its `dimension` coordinates; beams will add rotations to some
// nodes, so the map stores a first index and a count per node instead of assuming q[d·i + k].

#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

class DofMap {
 public:
  explicit DofMap(const Model& model) {
    first_.reserve(model.nodes.size());
    count_.reserve(model.nodes.size());
    for (const Node& node : model.nodes) {
      labels_base_.push_back(node.name);
      first_.push_back(n_dofs_);
      count_.push_back(model.dimension);
      n_dofs_ += model.dimension;
    }
  }

  int n_dofs() const { return n_dofs_; }
  // Index in q of coordinate `axis` (0 = x, 1 = y, 2 = z) of node `node`.
  int index(int node, int axis) const { return first_[node] + axis; }
  int first(int node) const { return first_[node]; }
  int count(int node) const { return count_[node]; }
  // "y.B": the unknown's name as history.csv spells it.
  std::string label(int dof) const {
    int node = 0;
    while (node + 1 < static_cast<int>(first_.size()) && first_[node + 1] <= dof) ++node;
    return std::string(1, "xyz"[dof - first_[node]]) + "." + labels_base_[node];
  }

 private:
  int n_dofs_ = 0;
  std::vector<int> first_, count_;
  std::vector<std::string> labels_base_;
};

}  // namespace deploydyn
