#include "deploydyn/thermal/member_shadows.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace deploydyn::thermal {

MemberShadows::MemberShadows(int n_members, int samples_along, int samples_across)
    : n_members_(n_members), samples_along_(samples_along), samples_across_(samples_across) {
  if (samples_along < 1 || samples_across < 1) {
    throw std::invalid_argument(fmt::format("MemberShadows: samples along ({}) and across ({}) must be at least 1",
                                            samples_along, samples_across));
  }
  const auto n = static_cast<std::size_t>(std::max(n_members, 0));
  silhouettes_.resize(n);
  lit_.reserve(n);
  last_seen_by_.resize(n);
  grid_boxes_.resize(n);
  everyone_.resize(n);
  std::iota(everyone_.begin(), everyone_.end(), 0);
  listed_ends_.resize(2 * n);
  listed_radii_.resize(n);
  const auto n_samples = static_cast<std::size_t>(samples_along) * static_cast<std::size_t>(samples_across);
  sample_shadowed_.resize(n_samples);
}

namespace {

// A condition on the samples of a row at η across the lit strip, ξ along it: below ≤ c(η) +
// slope ξ ≤ above, with c(η) = at_centre + per_eta η.
struct RowCondition {
  double at_centre, per_eta, slope, below, above;
  double inverse_slope = slope != 0.0 ? 1.0 / slope : 0.0;

  // Narrows [low, high] to the ξ where it holds on the sample row at η.
  void clip_row(double eta, double& low, double& high) const {
    const double c = at_centre + per_eta * eta;
    if (slope == 0.0) {
      if (c < below || c > above) high = -1.0;
    } else if (slope > 0.0) {
      low = std::max(low, (below - c) * inverse_slope);
      high = std::min(high, (above - c) * inverse_slope);
    } else {
      low = std::max(low, (above - c) * inverse_slope);
      high = std::min(high, (below - c) * inverse_slope);
    }
  }
};

}  // namespace

int MemberShadows::shade_samples(const Silhouette& lit, const Silhouette& occluder, double clearance) {
  // On the sample row at η across the lit strip, the point at ξ along it is P(ξ) = a + η e + ξ d
  // (in the sun's view) at depth z_a + ξ Δz. It lies in the occluder's rectangle where its
  // coordinates there, α(ξ) along the occluder's axis and β(ξ) across it, are in [0, 1] and
  // [−r, r], and the occluder's strip there, at depth z_a' + α Δz', is nearer the sun by the
  // clearance: three conditions linear in ξ, so the row's shaded samples are one run of them.
  // shade_by calls it only for the pairs that samples_clear_of could not clear: most of them
  // shade some sample, so the rows are run through at once.
  const auto first_sample = [&](double from) { return std::max(0, static_cast<int>(std::ceil(from * samples_along_ - 0.5))); };
  const auto last_sample = [&](double to) {
    return std::min(samples_along_ - 1, static_cast<int>(std::floor(to * samples_along_ - 0.5)));
  };
  const Eigen::Vector2d offset = lit.a - occluder.a;
  const RowCondition across{offset.dot(occluder.across), lit.across.dot(occluder.across), lit.axis.dot(occluder.across),
                            -occluder.radius, occluder.radius};
  const double alpha_0 = offset.dot(occluder.axis) * occluder.inverse_axis_squared;
  const double alpha_1 = lit.axis.dot(occluder.axis) * occluder.inverse_axis_squared;
  const double alpha_eta = lit.across.dot(occluder.axis) * occluder.inverse_axis_squared;
  const RowCondition along{alpha_0, alpha_eta, alpha_1, 0.0, 1.0};
  // The depth by which the occluder's strip is nearer the sun than the sample.
  const double occluder_rise = occluder.depth_b - occluder.depth_a, lit_rise = lit.depth_b - lit.depth_a;
  const RowCondition nearer{occluder.depth_a + alpha_0 * occluder_rise - lit.depth_a, alpha_eta * occluder_rise,
                            alpha_1 * occluder_rise - lit_rise, clearance, std::numeric_limits<double>::infinity()};
  int newly = 0;
  for (int c = 0; c < samples_across_; ++c) {
    const double eta = (2.0 * (c + 0.5) / samples_across_ - 1.0) * lit.radius;
    double low = 0.0, high = 1.0;
    across.clip_row(eta, low, high);
    along.clip_row(eta, low, high);
    nearer.clip_row(eta, low, high);
    if (!(low <= high)) continue;
    for (int i = first_sample(low), last = last_sample(high); i <= last; ++i) {
      char& shaded = sample_shadowed_[static_cast<std::size_t>(c * samples_along_ + i)];
      newly += shaded == 0 ? 1 : 0;
      shaded = 1;
    }
  }
  return newly;
}

