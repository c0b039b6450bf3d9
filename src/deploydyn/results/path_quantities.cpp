#include "deploydyn/results/path_quantities.hpp"

namespace deploydyn {

PathQuantities::PathQuantities(const Model& model) : layout_(model) {
  const std::vector<std::string>& all = layout_.columns();
  for (std::size_t c = 0; c < all.size(); ++c) {
    // Every per-item column is "<key>.<item>"; `t` and the four energies have no dot.
    if (all[c].find('.') == std::string::npos) continue;
    kept_.push_back(c);
    columns_.push_back(all[c]);
  }
}

void PathQuantities::append_row(const StepRecord& record, std::vector<double>& row) const {
  full_.clear();
  layout_.append_row(record, full_);
  for (const std::size_t c : kept_) row.push_back(full_[c]);
}

}  // namespace deploydyn
