#pragma once
// The share of each member that the other members hide from the sun (docs/theory.md, "Shadows
// between members").
//
// Each member is a cylinder of its section's outer radius r around its axis a → b. The sun sees
// it as its silhouette, the strip of width 2r along the axis in the plane through the axis
// normal to s⊥ (the sun's direction s less its component along the axis); the cylinder's ends
// are taken flat. Samples at the centres of an n_along × n_across grid on the strip each look
// towards the sun; a sample is in shadow when its ray meets any other member's strip, and
//
//     f_sh = (samples in shadow) / (n_along · n_across)
//
// is the share of the member's projected area A_proj = 2r L |sin θ| in shadow, with a sampling
// error below one row or column of the grid at each shadow edge: |Δf| ≤ 1/n_across for an
// edge along the member, 1/n_along across it. A member end-on to the sun (|sin θ| < 1e-9) has
// no sunlit strip: f_sh = 0 (it absorbs no direct light anyway), and it casts no shadow.
//
// The rays are parallel, so they are traced in the sun's view (docs/theory.md, the same
// section, "Tracing the rays in the sun's view"): projected along s onto a plane normal to it
// every strip is a rectangle, a sample's ray meets another member's strip exactly when the
// sample's projection lies in that rectangle and the strip there is nearer the sun, and a grid
// of the rectangles' bounding boxes in that plane gives each member the few others that can
// shade it. Tested against Embree's rays from the same samples (tests/support/ray_cast_shadows.hpp).
//
// `update` gives compute's fractions bit for bit at a fraction of its cost while the structure
// moves little between calls (docs/theory.md, the same section, "Updating the shadows
// incrementally"): the pairs that can shade each other are listed once from the members'
// silhouettes widened by a skin, and listed again only when some member's end has moved in the
// sun's view (relative to the structure's centroid, the sun's turn included) by half the skin.

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace deploydyn::thermal {

// One member's axis in the current configuration and its outer radius.
struct MemberCapsule {
  Eigen::Vector3d end_a_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d end_b_m = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
};

class MemberShadows {
 public:
  // Throws std::invalid_argument for sample counts below 1.
  MemberShadows(int n_members, int samples_along, int samples_across);

  // The shadowed fraction of every member (in [0, 1]) of the structure `members` (as many as
  // the constructor's n_members), lit from the direction `sun_direction` (towards the sun).
  // Both throw std::invalid_argument for other counts and for a position, radius or sun
  // direction that is not finite.
  void compute(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
               std::span<double> shadowed_fraction);
  // The same fractions as compute's, from the candidate pairs kept since their last listing.
  void update(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
              std::span<double> shadowed_fraction);
  long n_pair_listings() const { return n_pair_listings_; }  // by update, since construction

 private:
  // A member's strip seen from the sun: the rectangle {a + ξ axis + η across, ξ ∈ [0, 1],
  // |η| ≤ r} in the plane normal to s, and the depth towards the sun along its axis.
  struct Silhouette {
    Eigen::Vector2d a, axis, across;  // across: a unit vector ⟂ axis
    double inverse_axis_squared = 0.0;
    double radius = 0.0;
    double depth_a = 0.0, depth_b = 0.0;  // x · s at the ends
    Eigen::Vector2d box_min, box_max;     // the rectangle's bounding box
    // The parallelogram of the sample centres, middle ± half_run ± half_width (from the first to
    // the last sample along, the outer rows across), for shade_by's quick rejects; |axis|; and
    // the size of the coordinates, for their round-off.
    Eigen::Vector2d middle, half_run, half_width;
    double depth_middle = 0.0, half_run_rise = 0.0;  // the depth there, and its change to the outer samples
    double axis_length = 0.0;
    double coordinate_size = 0.0;  // the largest of the view's coordinates and the depths
    bool lit = false;                     // false end-on to the sun: no strip, the rest unset
  };
  // Whether no sample centre of `lit` can lie in `occluder`'s rectangle with the occluder there
  // `clearance` nearer the sun: outside the band across it, beyond its ends, or behind it, by
  // more than any round-off of shade_samples' arithmetic.
  static bool samples_clear_of(const Silhouette& lit, const Silhouette& occluder, double clearance);
  struct Box {
    Eigen::Vector2d min, max;
  };
  // Marks the samples of `lit` whose rays meet `occluder`'s strip at least `clearance` nearer
  // the sun (sample_shadowed_); returns how many were not marked before.
  int shade_samples(const Silhouette& lit, const Silhouette& occluder, double clearance);
  struct CellRange {
    std::int64_t x0, x1, y0, y1;
  };
  CellRange cells_of(const Box& box) const;
  std::size_t bucket_of(std::int64_t x, std::int64_t y) const;
  void check_input(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
                   std::span<const double> shadowed_fraction) const;
  // Each member's silhouette in the sun's view (sun_ the unit direction), lit_ those with one.
  void see_from_the_sun(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun);
  void build_grid(std::span<const int> members);  // over grid_boxes_ of `members`
  // Calls candidate(j) once for each member j listed in the cells of member i's grid box, until it returns false.
  template <class Candidate>
  void for_each_in_cells_of(int i, Candidate&& candidate);
  // shade_samples after the cheap tests (boxes apart, the occluder nowhere nearer the sun,
  // samples_clear_of).
  int shade_by(const Silhouette& lit, const Silhouette& occluder);
  // update's candidate pairs: listed again from `members`, and whether those listed still hold.
  void list_pairs(std::span<const MemberCapsule> members);
  bool pairs_still_hold(std::span<const MemberCapsule> members) const;

  int n_members_ = 0;
  int samples_along_ = 0;
  int samples_across_ = 0;
  // Kept between updates: no allocation once the first has sized them.
  std::vector<Silhouette> silhouettes_;
  std::vector<int> lit_;  // members with a strip (not end-on to the sun)
  Eigen::Vector3d sun_ = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d view_x_ = Eigen::Vector3d::UnitX(), view_y_ = Eigen::Vector3d::UnitY();  // e1, e2
  std::vector<Box> grid_boxes_;  // [member], the boxes the grid was built from
  std::vector<int> everyone_;    // 0, 1, …, n_members − 1
  // The grid: the cells hashed to bucket b hold cell_members_[cell_start_[b] .. cell_start_[b + 1]).
  Eigen::Vector2d grid_origin_ = Eigen::Vector2d::Zero();
  double inverse_cell_size_ = 1.0;  // 1 / the median member box's size
  std::int64_t cells_across_ = 1;  // along the view's first axis
  std::vector<double> extents_;    // of the members' boxes, for the median
  std::vector<int> cell_start_, cell_members_;
  std::vector<int> last_seen_by_;  // [member] → the member whose candidates last listed it
  std::vector<char> sample_shadowed_;  // [c · n_along + i] of the member being lit
  // update's candidate pairs: member i may be shaded by pair_members_[pair_start_[i] .. pair_start_[i + 1]),
  // listed when the members' ends were seen from the sun at listed_ends_ (2 per member, relative
  // to their centroid, (I − s sᵀ)(x − c)), with these radii, for motions up to half the skin.
  std::vector<int> pair_start_, pair_members_;
  std::vector<Eigen::Vector3d> listed_ends_;
  std::vector<double> listed_radii_;
  double skin_m_ = 0.0;
  long n_pair_listings_ = 0;
};

}  // namespace deploydyn::thermal
