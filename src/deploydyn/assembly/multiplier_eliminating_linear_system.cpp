#include "deploydyn/assembly/multiplier_eliminating_linear_system.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include "deploydyn/assembly/compressed_columns.hpp"

namespace deploydyn {
namespace {

// A group whose rows s B_C have a pivot this small against their largest is degenerate (its
// rows dependent): the whole matrix is singular then.
constexpr double kDegenerateGroup = 1e-14;

// The set of each coordinate, joined through the multipliers that reach several.
struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int root(int u) {
    while (parent[u] != u) u = parent[u] = parent[parent[u]];
    return u;
  }
  void join(int a, int b) { parent[root(a)] = root(b); }
};

}  // namespace

MultiplierEliminatingLinearSystem::MultiplierEliminatingLinearSystem(std::unique_ptr<KluLinearSystem> factored)
    : factored_(std::move(factored)) {
  // A singular reduced matrix is reported with this matrix's null vectors (singular()).
  factored_->defer_null_vectors(true);
}

void MultiplierEliminatingLinearSystem::build_storage(std::span<const MatrixEntry> entries) {
  const CompressedColumns whole = compress(size_, entries, slots_);
  positions_.clear();
  positions_.reserve(whole.row_index.size());
  std::vector<char> has_diagonal(size_, 0);
  std::vector<std::vector<int>> row_columns(size_);
  for (int col = 0; col < size_; ++col) {
    for (int k = whole.column_start[col]; k < whole.column_start[col + 1]; ++k) {
      const int row = whole.row_index[k];
      positions_.push_back({row, col});
      if (row == col) has_diagonal[col] = 1;
      row_columns[row].push_back(col);  // ascending, as columns come
    }
  }
  values_.assign(positions_.size(), 0.0);

  // Multipliers: no diagonal, two or more entries, all on unknowns with a diagonal, the row's
  // pattern the column's (s B and s Bᵀ).
  const auto column_rows = [&](int u) {
    return std::span<const int>(whole.row_index.data() + whole.column_start[u],
                                static_cast<std::size_t>(whole.column_start[u + 1] - whole.column_start[u]));
  };
  std::vector<char> is_multiplier(size_, 0);
  DisjointSets sets(size_);
  for (int u = 0; u < size_; ++u) {
    const std::span<const int> rows = column_rows(u);
    if (has_diagonal[u] || rows.size() < 2 || rows.size() > static_cast<std::size_t>(kMax)) continue;
    if (!std::equal(rows.begin(), rows.end(), row_columns[u].begin(), row_columns[u].end())) continue;
    if (!std::all_of(rows.begin(), rows.end(), [&](int r) { return has_diagonal[r] != 0; })) continue;
    is_multiplier[u] = 1;
    for (const int r : rows) sets.join(r, rows[0]);
  }
  // The groups, by the set of their coordinates; those too large stay in the reduced matrix.
  std::unordered_map<int, int> group_of_root;
  std::vector<Group> candidates;
  for (int u = 0; u < size_; ++u) {
    if (!is_multiplier[u]) continue;
    const int root = sets.root(column_rows(u)[0]);
    const auto [at, added] = group_of_root.try_emplace(root, static_cast<int>(candidates.size()));
    if (added) candidates.emplace_back();
    candidates[at->second].multipliers.push_back(u);
  }
  for (int u = 0; u < size_; ++u) {
    if (is_multiplier[u] || !has_diagonal[u]) continue;
    const auto at = group_of_root.find(sets.root(u));
    if (at != group_of_root.end()) candidates[at->second].coordinates.push_back(u);
  }
  enum class Role : char { plain, coordinate, multiplier };
  std::vector<Role> role(size_, Role::plain);
  std::vector<int> group_of(size_, -1), local(size_, -1);
  groups_.clear();
  for (Group& g : candidates) {
    if (g.n() > kMax || g.m() > g.n()) continue;
    const int index = static_cast<int>(groups_.size());
    for (int a = 0; a < g.n(); ++a) {
      role[g.coordinates[a]] = Role::coordinate;
      group_of[g.coordinates[a]] = index;
      local[g.coordinates[a]] = a;
    }
    for (int e = 0; e < g.m(); ++e) {
      role[g.multipliers[e]] = Role::multiplier;
      group_of[g.multipliers[e]] = index;
      local[g.multipliers[e]] = e;
    }
    g.rows.assign(static_cast<std::size_t>(g.m() * g.n()), -1);
    groups_.push_back(std::move(g));
  }
  // The reduced unknowns in the whole matrix's order, a group's where its first coordinate is.
  plain_of_.assign(size_, -1);
  int n_reduced = 0, n_local = 0;
  for (int u = 0; u < size_; ++u) {
    if (role[u] == Role::plain) {
      plain_of_[u] = n_reduced++;
    } else if (role[u] == Role::coordinate && local[u] == 0) {
      Group& g = groups_[group_of[u]];
      g.first_reduced = n_reduced;
      g.first_local = n_local;
      n_reduced += g.kept();
      n_local += g.n();
    }
  }

  std::vector<MatrixEntry> reduced;
  const auto add = [&](int row, int col) {
    reduced.push_back({row, col});
    return static_cast<int>(reduced.size()) - 1;
  };
  plain_entries_.clear();
  plain_row_group_columns_.clear();
  group_rows_plain_column_.clear();
  group_blocks_.clear();
  std::unordered_map<std::int64_t, int> plain_row_at, plain_column_at, block_at;
  const std::int64_t n_groups = static_cast<std::int64_t>(groups_.size()) + 1;
  const auto pair_key = [&](std::int64_t first, int group) { return first * n_groups + group; };
  for (int p = 0; p < static_cast<int>(positions_.size()); ++p) {
    const auto [row, col] = positions_[p];
    const Role row_role = role[row], col_role = role[col];
    if (row_role == Role::multiplier || col_role == Role::multiplier) {
      // s B_C and s B_Cᵀ of the group's own coordinates, nothing else: found so above.
      const bool own = group_of[row] == group_of[col] && row_role != col_role;
      if (!own) throw std::logic_error("a group's multiplier meets an unknown outside its coordinates");
      if (row_role == Role::multiplier) {
        Group& g = groups_[group_of[row]];
        g.rows[local[row] + g.m() * local[col]] = p;
      }
      continue;
    }
    if (row_role == Role::plain && col_role == Role::plain) {
      plain_entries_.push_back({p, add(plain_of_[row], plain_of_[col])});
    } else if (row_role == Role::plain) {
      const int g = group_of[col];
      const auto [at, added] =
          plain_row_at.try_emplace(pair_key(plain_of_[row], g), static_cast<int>(plain_row_group_columns_.size()));
      if (added) {
        PlainRowGroupColumns e{plain_of_[row], g, {}, {}};
        e.values.fill(-1);
        for (int l = 0; l < groups_[g].kept(); ++l) e.slots[l] = add(plain_of_[row], groups_[g].first_reduced + l);
        plain_row_group_columns_.push_back(e);
      }
      plain_row_group_columns_[at->second].values[local[col]] = p;
    } else if (col_role == Role::plain) {
      const int g = group_of[row];
      const auto [at, added] =
          plain_column_at.try_emplace(pair_key(plain_of_[col], g), static_cast<int>(group_rows_plain_column_.size()));
      if (added) {
        GroupRowsPlainColumn e{g, plain_of_[col], {}, {}};
        e.values.fill(-1);
        for (int k = 0; k < groups_[g].kept(); ++k) e.slots[k] = add(groups_[g].first_reduced + k, plain_of_[col]);
        group_rows_plain_column_.push_back(e);
      }
      group_rows_plain_column_[at->second].values[local[row]] = p;
    } else {
      const int rg = group_of[row], cg = group_of[col];
      const auto [at, added] = block_at.try_emplace(pair_key(rg, cg), static_cast<int>(group_blocks_.size()));
      if (added) {
        GroupBlock e{rg, cg, {}, {}};
        e.values.fill(-1);
        for (int k = 0; k < groups_[rg].kept(); ++k) {
          for (int l = 0; l < groups_[cg].kept(); ++l) {
            e.slots[k + kMax * l] = add(groups_[rg].first_reduced + k, groups_[cg].first_reduced + l);
          }
        }
        group_blocks_.push_back(e);
      }
      group_blocks_[at->second].values[local[row] + kMax * local[col]] = p;
    }
  }
  factored_->analyze(n_reduced, reduced);
  const std::span<const int> slot = factored_->slots();
  for (auto& e : plain_entries_) e.slot = slot[e.slot];
  for (auto& e : plain_row_group_columns_) {
    for (int l = 0; l < groups_[e.group].kept(); ++l) e.slots[l] = slot[e.slots[l]];
  }
  for (auto& e : group_rows_plain_column_) {
    for (int k = 0; k < groups_[e.group].kept(); ++k) e.slots[k] = slot[e.slots[k]];
  }
  for (auto& e : group_blocks_) {
    for (int k = 0; k < groups_[e.row_group].kept(); ++k) {
      for (int l = 0; l < groups_[e.column_group].kept(); ++l) e.slots[k + kMax * l] = slot[e.slots[k + kMax * l]];
    }
  }
  basis_.resize(groups_.size());
  triangle_.resize(groups_.size());
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    basis_[g] = Block::Identity(groups_[g].n(), groups_[g].n());
    triangle_[g] = Block::Identity(groups_[g].m(), groups_[g].m());
  }
  reduced_rhs_.resize(n_reduced);
  particular_.resize(n_local);
  balance_.resize(n_local);
  solution_.resize(n_local);
}