MemberShadows::CellRange MemberShadows::cells_of(const Box& box) const {
  const auto cell = [&](double coordinate, double origin) {
    return static_cast<std::int64_t>(std::floor((coordinate - origin) * inverse_cell_size_));
  };
  return {cell(box.min.x(), grid_origin_.x()), cell(box.max.x(), grid_origin_.x()), cell(box.min.y(), grid_origin_.y()),
          cell(box.max.y(), grid_origin_.y())};
}

std::size_t MemberShadows::bucket_of(std::int64_t x, std::int64_t y) const {
  // The cells row by row, wrapped around the buckets: a compact view keeps neighbours apart
  // and in order, cells of a large sparse one that share a bucket only add candidates.
  return static_cast<std::size_t>(y * cells_across_ + x) & (cell_start_.size() - 2);
}

// A uniform grid over the boxes of `members` in the sun's view, its cells the size of the
// median box, each member listed in every cell its box touches: the candidates for shading a
// member are the members listed in its own box's cells. The cells are hashed into about four
// buckets a member, so that a structure spread thinly over a large view (an arch, a long roof
// seen along its length) costs no more than a compact one.
void MemberShadows::build_grid(std::span<const int> members) {
  grid_origin_ = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d far_corner = -grid_origin_;
  extents_.clear();
  for (const int i : members) {
    const Box& box = grid_boxes_[static_cast<std::size_t>(i)];
    grid_origin_ = grid_origin_.cwiseMin(box.min);
    far_corner = far_corner.cwiseMax(box.max);
    extents_.push_back((box.max - box.min).maxCoeff());
  }
  // The median, not the mean: a few long members (an arch's ties) must not coarsen the grid.
  std::nth_element(extents_.begin(), extents_.begin() + static_cast<std::ptrdiff_t>(extents_.size() / 2), extents_.end());
  const double cell_size = std::max(extents_[extents_.size() / 2], 1e-12 * (1.0 + grid_origin_.cwiseAbs().maxCoeff()));
  inverse_cell_size_ = 1.0 / cell_size;
  cells_across_ = static_cast<std::int64_t>(std::min((far_corner.x() - grid_origin_.x()) / cell_size, 1e9)) + 1;
  std::size_t buckets = 16;
  while (buckets < 4 * members.size()) buckets *= 2;

  // Counting sort of (bucket, member) into cell_members_, in two passes over the boxes.
  cell_start_.assign(buckets + 1, 0);
  for (const int i : members) {
    const CellRange r = cells_of(grid_boxes_[static_cast<std::size_t>(i)]);
    for (std::int64_t y = r.y0; y <= r.y1; ++y) {
      for (std::int64_t x = r.x0; x <= r.x1; ++x) ++cell_start_[bucket_of(x, y) + 1];
    }
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  cell_members_.resize(static_cast<std::size_t>(cell_start_.back()));
  std::vector<int>& next = last_seen_by_;  // borrowed as each bucket's fill position
  next.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (const int i : members) {
    const CellRange r = cells_of(grid_boxes_[static_cast<std::size_t>(i)]);
    for (std::int64_t y = r.y0; y <= r.y1; ++y) {
      for (std::int64_t x = r.x0; x <= r.x1; ++x) cell_members_[static_cast<std::size_t>(next[bucket_of(x, y)]++)] = i;
    }
  }
  last_seen_by_.assign(static_cast<std::size_t>(n_members_), -1);
}

template <class Candidate>
void MemberShadows::for_each_in_cells_of(int i, Candidate&& candidate) {
  const CellRange r = cells_of(grid_boxes_[static_cast<std::size_t>(i)]);
  for (std::int64_t y = r.y0; y <= r.y1; ++y) {
    for (std::int64_t x = r.x0; x <= r.x1; ++x) {
      const std::size_t bucket = bucket_of(x, y);
      for (int m = cell_start_[bucket]; m < cell_start_[bucket + 1]; ++m) {
        const int j = cell_members_[static_cast<std::size_t>(m)];
        if (last_seen_by_[static_cast<std::size_t>(j)] == i) continue;
        last_seen_by_[static_cast<std::size_t>(j)] = i;
        if (!candidate(j)) return;
      }
    }
  }
}

// Sizes that disagree, and non-finite numbers: the grid turns coordinates into integer cell
// indices, which a NaN or an infinity would make undefined (a diverging run's last state).
void MemberShadows::check_input(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
                                std::span<const double> shadowed_fraction) const {
  if (static_cast<int>(members.size()) != n_members_ || static_cast<int>(shadowed_fraction.size()) != n_members_) {
    throw std::invalid_argument(fmt::format("MemberShadows: {} members and {} fractions, expected {}", members.size(),
                                            shadowed_fraction.size(), n_members_));
  }
  if (!sun_direction.allFinite()) throw std::invalid_argument("MemberShadows: the sun's direction is not finite");
  for (std::size_t i = 0; i < members.size(); ++i) {
    const MemberCapsule& m = members[i];
    if (!m.end_a_m.allFinite() || !m.end_b_m.allFinite() || !std::isfinite(m.radius_m)) {
      throw std::invalid_argument(fmt::format("MemberShadows: member {} has a position or radius that is not finite", i));
    }
  }
}

void MemberShadows::see_from_the_sun(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun) {
  // The sun's view: the plane normal to s, spanned by e1 and e2.
  sun_ = sun;
  Eigen::Index least_aligned = 0;
  sun.cwiseAbs().minCoeff(&least_aligned);
  view_x_ = Eigen::Vector3d::Unit(least_aligned).cross(sun).normalized();
  view_y_ = sun.cross(view_x_);
  const auto in_view = [&](const Eigen::Vector3d& x) { return Eigen::Vector2d(x.dot(view_x_), x.dot(view_y_)); };

  lit_.clear();
  for (std::size_t i = 0; i < members.size(); ++i) {
    const MemberCapsule& member = members[i];
    const Eigen::Vector3d axis = member.end_b_m - member.end_a_m;
    const Eigen::Vector3d across = axis.cross(sun);
    const double across_norm = across.norm();
    Silhouette& s = silhouettes_[i];
    s.lit = across_norm > 1e-9 * axis.norm();  // else end-on to the sun: no strip
    if (!s.lit) continue;
    s.a = in_view(member.end_a_m);
    s.axis = in_view(axis);
    s.across = in_view(across / across_norm);
    s.inverse_axis_squared = 1.0 / s.axis.squaredNorm();
    s.radius = member.radius_m;
    s.depth_a = member.end_a_m.dot(sun);
    s.depth_b = member.end_b_m.dot(sun);
    const Eigen::Vector2d half_width = s.radius * s.across.cwiseAbs();
    s.box_min = s.a.cwiseMin(s.a + s.axis) - half_width;
    s.box_max = s.a.cwiseMax(s.a + s.axis) + half_width;
    s.middle = s.a + 0.5 * s.axis;
    s.half_run = (0.5 - 0.5 / samples_along_) * s.axis;  // to the first and last sample centres
    s.half_width = (1.0 - 1.0 / samples_across_) * s.radius * s.across;  // to the outer rows' centres
    s.axis_length = s.axis.norm();
    s.depth_middle = 0.5 * (s.depth_a + s.depth_b);
    s.half_run_rise = (0.5 - 0.5 / samples_along_) * (s.depth_b - s.depth_a);
    s.coordinate_size = std::max({s.box_min.cwiseAbs().maxCoeff(), s.box_max.cwiseAbs().maxCoeff(), std::abs(s.depth_a),
                                  std::abs(s.depth_b)});
    lit_.push_back(static_cast<int>(i));
  }
}

bool MemberShadows::samples_clear_of(const Silhouette& lit, const Silhouette& occluder, double clearance) {
  // A linear function over the parallelogram middle ± half_run ± half_width takes its extremes
  // at the corners: value at the middle ± (|half_run · w| + |half_width · w|). shade_samples
  // finds the same conditions to round-off of a few ulps of the coordinates; the margin, 10⁻⁹ of
  // them (and 1 nm), is far above it, so a pair cleared here is one it would find shading no
  // sample: the fractions are unchanged, bit for bit.
  const double margin = 1e-9 * (1.0 + std::max(lit.coordinate_size, occluder.coordinate_size));
  const Eigen::Vector2d offset = lit.middle - occluder.a;
  // Across the occluder: |β| ≤ r' on its strip.
  const double beta = offset.dot(occluder.across);
  const double beta_spread = std::abs(lit.half_run.dot(occluder.across)) + std::abs(lit.half_width.dot(occluder.across));
  if (std::abs(beta) - beta_spread > occluder.radius + margin) return true;
  // Along it: 0 ≤ (P − a') · d' ≤ |d'|² on its strip.
  const double along = offset.dot(occluder.axis);
  const double along_spread = std::abs(lit.half_run.dot(occluder.axis)) + std::abs(lit.half_width.dot(occluder.axis));
  const double along_margin = margin * occluder.axis_length;
  if (along + along_spread < -along_margin ||
      along - along_spread > occluder.axis_length * occluder.axis_length + along_margin) {
    return true;
  }
  // Nearer the sun: the occluder's depth at α(P) = (P − a') · d' / |d'|², extended linearly as
  // shade_samples' third condition extends it, less the sample's, at least the clearance. Its
  // round-off grows with the occluder's rise per length seen, |Δz'| / |d'|.
  const double rise = occluder.depth_b - occluder.depth_a;
  const double per_along = rise * occluder.inverse_axis_squared;  // the depth per unit of (P − a') · d'
  const double nearer = occluder.depth_a + along * per_along - lit.depth_middle;
  const double nearer_spread = std::abs(lit.half_run.dot(occluder.axis) * per_along - lit.half_run_rise) +
                               std::abs(lit.half_width.dot(occluder.axis) * per_along);
  return nearer + nearer_spread < clearance - margin * (1.0 + std::abs(rise) / occluder.axis_length);
}

int MemberShadows::shade_by(const Silhouette& lit, const Silhouette& occluder) {
  if ((occluder.box_min.array() > lit.box_max.array()).any() || (occluder.box_max.array() < lit.box_min.array()).any()) {
    return 0;
  }
  // As a ray cast from the sample starts 10⁻³ r off it: members meeting at a joint are level
  // there, and neither shades the other by round-off.
  const double clearance = 1e-3 * lit.radius;
  // Nowhere nearer the sun than the farthest sample: it shades none.
  if (std::max(occluder.depth_a, occluder.depth_b) - std::min(lit.depth_a, lit.depth_b) < clearance) return 0;
  if (samples_clear_of(lit, occluder, clearance)) return 0;
  return shade_samples(lit, occluder, clearance);
}

void MemberShadows::compute(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
                            std::span<double> shadowed_fraction) {
  check_input(members, sun_direction, shadowed_fraction);
  see_from_the_sun(members, sun_direction.normalized());
  std::fill(shadowed_fraction.begin(), shadowed_fraction.end(), 0.0);
  if (lit_.empty()) return;
  for (const int i : lit_) {
    const Silhouette& s = silhouettes_[static_cast<std::size_t>(i)];
    grid_boxes_[static_cast<std::size_t>(i)] = {s.box_min, s.box_max};
  }
  build_grid(lit_);

  const int n_samples = samples_along_ * samples_across_;
  for (const int i : lit_) {
    const Silhouette& lit = silhouettes_[static_cast<std::size_t>(i)];
    int shadowed = 0;  // the samples start unmarked: cleared after the last member that marked any
    for_each_in_cells_of(i, [&](int j) {
      if (j != i) shadowed += shade_by(lit, silhouettes_[static_cast<std::size_t>(j)]);
      return shadowed < n_samples;
    });
    shadowed_fraction[static_cast<std::size_t>(i)] = static_cast<double>(shadowed) / n_samples;
    if (shadowed > 0) std::fill(sample_shadowed_.begin(), sample_shadowed_.end(), char{0});
  }
}

// The candidate pairs for update (docs/theory.md, "Updating the shadows incrementally"): every
// member's silhouette in the sun's view lies within its radius r of its axis's projection, so
// two members whose axes' projections, widened by r + skin/2 each, have apart boxes have
// silhouettes apart by more than the skin, and stay apart while neither end has moved by half
// the skin. End-on members are listed too: they may turn into the sun.
void MemberShadows::list_pairs(std::span<const MemberCapsule> members) {
  ++n_pair_listings_;
  constexpr double kSkinPerRadius = 2.0;
  double largest_radius = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const MemberCapsule& member : members) {
    largest_radius = std::max(largest_radius, member.radius_m);
    centroid += member.end_a_m + member.end_b_m;
  }
  centroid /= 2.0 * static_cast<double>(members.size());
  skin_m_ = kSkinPerRadius * largest_radius;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const MemberCapsule& member = members[i];
    const Eigen::Vector3d a = member.end_a_m - centroid, b = member.end_b_m - centroid;
    listed_ends_[2 * i] = a - a.dot(sun_) * sun_;
    listed_ends_[2 * i + 1] = b - b.dot(sun_) * sun_;
    listed_radii_[i] = member.radius_m;
    const Eigen::Vector2d a_seen(a.dot(view_x_), a.dot(view_y_)), b_seen(b.dot(view_x_), b.dot(view_y_));
    const double reach = member.radius_m + 0.5 * skin_m_;
    grid_boxes_[i] = {a_seen.cwiseMin(b_seen).array() - reach, a_seen.cwiseMax(b_seen).array() + reach};
  }
  build_grid(everyone_);
  pair_start_.assign(1, 0);
  pair_members_.clear();
  for (int i = 0; i < n_members_; ++i) {
    const Box& box = grid_boxes_[static_cast<std::size_t>(i)];
    for_each_in_cells_of(i, [&](int j) {
      const Box& other = grid_boxes_[static_cast<std::size_t>(j)];
      if (j != i && (other.min.array() <= box.max.array()).all() && (other.max.array() >= box.min.array()).all()) {
        pair_members_.push_back(j);
      }
      return true;
    });
    pair_start_.push_back(static_cast<int>(pair_members_.size()));
  }
}

