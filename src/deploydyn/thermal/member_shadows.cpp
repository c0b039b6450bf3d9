#include "deploydyn/thermal/member_shadows.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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
  const auto n_samples = static_cast<std::size_t>(samples_along) * static_cast<std::size_t>(samples_across);
  sample_shadowed_.resize(n_samples);
}

namespace {

// A condition on the samples of a row at η across the lit strip, ξ along it: below ≤ c(η) +
// slope ξ ≤ above, with c(η) = at_centre + per_eta η.
struct RowCondition {
  double at_centre, per_eta, slope, below, above;
  double inverse_slope = slope != 0.0 ? 1.0 / slope : 0.0;

  // Narrows [low, high] to the ξ where it holds on some row of [eta_low, eta_high].
  void clip(double eta_low, double eta_high, double& low, double& high) const {
    const double c_a = at_centre + per_eta * eta_low, c_b = at_centre + per_eta * eta_high;
    const double c_low = std::min(c_a, c_b), c_high = std::max(c_a, c_b);
    if (slope == 0.0) {
      if (c_high < below || c_low > above) high = -1.0;
    } else if (slope > 0.0) {
      low = std::max(low, (below - c_high) * inverse_slope);
      high = std::min(high, (above - c_low) * inverse_slope);
    } else {
      low = std::max(low, (above - c_low) * inverse_slope);
      high = std::min(high, (below - c_high) * inverse_slope);
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
  const Eigen::Vector2d offset = lit.a - occluder.a;
  const double alpha_0 = offset.dot(occluder.axis) * occluder.inverse_axis_squared;
  const double alpha_1 = lit.axis.dot(occluder.axis) * occluder.inverse_axis_squared;
  const double alpha_eta = lit.across.dot(occluder.axis) * occluder.inverse_axis_squared;
  const double beta_0 = offset.dot(occluder.across), beta_1 = lit.axis.dot(occluder.across);
  const double beta_eta = lit.across.dot(occluder.across);
  const double occluder_rise = occluder.depth_b - occluder.depth_a, lit_rise = lit.depth_b - lit.depth_a;
  const RowCondition conditions[] = {
      {alpha_0, alpha_eta, alpha_1, 0.0, 1.0},
      {beta_0, beta_eta, beta_1, -occluder.radius, occluder.radius},
      // The depth by which the occluder's strip is nearer the sun than the sample.
      {occluder.depth_a + alpha_0 * occluder_rise - lit.depth_a, alpha_eta * occluder_rise,
       alpha_1 * occluder_rise - lit_rise, clearance, std::numeric_limits<double>::infinity()}};
  const auto samples_on = [&](double eta_low, double eta_high, double& low, double& high) {
    low = 0.0;
    high = 1.0;
    for (const RowCondition& condition : conditions) condition.clip(eta_low, eta_high, low, high);
    return low <= high;
  };
  double low = 0.0, high = 1.0;
  if (!samples_on(-lit.radius, lit.radius, low, high)) return 0;  // most candidates shade none of the strip
  int newly = 0;
  for (int c = 0; c < samples_across_; ++c) {
    const double eta = (2.0 * (c + 0.5) / samples_across_ - 1.0) * lit.radius;
    if (!samples_on(eta, eta, low, high)) continue;
    // The samples at ξ_i = (i + ½)/n_along in [low, high].
    const int first = std::max(0, static_cast<int>(std::ceil(low * samples_along_ - 0.5)));
    const int last = std::min(samples_along_ - 1, static_cast<int>(std::floor(high * samples_along_ - 0.5)));
    for (int i = first; i <= last; ++i) {
      char& shaded = sample_shadowed_[static_cast<std::size_t>(c * samples_along_ + i)];
      newly += shaded == 0 ? 1 : 0;
      shaded = 1;
    }
  }
  return newly;
}

MemberShadows::CellRange MemberShadows::cells_of(const Silhouette& s) const {
  const auto cell = [&](double coordinate, double origin) {
    return static_cast<std::int64_t>(std::floor((coordinate - origin) * inverse_cell_size_));
  };
  return {cell(s.box_min.x(), grid_origin_.x()), cell(s.box_max.x(), grid_origin_.x()),
          cell(s.box_min.y(), grid_origin_.y()), cell(s.box_max.y(), grid_origin_.y())};
}

std::size_t MemberShadows::bucket_of(std::int64_t x, std::int64_t y) const {
  // The cells row by row, wrapped around the buckets: a compact view keeps neighbours apart
  // and in order, cells of a large sparse one that share a bucket only add candidates.
  return static_cast<std::size_t>(y * cells_across_ + x) & (cell_start_.size() - 2);
}

// A uniform grid over the lit members' bounding boxes in the sun's view, its cells the size of
// the median member's box, each member listed in every cell its box touches: the candidates
// for shading a member are the members listed in its own box's cells. The cells are hashed into
// about four buckets a member, so that a structure spread thinly over a large view (an arch, a
// long roof seen along its length) costs no more than a compact one.
void MemberShadows::build_grid() {
  grid_origin_ = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d far_corner = -grid_origin_;
  extents_.clear();
  for (const int i : lit_) {
    const Silhouette& s = silhouettes_[static_cast<std::size_t>(i)];
    grid_origin_ = grid_origin_.cwiseMin(s.box_min);
    far_corner = far_corner.cwiseMax(s.box_max);
    extents_.push_back((s.box_max - s.box_min).maxCoeff());
  }
  // The median, not the mean: a few long members (an arch's ties) must not coarsen the grid.
  std::nth_element(extents_.begin(), extents_.begin() + static_cast<std::ptrdiff_t>(extents_.size() / 2), extents_.end());
  const double cell_size = std::max(extents_[extents_.size() / 2], 1e-12 * (1.0 + grid_origin_.cwiseAbs().maxCoeff()));
  inverse_cell_size_ = 1.0 / cell_size;
  cells_across_ = static_cast<std::int64_t>(std::min((far_corner.x() - grid_origin_.x()) / cell_size, 1e9)) + 1;
  std::size_t buckets = 16;
  while (buckets < 4 * lit_.size()) buckets *= 2;

  // Counting sort of (bucket, member) into cell_members_, in two passes over the boxes.
  cell_start_.assign(buckets + 1, 0);
  for (const int i : lit_) {
    const CellRange r = cells_of(silhouettes_[static_cast<std::size_t>(i)]);
    for (std::int64_t y = r.y0; y <= r.y1; ++y) {
      for (std::int64_t x = r.x0; x <= r.x1; ++x) ++cell_start_[bucket_of(x, y) + 1];
    }
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  cell_members_.resize(static_cast<std::size_t>(cell_start_.back()));
  std::vector<int>& next = last_seen_by_;  // borrowed as each bucket's fill position
  next.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (const int i : lit_) {
    const CellRange r = cells_of(silhouettes_[static_cast<std::size_t>(i)]);
    for (std::int64_t y = r.y0; y <= r.y1; ++y) {
      for (std::int64_t x = r.x0; x <= r.x1; ++x) cell_members_[static_cast<std::size_t>(next[bucket_of(x, y)]++)] = i;
    }
  }
  last_seen_by_.assign(static_cast<std::size_t>(n_members_), -1);
}

void MemberShadows::compute(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
                            std::span<double> shadowed_fraction) {
  if (static_cast<int>(members.size()) != n_members_ || static_cast<int>(shadowed_fraction.size()) != n_members_) {
    throw std::invalid_argument(fmt::format("MemberShadows::compute: {} members and {} fractions, expected {}",
                                            members.size(), shadowed_fraction.size(), n_members_));
  }
  const Eigen::Vector3d sun = sun_direction.normalized();
  // The sun's view: the plane normal to s, spanned by e1 and e2.
  Eigen::Index least_aligned = 0;
  sun.cwiseAbs().minCoeff(&least_aligned);
  const Eigen::Vector3d e1 = Eigen::Vector3d::Unit(least_aligned).cross(sun).normalized();
  const Eigen::Vector3d e2 = sun.cross(e1);
  const auto in_view = [&](const Eigen::Vector3d& x) { return Eigen::Vector2d(x.dot(e1), x.dot(e2)); };

  lit_.clear();
  for (std::size_t i = 0; i < members.size(); ++i) {
    const MemberCapsule& member = members[i];
    const Eigen::Vector3d axis = member.end_b_m - member.end_a_m;
    const Eigen::Vector3d across = axis.cross(sun);
    const double across_norm = across.norm();
    shadowed_fraction[i] = 0.0;
    if (!(across_norm > 1e-9 * axis.norm())) continue;  // end-on to the sun: no strip
    Silhouette& s = silhouettes_[i];
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
    lit_.push_back(static_cast<int>(i));
  }
  if (lit_.empty()) return;
  build_grid();

  const double n_samples = static_cast<double>(samples_along_) * samples_across_;
  for (const int i : lit_) {
    const Silhouette& lit = silhouettes_[static_cast<std::size_t>(i)];
    std::fill(sample_shadowed_.begin(), sample_shadowed_.end(), char{0});
    // As a ray cast from the sample starts 10⁻³ r off it: members meeting at a joint are
    // level there, and neither shades the other by round-off.
    const double clearance = 1e-3 * lit.radius;
    const double farthest_sample = std::min(lit.depth_a, lit.depth_b);
    int shadowed = 0;
    const CellRange r = cells_of(lit);
    for (std::int64_t y = r.y0; y <= r.y1 && shadowed < n_samples; ++y) {
      for (std::int64_t x = r.x0; x <= r.x1 && shadowed < n_samples; ++x) {
        const std::size_t bucket = bucket_of(x, y);
        for (int m = cell_start_[bucket]; m < cell_start_[bucket + 1] && shadowed < n_samples; ++m) {
          const int j = cell_members_[static_cast<std::size_t>(m)];
          if (j == i || last_seen_by_[static_cast<std::size_t>(j)] == i) continue;
          last_seen_by_[static_cast<std::size_t>(j)] = i;
          const Silhouette& other = silhouettes_[static_cast<std::size_t>(j)];
          if ((other.box_min.array() > lit.box_max.array()).any() || (other.box_max.array() < lit.box_min.array()).any()) {
            continue;
          }
          // Nowhere nearer the sun than the farthest sample: it shades none.
          if (std::max(other.depth_a, other.depth_b) - farthest_sample < clearance) {
            continue;
          }
          shadowed += shade_samples(lit, other, clearance);
        }
      }
    }
    shadowed_fraction[static_cast<std::size_t>(i)] = shadowed / n_samples;
  }
}

}  // namespace deploydyn::thermal
