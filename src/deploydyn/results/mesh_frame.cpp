#include "deploydyn/results/mesh_frame.hpp"

#include <algorithm>
#include <limits>

namespace deploydyn {

MeshLayout::MeshLayout(const Model& model) : model_(model), dofs_(model), cells_(all_elements(model)) {
  const auto kinds = element_kinds();
  for (const ElementRef& cell : cells_) {
    group_of_cell_.push_back(static_cast<int>(std::find(kinds.begin(), kinds.end(), cell.kind) - kinds.begin()));
    for (int i = 0; i < cell.kind->n_element_nodes(); ++i) {
      connectivity_.push_back(cell.kind->element_node(model_, cell.index, i));
    }
    offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
  }
  for (const ElementKind* kind : kinds) {
    if (kind->n_elements(model_) == 0) continue;  // a bar-only model gets no beam arrays
    for (const ResultQuantity& quantity : kind->quantities(model_.dimension)) {
      if (quantity.recorded &&
          std::find(cell_arrays_.begin(), cell_arrays_.end(), quantity.name) == cell_arrays_.end()) {
        cell_arrays_.emplace_back(quantity.name);
      }
    }
  }
  for (const std::string& array : cell_arrays_) {
    std::vector<int>& indices = index_in_kind_.emplace_back();
    for (const ElementKind* kind : kinds) indices.push_back(quantity_index(*kind, model_.dimension, array));
  }
  cell_arrays_.emplace_back("temperature_change_C");
}

double MeshLayout::cell_value(const StepRecord& record, std::size_t array, int cell) const {
  const ElementRef& element = cells_[static_cast<std::size_t>(cell)];
  if (array == index_in_kind_.size()) return element.kind->temperature_change_C(model_, element.index, record.time_s);
  const auto group = static_cast<std::size_t>(group_of_cell_[static_cast<std::size_t>(cell)]);
  const int k = index_in_kind_[array][group];
  return k < 0 ? std::numeric_limits<double>::quiet_NaN() : record.elements[group].at(element.index, k);
}

bool MeshLayout::fits(const StepRecord& record) const {
  int n_results = 0;
  for (const ElementResults& results : record.elements) n_results += results.n_elements();
  return record.q.size() == dofs_.n_dofs() && record.v.size() == dofs_.n_dofs() &&
         record.elements.size() == element_kinds().size() && n_results == n_cells();
}

}  // namespace deploydyn
