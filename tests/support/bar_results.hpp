#pragma once
// A record's bar results as named fields, for tests that check bars (the record keeps every
// element type's results by quantity: solvers/step_record.hpp).

#include <algorithm>
#include <vector>

#include "deploydyn/elements/bar/bar_kind.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn {

struct BarResult {
  double strain = 0.0;             // total Green–Lagrange
  double mechanical_strain = 0.0;  // total − thermal
  double axial_force_N = 0.0;      // true axial force, tension positive
  double length_m = 0.0;
};

inline std::vector<BarResult> bar_results(const StepRecord& record) {
  const auto kinds = element_kinds();
  const auto g =
      static_cast<std::size_t>(std::find(kinds.begin(), kinds.end(), &bar_kind()) - kinds.begin());
  const ElementResults& results = record.elements.at(g);
  const ElementKind& bar = bar_kind();
  std::vector<BarResult> bars;
  for (int e = 0; e < results.n_elements(); ++e) {
    bars.push_back({results.at(e, quantity_index(bar, record.dimension, "strain")),
                    results.at(e, quantity_index(bar, record.dimension, "mechanical_strain")),
                    results.at(e, quantity_index(bar, record.dimension, "axial_force_N")),
                    results.at(e, quantity_index(bar, record.dimension, "length_m"))});
  }
  return bars;
}

}  // namespace deploydyn