MultiplierEliminatingLinearSystem::Column MultiplierEliminatingLinearSystem::gather(const std::array<int, kMax>& at,
                                                                                    int n) const {
  Column c(n);
  for (int i = 0; i < n; ++i) c[i] = at[i] >= 0 ? values_[at[i]] : 0.0;
  return c;
}

MultiplierEliminatingLinearSystem::Block MultiplierEliminatingLinearSystem::gather(
    const std::array<int, kMax * kMax>& at, int rows, int cols) const {
  Block b(rows, cols);
  for (int j = 0; j < cols; ++j) {
    for (int i = 0; i < rows; ++i) b(i, j) = at[i + kMax * j] >= 0 ? values_[at[i + kMax * j]] : 0.0;
  }
  return b;
}

FactorizationStatus MultiplierEliminatingLinearSystem::factorize_finite() {
  // Q and R of each group's (s B_C)ᵀ = Q [R; 0] (Eq. F2): Q's last kept() columns are N.
  Eigen::HouseholderQR<Block> qr;
  Block transposed_rows;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    const Group& group = groups_[g];
    transposed_rows.resize(group.n(), group.m());
    for (int a = 0; a < group.n(); ++a) {
      for (int e = 0; e < group.m(); ++e) {
        const int at = group.rows[e + group.m() * a];
        transposed_rows(a, e) = at >= 0 ? values_[at] : 0.0;
      }
    }
    qr.compute(transposed_rows);
    basis_[g] = qr.householderQ();
    triangle_[g] = qr.matrixQR().topRows(group.m()).triangularView<Eigen::Upper>();
    const auto pivots = triangle_[g].diagonal().cwiseAbs();
    if (!(pivots.minCoeff() > kDegenerateGroup * pivots.maxCoeff())) return singular(0.0);
  }
  // Tᵀ K T over the unknowns that stay (Eq. F3).
  factored_->set_zero();
  const std::span<double> reduced = factored_->values();
  for (const PlainEntry& e : plain_entries_) reduced[e.slot] += values_[e.value];
  for (const PlainRowGroupColumns& e : plain_row_group_columns_) {
    const Column share = null_space(e.group).transpose().lazyProduct(gather(e.values, groups_[e.group].n()));
    for (int l = 0; l < share.size(); ++l) reduced[e.slots[l]] += share[l];
  }
  for (const GroupRowsPlainColumn& e : group_rows_plain_column_) {
    const Column share = null_space(e.group).transpose().lazyProduct(gather(e.values, groups_[e.group].n()));
    for (int k = 0; k < share.size(); ++k) reduced[e.slots[k]] += share[k];
  }
  for (const GroupBlock& e : group_blocks_) {
    // Coefficient by coefficient (lazyProduct): at these sizes Eigen's blocked product costs more.
    const Block right = gather(e.values, groups_[e.row_group].n(), groups_[e.column_group].n())
                            .lazyProduct(null_space(e.column_group));
    const Block share = null_space(e.row_group).transpose().lazyProduct(right);
    for (int l = 0; l < share.cols(); ++l) {
      for (int k = 0; k < share.rows(); ++k) reduced[e.slots[k + kMax * l]] += share(k, l);
    }
  }
  const FactorizationStatus status = factored_->factorize();
  if (status.ok) return status;
  FactorizationStatus whole = singular(status.reciprocal_condition);
  if (whole.null_vectors.size() == 0 && status.null_vectors.cols() == 1) {
    // KLU's first zero pivot, as this matrix's unknown.
    Eigen::Index pivot = 0;
    status.null_vectors.col(0).cwiseAbs().maxCoeff(&pivot);
    int unknown = 0;
    for (int u = 0; u < size_; ++u) {
      if (plain_of_[u] == pivot) unknown = u;
    }
    for (const Group& g : groups_) {
      if (pivot >= g.first_reduced && pivot < g.first_reduced + g.kept()) unknown = g.coordinates[0];
    }
    whole.null_vectors = Eigen::VectorXd::Unit(size_, unknown);
  }
  return whole;
}

