#pragma once
// What path.csv holds after its own columns (runs/path_to_folder.hpp), and the Python
// continuation's "columns" and "values": at each point of a path, the columns history.csv would
// hold (results/history_layout.hpp, `output.select` applied: the nodes' positions, the
// elements' forces, strains, ..., the drivers' efforts, the supports' reactions), but for `t`
// (the path has its parameter) and the energies (a path's points are at rest and
// make_path_record gives no energies). One column builder for both files: HistoryLayout's.

#include <cstddef>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/results/history_layout.hpp"
#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn {

class PathQuantities {
 public:
  explicit PathQuantities(const Model& model);

  const std::vector<std::string>& columns() const { return columns_; }
  // Appends the record's values of columns(), in their order, to `row`.
  void append_row(const StepRecord& record, std::vector<double>& row) const;

 private:
  HistoryLayout layout_;
  std::vector<std::string> columns_;
  std::vector<std::size_t> kept_;    // of layout_.columns(): those of columns_
  mutable std::vector<double> full_;  // one history row, reused
};

}  // namespace deploydyn
