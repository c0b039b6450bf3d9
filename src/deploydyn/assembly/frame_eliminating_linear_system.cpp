#include "deploydyn/assembly/frame_eliminating_linear_system.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "deploydyn/assembly/compressed_columns.hpp"

namespace deploydyn {
namespace {

// A frame whose rows s B have a pivot this small against their largest is degenerate (its
// columns c_i dependent): the whole matrix is singular then.
constexpr double kDegenerateFrame = 1e-14;

enum class FrameRole { plain, coordinate, multiplier };

}  // namespace

FrameEliminatingLinearSystem::FrameEliminatingLinearSystem(std::vector<FrameUnknowns> frames,
                                                           std::unique_ptr<LinearSystem> reduced)
    : frames_(std::move(frames)), reduced_(std::move(reduced)) {
  // A singular reduced matrix is reported with the whole matrix's null vectors (singular()).
  reduced_->defer_null_vectors(true);
}

void FrameEliminatingLinearSystem::build_storage(std::span<const MatrixEntry> entries) {
  // The whole pattern, repeats sharing a slot, in (column, row) order.
  const CompressedColumns whole = compress(size_, entries, slots_);
  positions_.clear();
  positions_.reserve(whole.row_index.size());
  for (int col = 0; col < size_; ++col) {
    for (int k = whole.column_start[col]; k < whole.column_start[col + 1]; ++k) {
      positions_.push_back({whole.row_index[k], col});
    }
  }
  values_.assign(positions_.size(), 0.0);

  // Roles: a frame coordinate is 9 node + local, a frame multiplier 6 node + local.
  const int n_frames = static_cast<int>(frames_.size());
  std::vector<FrameRole> role(size_, FrameRole::plain);
  std::vector<int> local(size_, -1);
  for (int m = 0; m < n_frames; ++m) {
    for (int a = 0; a < 9; ++a) {
      role[frames_[m].coordinates[a]] = FrameRole::coordinate;
      local[frames_[m].coordinates[a]] = 9 * m + a;
    }
    for (int e = 0; e < 6; ++e) {
      role[frames_[m].first_multiplier + e] = FrameRole::multiplier;
      local[frames_[m].first_multiplier + e] = 6 * m + e;
    }
  }
  // The reduced unknowns in the whole matrix's order, a frame's three where its first coordinate is.
  plain_of_.assign(size_, -1);
  frame_first_reduced_.assign(n_frames, -1);
  int n_reduced = 0;
  for (int u = 0; u < size_; ++u) {
    if (role[u] == FrameRole::plain) {
      plain_of_[u] = n_reduced++;
    } else if (role[u] == FrameRole::coordinate && frame_first_reduced_[local[u] / 9] < 0) {
      frame_first_reduced_[local[u] / 9] = n_reduced;
      n_reduced += 3;
    }
  }

  // Each whole entry's share of the reduced pattern; slots are indices in `reduced` until the
  // reduced system has analysed it.
  std::vector<MatrixEntry> reduced;
  const auto add = [&](int row, int col) {
    reduced.push_back({row, col});
    return static_cast<int>(reduced.size()) - 1;
  };
  frame_rows_.assign(n_frames, {});
  for (auto& rows : frame_rows_) rows.fill(-1);
  plain_entries_.clear();
  plain_row_frame_columns_.clear();
  frame_rows_plain_column_.clear();
  frame_blocks_.clear();
  // Where a (plain unknown or frame, frame) pair's gathered block is, by key.
  std::unordered_map<std::int64_t, int> plain_row_at, plain_column_at, frame_block_at;
  const auto pair_key = [&](int first, int frame) { return static_cast<std::int64_t>(first) * (n_frames + 1) + frame; };
  for (int p = 0; p < static_cast<int>(positions_.size()); ++p) {
    const auto [row, col] = positions_[p];
    const FrameRole row_role = role[row], col_role = role[col];
    if (row_role == FrameRole::multiplier || col_role == FrameRole::multiplier) {
      // s B and s Bᵀ of the node's own frame, nothing else: the elimination rests on it.
      const bool own_rows = row_role == FrameRole::multiplier && col_role == FrameRole::coordinate &&
                            local[row] / 6 == local[col] / 9;
      const bool own_columns = col_role == FrameRole::multiplier && row_role == FrameRole::coordinate &&
                               local[col] / 6 == local[row] / 9;
      if (!own_rows && !own_columns) {
        throw std::logic_error("a frame's orthonormality rows meet unknowns other than its coordinates");
      }
      if (own_rows) frame_rows_[local[row] / 6][local[row] % 6 + 6 * (local[col] % 9)] = p;
      continue;
    }
    if (row_role == FrameRole::plain && col_role == FrameRole::plain) {
      plain_entries_.push_back({p, add(plain_of_[row], plain_of_[col])});
    } else if (row_role == FrameRole::plain) {
      const int frame = local[col] / 9;
      const auto [at, added] = plain_row_at.try_emplace(pair_key(plain_of_[row], frame), static_cast<int>(plain_row_frame_columns_.size()));
      if (added) {
        PlainRowFrameColumns e{plain_of_[row], frame, {}, {}};
        e.values.fill(-1);
        for (int l = 0; l < 3; ++l) e.slots[l] = add(plain_of_[row], frame_first_reduced_[frame] + l);
        plain_row_frame_columns_.push_back(e);
      }
      plain_row_frame_columns_[at->second].values[local[col] % 9] = p;
    } else if (col_role == FrameRole::plain) {
      const int frame = local[row] / 9;
      const auto [at, added] = plain_column_at.try_emplace(pair_key(plain_of_[col], frame), static_cast<int>(frame_rows_plain_column_.size()));
      if (added) {
        FrameRowsPlainColumn e{frame, plain_of_[col], {}, {}};
        e.values.fill(-1);
        for (int k = 0; k < 3; ++k) e.slots[k] = add(frame_first_reduced_[frame] + k, plain_of_[col]);
        frame_rows_plain_column_.push_back(e);
      }
      frame_rows_plain_column_[at->second].values[local[row] % 9] = p;
    } else {
      const int row_frame = local[row] / 9, column_frame = local[col] / 9;
      const auto [at, added] = frame_block_at.try_emplace(pair_key(row_frame, column_frame), static_cast<int>(frame_blocks_.size()));
      if (added) {
        FrameBlock e{row_frame, column_frame, {}, {}};
        e.values.fill(-1);
        for (int k = 0; k < 3; ++k) {
          for (int l = 0; l < 3; ++l) {
            e.slots[3 * k + l] = add(frame_first_reduced_[row_frame] + k, frame_first_reduced_[column_frame] + l);
          }
        }
        frame_blocks_.push_back(e);
      }
      frame_blocks_[at->second].values[local[row] % 9 + 9 * (local[col] % 9)] = p;
    }
  }
  for (const auto& rows : frame_rows_) {
    if (std::find(rows.begin(), rows.end(), -1) != rows.end()) {
      throw std::logic_error("a frame's orthonormality rows lack an entry of its 6 × 9 block");
    }
  }
  reduced_->analyze(n_reduced, reduced);
  const std::span<const int> slot = reduced_->slots();
  for (auto& e : plain_entries_) e.slot = slot[e.slot];
  for (auto& e : plain_row_frame_columns_) {
    for (int& s : e.slots) s = slot[s];
  }
  for (auto& e : frame_rows_plain_column_) {
    for (int& s : e.slots) s = slot[s];
  }
  for (auto& e : frame_blocks_) {
    for (int& s : e.slots) s = slot[s];
  }
  basis_.assign(n_frames, FrameBasis::Identity());
  triangle_.assign(n_frames, FrameTriangle::Identity());
  reduced_rhs_.resize(n_reduced);
  particular_.resize(9 * n_frames);
  frame_balance_.resize(9 * n_frames);
  frame_solution_.resize(9 * n_frames);
}

FrameEliminatingLinearSystem::Gathered9 FrameEliminatingLinearSystem::gather(const std::array<int, 9>& at) const {
  Gathered9 g;
  for (int i = 0; i < 9; ++i) g[i] = at[i] >= 0 ? values_[at[i]] : 0.0;
  return g;
}

FrameEliminatingLinearSystem::Gathered81 FrameEliminatingLinearSystem::gather(const std::array<int, 81>& at) const {
  Gathered81 g;
  for (int i = 0; i < 81; ++i) g.data()[i] = at[i] >= 0 ? values_[at[i]] : 0.0;
  return g;
}

// Q and R of each node's (s B)ᵀ = Q [R; 0] (Householder, fixed size): Q's last three columns
// span the null space N of s B (Eq. F2), the first six and R give δq_p and the multipliers.
void FrameEliminatingLinearSystem::compute_frame_bases() {
  Eigen::Matrix<double, 9, 6> transposed_rows;
  Eigen::HouseholderQR<Eigen::Matrix<double, 9, 6>> qr;
  for (std::size_t m = 0; m < frames_.size(); ++m) {
    const std::array<int, 54>& at = frame_rows_[m];
    for (int a = 0; a < 9; ++a) {
      for (int e = 0; e < 6; ++e) transposed_rows(a, e) = values_[at[e + 6 * a]];
    }
    qr.compute(transposed_rows);
    basis_[m] = qr.householderQ();
    triangle_[m] = qr.matrixQR().topRows<6>().triangularView<Eigen::Upper>();
  }
}

FactorizationStatus FrameEliminatingLinearSystem::factorize_finite() {
  compute_frame_bases();
  for (const FrameTriangle& r : triangle_) {
    const double largest = r.diagonal().cwiseAbs().maxCoeff();
    if (!(r.diagonal().cwiseAbs().minCoeff() > kDegenerateFrame * largest)) return singular(0.0);
  }
  // Tᵀ K T over the unknowns that stay (Eq. F3).
  reduced_->set_zero();
  const std::span<double> reduced = reduced_->values();
  for (const PlainEntry& e : plain_entries_) reduced[e.slot] += values_[e.value];
  for (const PlainRowFrameColumns& e : plain_row_frame_columns_) {
    const Eigen::Matrix<double, 1, 3> share = gather(e.values).transpose() * basis_[e.frame].rightCols<3>();
    for (int l = 0; l < 3; ++l) reduced[e.slots[l]] += share[l];
  }
  for (const FrameRowsPlainColumn& e : frame_rows_plain_column_) {
    const Eigen::Vector3d share = basis_[e.frame].rightCols<3>().transpose() * gather(e.values);
    for (int k = 0; k < 3; ++k) reduced[e.slots[k]] += share[k];
  }
  for (const FrameBlock& e : frame_blocks_) {
    // Coefficient by coefficient (lazyProduct): Eigen's blocked product cost more at these sizes.
    const Eigen::Matrix<double, 9, 3> right = gather(e.values).lazyProduct(basis_[e.column_frame].rightCols<3>());
    const Eigen::Matrix3d share = basis_[e.row_frame].rightCols<3>().transpose().lazyProduct(right);
    for (int k = 0; k < 3; ++k) {
      for (int l = 0; l < 3; ++l) reduced[e.slots[3 * k + l]] += share(k, l);
    }
  }
  const FactorizationStatus status = reduced_->factorize();
  if (status.ok) return status;
  FactorizationStatus whole = singular(status.reciprocal_condition);
  if (whole.null_vectors.size() == 0 && status.null_vectors.cols() == 1) {
    // Too large for the whole null space: KLU's first zero pivot, as the whole matrix's unknown.
    Eigen::Index pivot = 0;
    status.null_vectors.col(0).cwiseAbs().maxCoeff(&pivot);
    int unknown = 0;
    for (int u = 0; u < size_; ++u) {
      if (plain_of_[u] == pivot) unknown = u;
    }
    for (std::size_t m = 0; m < frames_.size(); ++m) {
      if (pivot >= frame_first_reduced_[m] && pivot < frame_first_reduced_[m] + 3) unknown = frames_[m].coordinates[0];
    }
    whole.null_vectors = Eigen::VectorXd::Unit(size_, unknown);
  }
  return whole;
}

void FrameEliminatingLinearSystem::solve(Eigen::Ref<Eigen::VectorXd> rhs) {
  const int n_frames = static_cast<int>(frames_.size());
  // δq_p = Q₁ R⁻ᵀ r_λ on each frame (Eq. F1), and the frame rows' balance r − K δq_p.
  for (int m = 0; m < n_frames; ++m) {
    const FrameUnknowns& f = frames_[m];
    const Eigen::Matrix<double, 6, 1> scaled =
        triangle_[m].transpose().triangularView<Eigen::Lower>().solve(rhs.segment<6>(f.first_multiplier));
    particular_.segment<9>(9 * m) = basis_[m].leftCols<6>() * scaled;
    for (int a = 0; a < 9; ++a) frame_balance_[9 * m + a] = rhs[f.coordinates[a]];
  }
  for (int u = 0; u < size_; ++u) {
    if (plain_of_[u] >= 0) reduced_rhs_[plain_of_[u]] = rhs[u];
  }
  for (const PlainRowFrameColumns& e : plain_row_frame_columns_) {
    reduced_rhs_[e.row] -= gather(e.values).dot(particular_.segment<9>(9 * e.frame));
  }
  for (const FrameBlock& e : frame_blocks_) {
    frame_balance_.segment<9>(9 * e.row_frame) -= gather(e.values) * particular_.segment<9>(9 * e.column_frame);
  }
  // Tᵀ(r − K δq_p) (Eq. F4); the frame multipliers' columns are left out, Nᵀ s Bᵀ = 0.
  for (int m = 0; m < n_frames; ++m) {
    reduced_rhs_.segment<3>(frame_first_reduced_[m]) =
        basis_[m].rightCols<3>().transpose() * frame_balance_.segment<9>(9 * m);
  }
  reduced_->solve(reduced_rhs_);
  // δq = δq_p + N y; the frame rows' balance less K's share of N y and the plain unknowns is
  // s Bᵀ δλ (Eq. F5): δλ = R⁻¹ Q₁ᵀ w.
  for (int m = 0; m < n_frames; ++m) {
    frame_solution_.segment<9>(9 * m) = basis_[m].rightCols<3>() * reduced_rhs_.segment<3>(frame_first_reduced_[m]);
  }
  for (const FrameBlock& e : frame_blocks_) {
    frame_balance_.segment<9>(9 * e.row_frame) -= gather(e.values) * frame_solution_.segment<9>(9 * e.column_frame);
  }
  for (const FrameRowsPlainColumn& e : frame_rows_plain_column_) {
    frame_balance_.segment<9>(9 * e.frame) -= gather(e.values) * reduced_rhs_[e.column];
  }
  for (int u = 0; u < size_; ++u) {
    if (plain_of_[u] >= 0) rhs[u] = reduced_rhs_[plain_of_[u]];
  }
  for (int m = 0; m < n_frames; ++m) {
    const FrameUnknowns& f = frames_[m];
    for (int a = 0; a < 9; ++a) rhs[f.coordinates[a]] = particular_[9 * m + a] + frame_solution_[9 * m + a];
    const Eigen::Matrix<double, 6, 1> projected = basis_[m].leftCols<6>().transpose() * frame_balance_.segment<9>(9 * m);
    rhs.segment<6>(f.first_multiplier) = triangle_[m].triangularView<Eigen::Upper>().solve(projected);
  }
}

}  // namespace deploydyn