void MultiplierEliminatingLinearSystem::solve(Eigen::Ref<Eigen::VectorXd> rhs) {
  const int n_groups = static_cast<int>(groups_.size());
  // δq_p = Q₁ R⁻ᵀ r_λ on each group (Eq. F1), and its coordinates' balance r − K δq_p.
  Column scaled;
  for (int g = 0; g < n_groups; ++g) {
    const Group& group = groups_[g];
    scaled.resize(group.m());
    for (int e = 0; e < group.m(); ++e) scaled[e] = rhs[group.multipliers[e]];
    triangle_[g].transpose().triangularView<Eigen::Lower>().solveInPlace(scaled);
    particular_.segment(group.first_local, group.n()) = basis_[g].leftCols(group.m()).lazyProduct(scaled);
    for (int a = 0; a < group.n(); ++a) balance_[group.first_local + a] = rhs[group.coordinates[a]];
  }
  for (int u = 0; u < size_; ++u) {
    if (plain_of_[u] >= 0) reduced_rhs_[plain_of_[u]] = rhs[u];
  }
  for (const PlainRowGroupColumns& e : plain_row_group_columns_) {
    const Group& g = groups_[e.group];
    reduced_rhs_[e.row] -= gather(e.values, g.n()).dot(particular_.segment(g.first_local, g.n()));
  }
  for (const GroupBlock& e : group_blocks_) {
    const Group &rg = groups_[e.row_group], &cg = groups_[e.column_group];
    balance_.segment(rg.first_local, rg.n()) -=
        gather(e.values, rg.n(), cg.n()).lazyProduct(particular_.segment(cg.first_local, cg.n()));
  }
  // Tᵀ(r − K δq_p) (Eq. F4); the multipliers' columns are left out, Nᵀ s B_Cᵀ = 0.
  for (int g = 0; g < n_groups; ++g) {
    const Group& group = groups_[g];
    reduced_rhs_.segment(group.first_reduced, group.kept()) =
        null_space(g).transpose().lazyProduct(balance_.segment(group.first_local, group.n()));
  }
  factored_->solve(reduced_rhs_);
  // δq_C = δq_p + N y; the coordinates' balance less K's share of the solution is s B_Cᵀ δλ
  // (Eq. F5): δλ = R⁻¹ Q₁ᵀ w.
  for (int g = 0; g < n_groups; ++g) {
    const Group& group = groups_[g];
    solution_.segment(group.first_local, group.n()) =
        null_space(g).lazyProduct(reduced_rhs_.segment(group.first_reduced, group.kept()));
  }
  for (const GroupBlock& e : group_blocks_) {
    const Group &rg = groups_[e.row_group], &cg = groups_[e.column_group];
    balance_.segment(rg.first_local, rg.n()) -=
        gather(e.values, rg.n(), cg.n()).lazyProduct(solution_.segment(cg.first_local, cg.n()));
  }
  for (const GroupRowsPlainColumn& e : group_rows_plain_column_) {
    const Group& g = groups_[e.group];
    balance_.segment(g.first_local, g.n()) -= gather(e.values, g.n()) * reduced_rhs_[e.column];
  }
  for (int u = 0; u < size_; ++u) {
    if (plain_of_[u] >= 0) rhs[u] = reduced_rhs_[plain_of_[u]];
  }
  for (int g = 0; g < n_groups; ++g) {
    const Group& group = groups_[g];
    for (int a = 0; a < group.n(); ++a) {
      rhs[group.coordinates[a]] = particular_[group.first_local + a] + solution_[group.first_local + a];
    }
    scaled = basis_[g].leftCols(group.m()).transpose().lazyProduct(balance_.segment(group.first_local, group.n()));
    triangle_[g].triangularView<Eigen::Upper>().solveInPlace(scaled);
    for (int e = 0; e < group.m(); ++e) rhs[group.multipliers[e]] = scaled[e];
  }
}

}  // namespace deploydyn
