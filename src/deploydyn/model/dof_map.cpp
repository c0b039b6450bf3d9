#include "deploydyn/model/dof_map.hpp"

#include <algorithm>
#include <map>

#include "deploydyn/elements/element_kinds.hpp"

namespace deploydyn {

DofMap::DofMap(const Model& model) {
  std::vector<std::vector<std::string>> added(model.nodes.size());
  for (const ElementKind* kind : element_kinds()) kind->add_node_unknowns(model, added);

  std::vector<std::string> position;
  for (int axis = 0; axis < model.dimension; ++axis) position.emplace_back(1, "xyz"[axis]);
  std::map<std::vector<std::string>, int> set_index{{position, 0}};
  unknown_sets_.push_back(position);
  first_.reserve(model.nodes.size());
  set_of_node_.reserve(model.nodes.size());
  node_names_.reserve(model.nodes.size());
  for (std::size_t node = 0; node < model.nodes.size(); ++node) {
    first_.push_back(n_dofs_);
    node_names_.push_back(model.nodes[node].name);
    if (added[node].empty()) {  // the common case: a position only
      set_of_node_.push_back(0);
      n_dofs_ += model.dimension;
      continue;
    }
    std::vector<std::string> names = position;
    for (const std::string& name : added[node]) {
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    const auto [found, is_new] = set_index.emplace(names, static_cast<int>(unknown_sets_.size()));
    if (is_new) unknown_sets_.push_back(std::move(names));
    set_of_node_.push_back(found->second);
    n_dofs_ += static_cast<int>(unknown_sets_[found->second].size());
  }
}

int DofMap::index(int node, std::string_view unknown) const {
  const std::vector<std::string>& names = unknowns(node);
  const auto found = std::find(names.begin(), names.end(), unknown);
  return found == names.end() ? -1 : first_[node] + static_cast<int>(found - names.begin());
}

std::string DofMap::label(int dof) const {
  const auto after = std::upper_bound(first_.begin(), first_.end(), dof);
  const auto node = static_cast<int>(after - first_.begin()) - 1;
  return unknowns(node)[dof - first_[node]] + "." + node_names_[node];
}

}  // namespace deploydyn
