#include "deploydyn/assembly/sparse_linear_system.hpp"

#include <algorithm>
#include <numeric>

namespace deploydyn {
namespace {

// The whole pattern in compressed columns, before the held pairs are taken out.
struct CompressedColumns {
  std::vector<int> column_start;  // size + 1
  std::vector<int> row_index;
};

// Buckets the entries by column (counting sort), then sorts each column's few rows:
// O(entries). entry_position[k] becomes entry k's place in row_index (repeats share one).
CompressedColumns compress(int size, std::span<const MatrixEntry> entries, std::vector<int>& entry_position) {
  std::vector<int> bucket_start(size + 1, 0);
  for (const MatrixEntry& e : entries) ++bucket_start[e.col + 1];
  std::partial_sum(bucket_start.begin(), bucket_start.end(), bucket_start.begin());
  std::vector<int> by_column(entries.size());
  {
    std::vector<int> next(bucket_start.begin(), bucket_start.end() - 1);
    for (int k = 0; k < static_cast<int>(entries.size()); ++k) by_column[next[entries[k].col]++] = k;
  }
  CompressedColumns pattern;
  pattern.column_start.assign(size + 1, 0);
  pattern.row_index.reserve(entries.size() / 2);
  entry_position.assign(entries.size(), 0);
  for (int col = 0; col < size; ++col) {
    const auto first = by_column.begin() + bucket_start[col];
    const auto last = by_column.begin() + bucket_start[col + 1];
    std::sort(first, last, [&](int a, int b) { return entries[a].row < entries[b].row; });
    for (auto k = first; k != last; ++k) {
      if (k == first || entries[*k].row != entries[*(k - 1)].row) pattern.row_index.push_back(entries[*k].row);
      entry_position[*k] = static_cast<int>(pattern.row_index.size()) - 1;
    }
    pattern.column_start[col + 1] = static_cast<int>(pattern.row_index.size());
  }
  return pattern;
}

enum class Role { kept, coordinate, equation };

}  // namespace

void SparseLinearSystem::build_storage(std::span<const MatrixEntry> entries) {
  std::vector<int> whole_position;
  const CompressedColumns whole = compress(size_, entries, whole_position);

  // Held pairs: row j and column j each with one entry, at (j, i) and (i, j), i ≠ j.
  std::vector<int> row_count(size_, 0), last_column_in_row(size_, -1);
  for (int col = 0; col < size_; ++col) {
    for (int k = whole.column_start[col]; k < whole.column_start[col + 1]; ++k) {
      ++row_count[whole.row_index[k]];
      last_column_in_row[whole.row_index[k]] = col;
    }
  }
  std::vector<Role> role(size_, Role::kept);
  std::vector<int> pair_of(size_, -1);
  held_.clear();
  for (int j = 0; j < size_; ++j) {
    if (row_count[j] != 1 || whole.column_start[j + 1] - whole.column_start[j] != 1) continue;
    const int i = whole.row_index[whole.column_start[j]];
    if (i == j || last_column_in_row[j] != i || role[i] != Role::kept || role[j] != Role::kept) continue;
    role[i] = Role::coordinate;
    role[j] = Role::equation;
    pair_of[i] = pair_of[j] = static_cast<int>(held_.size());
    held_.push_back({.coordinate = i, .equation = j});
  }
  kept_.clear();
  std::vector<int> factored_index(size_, -1);
  for (int u = 0; u < size_; ++u) {
    if (role[u] != Role::kept) continue;
    factored_index[u] = static_cast<int>(kept_.size());
    kept_.push_back(u);
  }

  // values_: the factored pattern's entries first (what the back end reads), then the rest.
  std::vector<int> place(whole.row_index.size(), -1);
  column_start_.assign(kept_.size() + 1, 0);
  row_index_.clear();
  for (int f = 0; f < factored_size(); ++f) {
    const int col = kept_[f];
    for (int k = whole.column_start[col]; k < whole.column_start[col + 1]; ++k) {
      const int row = whole.row_index[k];
      if (role[row] != Role::kept) continue;
      place[k] = static_cast<int>(row_index_.size());
      row_index_.push_back(factored_index[row]);
    }
    column_start_[f + 1] = static_cast<int>(row_index_.size());
  }
  held_positions_.clear();
  column_couplings_.clear();
  row_couplings_.clear();
  for (int col = 0; col < size_; ++col) {
    for (int k = whole.column_start[col]; k < whole.column_start[col + 1]; ++k) {
      if (place[k] >= 0) continue;
      const int row = whole.row_index[k];
      const int slot = static_cast<int>(row_index_.size() + held_positions_.size());
      place[k] = slot;
      held_positions_.push_back({row, col});
      if (role[row] == Role::equation) {
        held_[pair_of[row]].pivot = slot;
      } else if (role[col] == Role::equation) {
        held_[pair_of[col]].partner = slot;
      } else if (role[row] == Role::coordinate) {
        row_couplings_.push_back({slot, col, pair_of[row]});
      } else {
        column_couplings_.push_back({slot, factored_index[row], pair_of[col]});
      }
    }
  }
  for (int k = 0; k < static_cast<int>(entries.size()); ++k) slots_[k] = place[whole_position[k]];
  row_index_.shrink_to_fit();
  values_.assign(row_index_.size() + held_positions_.size(), 0.0);
  factored_rhs_.resize(factored_size());
  held_value_.resize(static_cast<Eigen::Index>(held_.size()));
  held_balance_.resize(static_cast<Eigen::Index>(held_.size()));
  if (factored_size() > 0) analyze_pattern();  // none when every coordinate is held
}

MatrixEntry SparseLinearSystem::position(int value_index) const {
  const int factored_entries = static_cast<int>(row_index_.size());
  if (value_index >= factored_entries) return held_positions_[value_index - factored_entries];
  const auto col = std::upper_bound(column_start_.begin(), column_start_.end(), value_index) -
                   column_start_.begin() - 1;
  return {kept_[row_index_[value_index]], kept_[col]};
}

FactorizationStatus SparseLinearSystem::factorize_finite() {
  // A zero pivot leaves row j (or column j) empty: the whole matrix is singular.
  for (const HeldPair& pair : held_) {
    if (values_[pair.pivot] == 0.0 || values_[pair.partner] == 0.0) return singular(0.0);
  }
  return factored_size() > 0 ? factorize_pattern() : FactorizationStatus{};
}

// docs/theory.md, Eq. (H1)-(H3): the held coordinates from their rows, the kept unknowns from the
// factored system with the held columns moved to the right-hand side, then the held equations'
// unknowns from the held coordinates' rows.
void SparseLinearSystem::solve(Eigen::Ref<Eigen::VectorXd> rhs) {
  if (held_.empty()) {
    solve_pattern(rhs.data());
    return;
  }
  for (std::size_t p = 0; p < held_.size(); ++p) {
    held_value_[p] = rhs[held_[p].equation] / values_[held_[p].pivot];
    held_balance_[p] = rhs[held_[p].coordinate];
  }
  for (int f = 0; f < factored_size(); ++f) factored_rhs_[f] = rhs[kept_[f]];
  for (const Coupling& c : column_couplings_) factored_rhs_[c.index] -= values_[c.slot] * held_value_[c.pair];
  if (factored_size() > 0) solve_pattern(factored_rhs_.data());
  for (int f = 0; f < factored_size(); ++f) rhs[kept_[f]] = factored_rhs_[f];
  for (std::size_t p = 0; p < held_.size(); ++p) rhs[held_[p].coordinate] = held_value_[p];
  for (const Coupling& c : row_couplings_) held_balance_[c.pair] -= values_[c.slot] * rhs[c.index];
  for (std::size_t p = 0; p < held_.size(); ++p) {
    rhs[held_[p].equation] = held_balance_[p] / values_[held_[p].partner];
  }
}

}  // namespace deploydyn
