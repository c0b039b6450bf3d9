#include "deploydyn/assembly/sparse_linear_system.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "deploydyn/assembly/compressed_columns.hpp"

namespace deploydyn {
namespace {

// Held pairs (coordinate i, equation j): row j and column j each with one entry, at (j, i) and
// (i, j), i ≠ j, no unknown in two pairs. Found from the pattern alone.
std::vector<std::pair<int, int>> find_held_pairs(const CompressedColumns& whole) {
  const int size = static_cast<int>(whole.column_start.size()) - 1;
  std::vector<int> row_count(size, 0), last_column_in_row(size, -1);
  for (int col = 0; col < size; ++col) {
    for (int k = whole.column_start[col]; k < whole.column_start[col + 1]; ++k) {
      ++row_count[whole.row_index[k]];
      last_column_in_row[whole.row_index[k]] = col;
    }
  }
  std::vector<bool> paired(size, false);
  std::vector<std::pair<int, int>> pairs;
  for (int j = 0; j < size; ++j) {
    if (row_count[j] != 1 || whole.column_start[j + 1] - whole.column_start[j] != 1) continue;
    const int i = whole.row_index[whole.column_start[j]];
    if (i == j || last_column_in_row[j] != i || paired[i] || paired[j]) continue;
    paired[i] = paired[j] = true;
    pairs.emplace_back(i, j);
  }
  return pairs;
}

enum class Role { kept, coordinate, equation };

}  // namespace

void SparseLinearSystem::build_storage(std::span<const MatrixEntry> entries) {
  std::vector<int> whole_position;
  const CompressedColumns whole = compress(size_, entries, whole_position);

  std::vector<Role> role(size_, Role::kept);
  std::vector<int> pair_of(size_, -1);
  held_.clear();
  for (const auto& [i, j] : find_held_pairs(whole)) {
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

  // values_: the factored pattern's entries first (what the back end reads), then per pair the
  // held coordinate's column in the kept rows, then its row, then the pair's two entries. Each
  // coupling is contiguous, so that a solve streams through it.
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
  row_index_.shrink_to_fit();
  const int n_pairs = static_cast<int>(held_.size());
  held_column_.start.assign(n_pairs + 1, 0);
  held_row_.start.assign(n_pairs + 1, 0);
  // Every entry off the factored pattern, with what it is: a pair's own entry, or one of a held
  // coordinate's row (any column but its equation's) or column (a kept row).
  enum class Held { pivot, partner, in_row, in_column };
  auto for_each_held_entry = [&](auto&& visit) {
    for (int col = 0; col < size_; ++col) {
      for (int k = whole.column_start[col]; k < whole.column_start[col + 1]; ++k) {
        const int row = whole.row_index[k];
        if (role[row] == Role::kept && role[col] == Role::kept) continue;
        const Held held = role[row] == Role::equation       ? Held::pivot
                          : role[col] == Role::equation     ? Held::partner
                          : role[row] == Role::coordinate ? Held::in_row
                                                            : Held::in_column;
        visit(k, row, col, held);
      }
    }
  };
  for_each_held_entry([&](int, int row, int col, Held held) {
    if (held == Held::in_row) ++held_row_.start[pair_of[row] + 1];
    if (held == Held::in_column) ++held_column_.start[pair_of[col] + 1];
  });
  held_column_.start[0] = static_cast<int>(row_index_.size());
  std::partial_sum(held_column_.start.begin(), held_column_.start.end(), held_column_.start.begin());
  held_row_.start[0] = held_column_.start.back();
  std::partial_sum(held_row_.start.begin(), held_row_.start.end(), held_row_.start.begin());
  held_column_.index.resize(held_column_.start.back() - held_column_.start.front());
  held_row_.index.resize(held_row_.start.back() - held_row_.start.front());
  std::vector<int> next_in_column(held_column_.start.begin(), held_column_.start.end() - 1);
  std::vector<int> next_in_row(held_row_.start.begin(), held_row_.start.end() - 1);
  for_each_held_entry([&](int k, int row, int col, Held held) {
    switch (held) {
      case Held::pivot: place[k] = pivot_slot(pair_of[row]); break;
      case Held::partner: place[k] = partner_slot(pair_of[col]); break;
      case Held::in_row:
        place[k] = next_in_row[pair_of[row]]++;
        held_row_.index[place[k] - held_row_.start.front()] = col;
        break;
      case Held::in_column:
        place[k] = next_in_column[pair_of[col]]++;
        held_column_.index[place[k] - held_column_.start.front()] = factored_index[row];
        break;
    }
  });
  for (int k = 0; k < static_cast<int>(entries.size()); ++k) slots_[k] = place[whole_position[k]];
  values_.assign(held_row_.start.back() + 2 * held_.size(), 0.0);
  factored_rhs_.resize(factored_size());
  held_value_.resize(n_pairs);
  held_balance_.resize(n_pairs);
  if (factored_size() > 0) analyze_pattern();  // none when every coordinate is held
}

MatrixEntry SparseLinearSystem::position(int value_index) const {
  // The pair whose run in `runs` holds value_index.
  auto pair_in = [&](const HeldRuns& runs) {
    return static_cast<int>(std::upper_bound(runs.start.begin(), runs.start.end(), value_index) - runs.start.begin()) - 1;
  };
  if (value_index < held_column_.start.front()) {
    const auto col = std::upper_bound(column_start_.begin(), column_start_.end(), value_index) -
                     column_start_.begin() - 1;
    return {kept_[row_index_[value_index]], kept_[col]};
  }
  if (value_index < held_row_.start.front()) {
    const HeldPair& pair = held_[pair_in(held_column_)];
    return {kept_[held_column_.index[value_index - held_column_.start.front()]], pair.coordinate};
  }
  if (value_index < held_row_.start.back()) {
    const HeldPair& pair = held_[pair_in(held_row_)];
    return {pair.coordinate, held_row_.index[value_index - held_row_.start.front()]};
  }
  const int offset = value_index - held_row_.start.back();  // pivot_slot, partner_slot
  const HeldPair& pair = held_[offset / 2];
  return offset % 2 == 0 ? MatrixEntry{pair.equation, pair.coordinate} : MatrixEntry{pair.coordinate, pair.equation};
}

FactorizationStatus SparseLinearSystem::factorize_finite() {
  // A zero pivot leaves row j (or column j) empty: the whole matrix is singular.
  for (int p = 0; p < static_cast<int>(held_.size()); ++p) {
    if (values_[pivot_slot(p)] != 0.0 && values_[partner_slot(p)] != 0.0) continue;
    FactorizationStatus status = singular(0.0);
    // Too large for an SVD: name the pair's equation (its constraint is degenerate).
    if (status.null_vectors.size() == 0) status.null_vectors = Eigen::VectorXd::Unit(size_, held_[p].equation);
    return status;
  }
  return factored_size() > 0 ? factorize_pattern() : FactorizationStatus{};
}

// docs/theory.md, Eqs. (H1)–(H3): the held coordinates from their rows, the kept unknowns from
// the factored system with the held columns moved to the right-hand side, then the held
// equations' unknowns from the held coordinates' rows.
void SparseLinearSystem::solve(Eigen::Ref<Eigen::VectorXd> rhs) {
  if (held_.empty()) {
    if (factored_size() > 0) solve_pattern(rhs.data());
    return;
  }
  const int n_pairs = static_cast<int>(held_.size());
  for (int p = 0; p < n_pairs; ++p) {
    held_value_[p] = rhs[held_[p].equation] / values_[pivot_slot(p)];
    held_balance_[p] = rhs[held_[p].coordinate];
  }
  for (int f = 0; f < factored_size(); ++f) factored_rhs_[f] = rhs[kept_[f]];
  const int first_in_column = held_column_.start.front();
  for (int p = 0; p < n_pairs; ++p) {
    const double x = held_value_[p];
    if (x == 0.0) continue;  // the coordinate is where its constraint holds it: Newton's usual case
    for (int slot = held_column_.start[p]; slot < held_column_.start[p + 1]; ++slot) {
      factored_rhs_[held_column_.index[slot - first_in_column]] -= values_[slot] * x;
    }
  }
  if (factored_size() > 0) solve_pattern(factored_rhs_.data());
  for (int f = 0; f < factored_size(); ++f) rhs[kept_[f]] = factored_rhs_[f];
  for (int p = 0; p < n_pairs; ++p) rhs[held_[p].coordinate] = held_value_[p];
  const int first_in_row = held_row_.start.front();
  for (int p = 0; p < n_pairs; ++p) {
    double balance = held_balance_[p];
    for (int slot = held_row_.start[p]; slot < held_row_.start[p + 1]; ++slot) {
      balance -= values_[slot] * rhs[held_row_.index[slot - first_in_row]];
    }
    rhs[held_[p].equation] = balance / values_[partner_slot(p)];
  }
}

}  // namespace deploydyn
