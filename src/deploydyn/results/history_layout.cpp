#include "deploydyn/results/history_layout.hpp"

#include <fmt/format.h>
#include <fnmatch.h>

#include <algorithm>
#include <stdexcept>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/dof_map.hpp"

namespace deploydyn {
namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};

// One column a model could give: its name, family, and the node or element it belongs to.
struct Column {
  std::string name;
  std::string family;
  int node = -1;
  int element = -1;  // in the order of all_elements
};

// Every column, in the order of the full row (HistoryLayout::append_row).
std::vector<Column> all_columns(const Model& model) {
  std::vector<Column> columns{{"t", "t"}};
  const DofMap dofs(model);
  for (int node = 0; node < model.n_nodes(); ++node) {
    for (int k = 0; k < dofs.count(node); ++k) {
      columns.push_back({dofs.label(dofs.first(node) + k), "position", node});
    }
  }
  for (int node = 0; node < model.n_nodes(); ++node) {
    for (int axis = 0; axis < model.dimension; ++axis) {
      columns.push_back({fmt::format("u{}.{}", kAxes[axis], model.nodes[node].name), "displacement", node});
    }
  }
  const std::vector<ElementRef> elements = all_elements(model);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    for (const ResultQuantity& quantity : elements[e].kind->quantities(model.dimension)) {
      if (!quantity.recorded) continue;
      columns.push_back({std::string(quantity.key) + "." + elements[e].kind->element_name(model, elements[e].index),
                         std::string(quantity.key), -1, static_cast<int>(e)});
    }
  }
  for (const Driver& driver : model.drivers) {
    columns.push_back({(drives_rotation(driver.kind) ? "torque." : "force.") + driver.name, "driver"});
  }
  for (const char* energy : {"kinetic", "strain_energy", "external_work", "dissipated"}) {
    columns.push_back({energy, "energy"});
  }
  for (std::string& label : reaction_labels(model)) columns.push_back({std::move(label), "reaction"});
  return columns;
}

// The families of a model without a choice: the paper's columns and the reactions.
bool in_default(const Model& model, const std::string& family) {
  if (family == "displacement") return false;
  for (const ElementKind* kind : element_kinds()) {
    for (const ResultQuantity& quantity : kind->quantities(model.dimension)) {
      if (quantity.key == family && !quantity.by_default) return false;
    }
  }
  return true;
}

// Whether every unknown of the node is held by a support: its position never changes.
std::vector<bool> fixed_nodes(const Model& model) {
  std::vector<bool> fixed(static_cast<std::size_t>(model.n_nodes()), false);
  const DofMap dofs(model);
  for (const FixedNode& support : model.supports) {
    bool all = true;
    for (int axis = 0; axis < model.dimension; ++axis) all = all && support.axes[axis];
    if (dofs.count(support.node) > model.dimension && !support.rotation) all = false;
    if (all) fixed[static_cast<std::size_t>(support.node)] = true;
  }
  return fixed;
}

// The items `patterns` choose among `names` (every one for "all", none for "none", the nodes
// not fixed for "moving").
std::vector<bool> chosen(const std::vector<std::string>& patterns, const std::vector<std::string>& names,
                         const std::vector<bool>& fixed) {
  std::vector<bool> out(names.size(), patterns.empty());
  for (const std::string& pattern : patterns) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (pattern == kAllWord || (pattern == kMovingWord && !fixed[i]) || name_matches(pattern, names[i])) {
        out[i] = true;
      }
    }
  }
  return out;
}

std::vector<std::string> node_names(const Model& model) {
  std::vector<std::string> names;
  for (const Node& node : model.nodes) names.push_back(node.name);
  return names;
}

}  // namespace

std::vector<std::string> history_families(const Model& model) {
  std::vector<std::string> families{"position", "displacement"};
  for (const ElementKind* kind : element_kinds()) {
    if (kind->n_elements(model) == 0) continue;
    for (const ResultQuantity& quantity : kind->quantities(model.dimension)) {
      const std::string key(quantity.key);
      if (quantity.recorded && std::find(families.begin(), families.end(), key) == families.end()) {
        families.push_back(key);
      }
    }
  }
  for (const char* family : {"driver", "energy", "reaction"}) families.emplace_back(family);
  return families;
}

bool name_matches(const std::string& pattern, const std::string& name) {
  return fnmatch(pattern.c_str(), name.c_str(), 0) == 0;
}