// Whether no end has moved in the sun's view, relative to the centroid, by more than half the
// skin since the pairs were listed, less a margin for round-off far above it: the silhouettes
// of the pairs not listed are then apart by more than that margin, where no sample can fall
// into the other's rectangle by round-off.
bool MemberShadows::pairs_still_hold(std::span<const MemberCapsule> members) const {
  if (pair_start_.empty()) return false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double farthest = 0.0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const MemberCapsule& member = members[i];
    if (member.radius_m != listed_radii_[i]) return false;
    centroid += member.end_a_m + member.end_b_m;
    farthest = std::max({farthest, member.end_a_m.cwiseAbs().maxCoeff(), member.end_b_m.cwiseAbs().maxCoeff()});
  }
  centroid /= 2.0 * static_cast<double>(members.size());
  const double round_off_m = 1e-9 * (1.0 + farthest);
  const double limit = 0.5 * skin_m_ - round_off_m;
  if (!(limit > 0.0)) return false;
  const auto moved = [&](const Eigen::Vector3d& end, const Eigen::Vector3d& listed) {
    const Eigen::Vector3d x = end - centroid;
    return (x - x.dot(sun_) * sun_ - listed).squaredNorm() > limit * limit;
  };
  for (std::size_t i = 0; i < members.size(); ++i) {
    if (moved(members[i].end_a_m, listed_ends_[2 * i]) || moved(members[i].end_b_m, listed_ends_[2 * i + 1])) {
      return false;
    }
  }
  return true;
}

void MemberShadows::update(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
                           std::span<double> shadowed_fraction) {
  check_input(members, sun_direction, shadowed_fraction);
  see_from_the_sun(members, sun_direction.normalized());
  std::fill(shadowed_fraction.begin(), shadowed_fraction.end(), 0.0);
  if (lit_.empty()) return;
  if (!pairs_still_hold(members)) list_pairs(members);

  const int n_samples = samples_along_ * samples_across_;
  for (const int i : lit_) {
    const Silhouette& lit = silhouettes_[static_cast<std::size_t>(i)];
    int shadowed = 0;  // the samples start unmarked: cleared after the last member that marked any
    for (int m = pair_start_[static_cast<std::size_t>(i)]; m < pair_start_[static_cast<std::size_t>(i) + 1]; ++m) {
      const Silhouette& other = silhouettes_[static_cast<std::size_t>(pair_members_[static_cast<std::size_t>(m)])];
      if (other.lit) shadowed += shade_by(lit, other);
      if (shadowed == n_samples) break;
    }
    shadowed_fraction[static_cast<std::size_t>(i)] = static_cast<double>(shadowed) / n_samples;
    if (shadowed > 0) std::fill(sample_shadowed_.begin(), sample_shadowed_.end(), char{0});
  }
}

}  // namespace deploydyn::thermal