std::vector<std::string> reaction_labels(const Model& model) {
  std::vector<std::string> labels;
  for (const FixedNode& support : model.supports) {
    const std::string& node = model.nodes[support.node].name;
    for (int axis = 0; axis < model.dimension; ++axis) {
      if (support.axes[axis]) labels.push_back(fmt::format("reaction.{}.{}", node, kAxes[axis]));
    }
    if (support.rotation && model.dimension == 2) labels.push_back(fmt::format("reaction.{}.rz", node));
  }
  return labels;
}

HistoryLayout::HistoryLayout(const Model& model) {
  const std::vector<Column> all = all_columns(model);
  n_full_ = all.size();
  const DofMap dofs(model);
  for (int node = 0; node < model.n_nodes(); ++node) {
    for (int axis = 0; axis < model.dimension; ++axis) {
      position_dofs_.push_back(dofs.index(node, axis));
      initial_m_.push_back(model.nodes[node].position_m[axis]);
    }
  }

  OutputSelection select = model.output.select;
  const std::vector<std::string> families = history_families(model);
  selection_ = select.empty() ? "default" : "output.select";
  if (select.quantities.empty()) {
    for (const std::string& family : families) {
      if (in_default(model, family)) select.quantities.push_back(family);
    }
  }
  if (model.output.select.empty()) {
    const auto n_default = std::count_if(all.begin(), all.end(), [&](const Column& c) {
      return c.family == "t" ||
             std::find(select.quantities.begin(), select.quantities.end(), c.family) != select.quantities.end();
    });
    if (static_cast<std::size_t>(n_default) > kLargeHistoryColumns) {
      select.nodes = {std::string(kMovingWord)};
      select.quantities = {"position", "force", "driver", "energy"};
      selection_ = "large model default";
      note_ = fmt::format(
          "history.csv: this model's full history has {} columns, so it holds the positions of the "
          "nodes that move, the elements' forces, the drivers and energies (envelopes.csv has every "
          "quantity's extremes, reactions included); choose otherwise with output.select "
          "(docs/model-format.md)",
          n_default);
    }
  }

  const std::vector<bool> fixed = fixed_nodes(model);
  const std::vector<bool> nodes = chosen(select.nodes, node_names(model), fixed);
  const std::vector<std::string> element_list = element_names(model);
  const std::vector<bool> elements = chosen(select.elements, element_list, std::vector<bool>(element_list.size()));
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Column& c = all[i];
    const bool family = c.family == "t" || std::find(select.quantities.begin(), select.quantities.end(),
                                                     c.family) != select.quantities.end();
    if (!family) continue;
    if (c.node >= 0 && !nodes[static_cast<std::size_t>(c.node)]) continue;
    if (c.element >= 0 && !elements[static_cast<std::size_t>(c.element)]) continue;
    columns_.push_back(c.name);
    picks_.push_back(i);
  }
}

void HistoryLayout::append_row(const StepRecord& r, std::vector<double>& row) const {
  // Walks the full row in its order and keeps the picked columns (picks_ ascend): no full row
  // is built, so no allocation per row.
  const std::size_t n_before = row.size();
  std::size_t i = 0;
  auto pick = picks_.begin();
  const auto take = [&](double value) {
    if (pick != picks_.end() && *pick == i) {
      row.push_back(value);
      ++pick;
    }
    ++i;
  };
  take(r.time_s);
  for (const double value : r.q) take(value);
  for (std::size_t k = 0; k < position_dofs_.size(); ++k) take(r.q[position_dofs_[k]] - initial_m_[k]);
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < r.elements.size(); ++g) {
    const auto quantities = kinds[g]->quantities(r.dimension);
    const ElementResults& results = r.elements[g];
    for (int e = 0; e < results.n_elements(); ++e) {
      for (int k = 0; k < results.n_quantities; ++k) {
        if (quantities[static_cast<std::size_t>(k)].recorded) take(results.at(e, k));
      }
    }
  }
  for (const double value : r.driver_efforts) take(value);
  for (const double value : {r.kinetic_energy_J, r.strain_energy_J, r.external_work_J, r.dissipated_J}) take(value);
  for (const double value : r.reactions) take(value);
  if (i != n_full_) {
    row.resize(n_before);
    throw std::invalid_argument(fmt::format("history row: the record gives {} values, the model {}", i, n_full_));
  }
}

}  // namespace deploydyn
