// Shadows between members (thermal/member_shadows.hpp) against the geometry of their
// silhouettes: a member behind a parallel one of the same width is fully shadowed, half
// shadowed when offset by half its width; at any offset the fraction is within the sampling
// error 1/n_across of the overlap of the two strips; a member never shades itself; an
// occluder's edge 10⁻¹¹ m inside the outer samples still shades them (the quick reject before
// the exact test keeps a margin above round-off). On a roof
// and on random tangles, every member's fraction equals that of the same samples' rays cast
// with Embree (tests/support/ray_cast_shadows.hpp), the ray caster it replaced. `update`, which
// keeps the candidate pairs between calls (docs/theory.md, "Updating the shadows
// incrementally"), gives compute's fractions bit for bit at every step over structures whose
// members move relative to each other under a turning sun, and a member sliding over another
// shades it from the same step.

#include "deploydyn/thermal/member_shadows.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "deploydyn/generators/roof.hpp"
#include "support/ray_cast_shadows.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace deploydyn::thermal {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kRadius_m = 0.01;
const Eigen::Vector3d kSunAbove = Eigen::Vector3d::UnitZ();

// The lit member along x at z = 0, and one above it (towards the sun) offset by `offset_m` in y.
std::array<MemberCapsule, 2> lit_and_above(double offset_m) {
  return {MemberCapsule{{0, 0, 0}, {1, 0, 0}, kRadius_m}, MemberCapsule{{0, offset_m, 0.1}, {1, offset_m, 0.1}, kRadius_m}};
}

// The share of the lower member's sunlit strip (width 2r) that the upper one's covers.
double strip_overlap(double offset_m) { return std::max(0.0, 2.0 * kRadius_m - std::abs(offset_m)) / (2.0 * kRadius_m); }

std::array<double, 2> shadowed(MemberShadows& shadows, const std::array<MemberCapsule, 2>& members,
                               const Eigen::Vector3d& sun = kSunAbove) {
  std::array<double, 2> fractions{-1.0, -1.0};
  shadows.compute(members, sun, fractions);
  return fractions;
}

TEST(MemberShadows, MemberBehindAParallelOneOfTheSameWidthIsFullyShadowed) {
  MemberShadows shadows(2, 8, 4);
  const auto fractions = shadowed(shadows, lit_and_above(0.0));
  EXPECT_EQ(fractions[0], 1.0);
  EXPECT_EQ(fractions[1], 0.0);  // the upper one, in full sun: the lower one is behind it
}

TEST(MemberShadows, OffsetByHalfItsWidthIsHalfShadowed) {
  for (const int across : {2, 4, 8}) {
    MemberShadows shadows(2, 8, across);
    EXPECT_EQ(shadowed(shadows, lit_and_above(kRadius_m))[0], 0.5) << across;  // an even grid: exact
    EXPECT_EQ(shadowed(shadows, lit_and_above(-kRadius_m))[0], 0.5) << across;
  }
}

TEST(MemberShadows, AnyOffsetIsWithinTheSamplingErrorOfTheStripsOverlap) {
  for (const int across : {1, 3, 4, 16}) {
    MemberShadows shadows(2, 8, across);
    for (double offset = -2.5 * kRadius_m; offset <= 2.5 * kRadius_m; offset += 0.05 * kRadius_m) {
      const double f = shadowed(shadows, lit_and_above(offset))[0];
      EXPECT_LE(std::abs(f - strip_overlap(offset)), 1.0 / across) << "across " << across << ", offset " << offset;
    }
  }
}

TEST(MemberShadows, AnEdgeAcrossTheMemberIsWithinOneRowAlong) {
  // The upper member covers x in [0, 0.5]: half the lower one's length.
  MemberShadows shadows(2, 8, 4);
  const std::array<MemberCapsule, 2> members{MemberCapsule{{0, 0, 0}, {1, 0, 0}, kRadius_m},
                                             MemberCapsule{{-0.1, 0, 0.1}, {0.5, 0, 0.1}, kRadius_m}};
  EXPECT_EQ(shadowed(shadows, members)[0], 0.5);
  // An oblique sun moves the shadow along: from (x, 0, 0.1) towards −s it lands 0.1 · tan(30°)
  // further in +x, covering [0, 0.5577].
  const Eigen::Vector3d sun(-std::sin(std::numbers::pi / 6), 0.0, std::cos(std::numbers::pi / 6));
  MemberShadows fine(2, 64, 4);
  EXPECT_NEAR(shadowed(fine, members, sun)[0], 0.5 + 0.1 * std::tan(std::numbers::pi / 6), 1.0 / 64 + 1e-12);
}

// shade_by clears a pair before the exact test when no sample centre can lie in the occluder's
// rectangle nearer the sun, by a margin above round-off (10⁻⁹ of the coordinates): an occluder's
// edge 10⁻¹¹ m inside the outer sample row, or the last sample column, or its strip 10⁻¹¹ m
// beyond the clearance above the samples, must still shade them, and 10⁻¹¹ m short must not,
// the pair turned and moved every way with its sun.
TEST(MemberShadows, AnOccludersEdgeJustInsideTheOuterSamplesShadesThem) {
  std::mt19937 random(29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  constexpr double r = kRadius_m, tiny_m = 1e-11;
  for (int turn = 0; turn < 20; ++turn) {
    const Eigen::Matrix3d rotation =
        turn == 0 ? Eigen::Matrix3d::Identity()
                  : Eigen::Quaterniond(unit(random), unit(random), unit(random), unit(random)).normalized().toRotationMatrix();
    const Eigen::Vector3d shift = turn == 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(unit(random), unit(random), unit(random));
    const auto placed = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return MemberCapsule{rotation * a + shift, rotation * b + shift, r};
    };
    const Eigen::Vector3d sun = rotation * kSunAbove;
    for (const double inside_m : {tiny_m, -tiny_m}) {
      const bool covers = inside_m > 0.0;
      // Along 8 × across 4 samples on the lower member, x ∈ [0, 1]: rows at y = ±r/4, ±3r/4,
      // columns at x = (i + ½)/8. An upper band |y − y₀| ≤ r reaches the row at 3r/4 while y₀ ≤ 7r/4.
      const std::array<MemberCapsule, 2> beside{placed({0, 0, 0}, {1, 0, 0}),
                                                placed({-0.5, 1.75 * r - inside_m, 0.1}, {1.5, 1.75 * r - inside_m, 0.1})};
      // An upper member from x₀ on covers the last column (x = 15/16) while x₀ ≤ 15/16: 4 samples.
      const std::array<MemberCapsule, 2> beyond{placed({0, 0, 0}, {1, 0, 0}),
                                                placed({15.0 / 16.0 - inside_m, 0, 0.1}, {2, 0, 0.1})};
      // An upper member right above, nearer the sun by the clearance (10⁻³ r) and a little more, or less.
      const std::array<MemberCapsule, 2> barely_above{placed({0, 0, 0}, {1, 0, 0}),
                                                      placed({-0.5, 0, 1e-3 * r + inside_m}, {1.5, 0, 1e-3 * r + inside_m})};
      for (const auto& [members, expected] : {std::pair{beside, covers ? 0.25 : 0.0}, std::pair{beyond, covers ? 0.125 : 0.0},
                                              std::pair{barely_above, covers ? 1.0 : 0.0}}) {
        MemberShadows traced(2, 8, 4), updated(2, 8, 4);
        EXPECT_EQ(shadowed(traced, members, sun)[0], expected) << "turn " << turn << ", inside by " << inside_m;
        std::array<double, 2> fractions{-1.0, -1.0};
        updated.update(members, sun, fractions);
        EXPECT_EQ(fractions[0], expected) << "turn " << turn << ", inside by " << inside_m;
      }
    }
  }
}

TEST(MemberShadows, AMemberDoesNotShadeItself) {
  MemberShadows shadows(1, 8, 4);
  std::array<double, 1> fraction{-1.0};
  const std::array<MemberCapsule, 1> alone{MemberCapsule{{0, 0, 0}, {1, 0.2, 0.3}, kRadius_m}};
  for (const Eigen::Vector3d& sun : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 1, 1).normalized(),
                                     Eigen::Vector3d(1, 0.2, 0.3).normalized()}) {
    shadows.compute(alone, sun, fraction);
    EXPECT_EQ(fraction[0], 0.0);
  }
}

TEST(MemberShadows, TheSunBelowLeavesTheUpperMemberInTheLowerOnesShadow) {
  MemberShadows shadows(2, 8, 4);
  const auto fractions = shadowed(shadows, lit_and_above(0.0), -kSunAbove);
  EXPECT_EQ(fractions[0], 0.0);
  EXPECT_EQ(fractions[1], 1.0);
}

TEST(MemberShadows, SamplesAndSizesAreChecked) {
  EXPECT_THROW(MemberShadows(2, 0, 4), std::invalid_argument);
  EXPECT_THROW(MemberShadows(2, 4, 0), std::invalid_argument);
  MemberShadows shadows(3, 4, 4);
  std::array<double, 2> fractions{};
  EXPECT_THROW(shadows.compute(lit_and_above(0.0), kSunAbove, fractions), std::invalid_argument);
}

// Every member's fraction from the sun's view against Embree's rays from the same samples. A
// sample within single precision's reach of a strip's edge or depth may fall either way in
// Embree: at most one sample a member, in at most 1 % of the members.
void expect_as_the_rays_say(const std::vector<MemberCapsule>& members, const Eigen::Vector3d& sun, int along,
                            int across, const std::string& what) {
  MemberShadows shadows(static_cast<int>(members.size()), along, across);
  std::vector<double> fractions(members.size(), -1.0);
  shadows.compute(members, sun, fractions);
  const std::vector<double> rays = test::ray_cast_shadowed_fractions(members, sun, along, across);
  int differ = 0, shaded = 0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    EXPECT_LE(std::abs(fractions[i] - rays[i]), 1.0 / (along * across) + 1e-15) << what << ", member " << i;
    differ += fractions[i] != rays[i] ? 1 : 0;
    shaded += rays[i] > 0.0 ? 1 : 0;
  }
  EXPECT_LE(differ, static_cast<int>(members.size()) / 100) << what;
  EXPECT_GT(shaded, static_cast<int>(members.size()) / 20) << what << ": too few shadows to compare";
}

TEST(MemberShadows, OnATangleOfRandomMembersEveryFractionIsTheRaysOne) {
  std::mt19937 random(20261129);
  std::uniform_real_distribution<double> in_box(0.0, 1.0), radius(0.005, 0.04), unit(-1.0, 1.0);
  for (int tangle = 0; tangle < 4; ++tangle) {
    std::vector<MemberCapsule> members(400);
    for (MemberCapsule& m : members) {
      m.end_a_m = {in_box(random), in_box(random), in_box(random)};
      m.end_b_m = m.end_a_m + 0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random));
      m.radius_m = radius(random);
    }
    members[7].end_b_m = members[7].end_a_m + Eigen::Vector3d(0.1, 0.2, 0.3);  // end-on to the sun below
    const Eigen::Vector3d sun = tangle == 0 ? Eigen::Vector3d(0.1, 0.2, 0.3).normalized()
                                            : Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
    expect_as_the_rays_say(members, sun, tangle == 3 ? 16 : 8, tangle == 3 ? 2 : 4, "tangle " + std::to_string(tangle));
  }
}

// The 3D roof of 10 trusses × 26 units, pinned: 1 007 bars.
Model pinned_roof_of_1007_bars() {
  RoofOptions options;
  options.n_units = 26;
  options.n_trusses = 10;
  options.delta_t_C = 0.0;
  options.bearings = RoofBearings::pinned;
  return make_roof(options);
}

TEST(MemberShadows, OnARoofEveryFractionIsTheRaysOne) {
  const Model roof = pinned_roof_of_1007_bars();
  std::vector<MemberCapsule> members;
  for (const BarElement& bar : roof.bars) {
    members.push_back({roof.nodes[static_cast<std::size_t>(bar.node_a)].position_m,
                       roof.nodes[static_cast<std::size_t>(bar.node_b)].position_m, 0.02});
  }
  for (const Eigen::Vector3d& sun : {Eigen::Vector3d(0.3, 0.8, 0.5).normalized(), Eigen::Vector3d(0.05, 0.1, 1.0).normalized(),
                                     Eigen::Vector3d(1.0, 0.02, 0.1).normalized()}) {
    expect_as_the_rays_say(members, sun, 8, 4, "roof");
  }
}

// MemberShadows::update against compute's full trace of the same configuration.

// The sun turned by `angle` about an axis oblique to it.
Eigen::Vector3d turned_sun(double angle) {
  const Eigen::Vector3d start = Eigen::Vector3d(0.3, 0.8, 0.5).normalized();
  return Eigen::AngleAxisd(angle, Eigen::Vector3d(1.0, -0.2, 0.4).normalized()) * start;
}

// Steps `members` through `move` (called with the step's index before each step), comparing
// update's fractions with compute's at every step; returns how many steps some member was shaded.
template <class Move>
int expect_update_as_compute(std::vector<MemberCapsule> members, int steps, Move&& move, int along = 8, int across = 4) {
  const int n = static_cast<int>(members.size());
  MemberShadows incremental(n, along, across), reference(n, along, across);
  std::vector<double> updated(members.size()), traced(members.size());
  int shaded_steps = 0;
  for (int step = 0; step < steps; ++step) {
    const Eigen::Vector3d sun = move(step, members);
    incremental.update(members, sun, updated);
    reference.compute(members, sun, traced);
    const auto differs = std::mismatch(updated.begin(), updated.end(), traced.begin());
    if (differs.first != updated.end()) {
      ADD_FAILURE() << "step " << step << ", member " << (differs.first - updated.begin()) << ": update "
                    << *differs.first << ", compute " << *differs.second;
      return shaded_steps;
    }
    shaded_steps += std::any_of(traced.begin(), traced.end(), [](double f) { return f > 0.0; }) ? 1 : 0;
  }
  // The pairs were kept over several steps, and listed again as the members moved.
  EXPECT_GT(incremental.n_pair_listings(), 1);
  EXPECT_LT(incremental.n_pair_listings(), steps / 2);
  return shaded_steps;
}

TEST(MemberShadowsUpdate, RandomMembersMovingApartAndTogetherUnderATurningSunAsTheFullTrace) {
  std::mt19937 random(20261129);
  std::uniform_real_distribution<double> in_box(0.0, 1.0), radius(0.005, 0.02), unit(-1.0, 1.0);
  std::vector<MemberCapsule> members(300);
  std::vector<Eigen::Vector3d> velocity_a, velocity_b;  // m per step, each end its own
  for (MemberCapsule& m : members) {
    m.end_a_m = {in_box(random), in_box(random), in_box(random)};
    m.end_b_m = m.end_a_m + 0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random));
    m.radius_m = radius(random);
    velocity_a.push_back(1e-3 * Eigen::Vector3d(unit(random), unit(random), unit(random)));
    velocity_b.push_back(1e-3 * Eigen::Vector3d(unit(random), unit(random), unit(random)));
  }
  members[7].end_b_m = members[7].end_a_m + 0.3 * turned_sun(0.0);  // end-on to the sun at the start
  const int shaded = expect_update_as_compute(members, 300, [&](int step, std::vector<MemberCapsule>& moving) {
    for (std::size_t i = 0; step > 0 && i < moving.size(); ++i) {
      moving[i].end_a_m += velocity_a[i];
      moving[i].end_b_m += velocity_b[i];
    }
    return turned_sun(2e-3 * step);
  });
  EXPECT_EQ(shaded, 300);
}

TEST(MemberShadowsUpdate, ARoofDeformingAndDriftingUnderATurningSunAsTheFullTrace) {
  const Model roof = pinned_roof_of_1007_bars();
  std::vector<Eigen::Vector3d> nodes;
  for (const Node& node : roof.nodes) nodes.push_back(node.position_m);
  std::vector<MemberCapsule> members;
  for (const BarElement& bar : roof.bars) members.push_back({nodes[bar.node_a], nodes[bar.node_b], 0.02});
  // A wave along the roof that bends it across the sun, and a drift: the joints move
  // relative to each other by up to 3 mm a step, the pairs are listed again every few steps.
  const Eigen::Vector3d across_sun = turned_sun(0.0).cross(Eigen::Vector3d::UnitZ()).normalized();
  expect_update_as_compute(members, 150, [&](int step, std::vector<MemberCapsule>& moving) {
    const auto at = [&](const Eigen::Vector3d& x) {
      const double wave = 0.05 * std::sin(2.0 * x.x() + 0.04 * step) * std::min(1.0, step / 50.0);
      return Eigen::Vector3d(x + Eigen::Vector3d(1e-3 * step, 0.0, 0.0) + wave * across_sun);
    };
    for (std::size_t i = 0; i < moving.size(); ++i) {
      moving[i].end_a_m = at(nodes[roof.bars[i].node_a]);
      moving[i].end_b_m = at(nodes[roof.bars[i].node_b]);
    }
    return turned_sun(1e-5 * step);
  });
}

TEST(MemberShadowsUpdate, AMemberSlidingOverAnotherShadesItFromTheSameStepAsInTheFullTrace) {
  // The upper member starts 5 cm aside of the lower one, its silhouette 3 cm off, beyond the
  // skin (2 r): not a candidate. It slides over it and on past it by 0.5 mm a step, the sun
  // above: listed as a candidate once it has come within the skin, it starts to shade between
  // two listings, at the step the full trace does.
  const double r = 0.01;
  const std::vector<MemberCapsule> members{MemberCapsule{{0, 0, 0}, {1, 0, 0}, r},
                                           MemberCapsule{{0, 0.05, 0.1}, {1, 0.05, 0.1}, r}};
  const int shaded_steps = expect_update_as_compute(members, 201, [&](int step, std::vector<MemberCapsule>& moving) {
    moving[1].end_a_m.y() = moving[1].end_b_m.y() = 0.05 - 5e-4 * step;
    return Eigen::Vector3d::UnitZ();
  });
  // The outer sample column, at 0.75 r, is under the upper strip while |y| ≤ 1.75 r: 71 steps.
  EXPECT_NEAR(shaded_steps, 71, 2);
}

TEST(MemberShadowsUpdate, SizesAreChecked) {
  MemberShadows shadows(3, 4, 4);
  std::vector<MemberCapsule> members(2);
  std::vector<double> fractions(2);
  EXPECT_THROW(shadows.update(members, Eigen::Vector3d::UnitZ(), fractions), std::invalid_argument);
}

// A diverged state's NaN or infinity would reach the grid's float-to-integer cell index.
TEST(MemberShadows, NonFiniteInputIsRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> fractions(2);
  for (int field = 0; field < 4; ++field) {
    std::array<MemberCapsule, 2> members = lit_and_above(0.0);
    Eigen::Vector3d sun = kSunAbove;
    if (field == 0) members[1].end_a_m.y() = nan;
    if (field == 1) members[0].end_b_m.z() = -inf;
    if (field == 2) members[1].radius_m = nan;
    if (field == 3) sun.x() = nan;
    MemberShadows shadows(2, 4, 4);
    EXPECT_THROW(shadows.compute(members, sun, fractions), std::invalid_argument) << field;
    EXPECT_THROW(shadows.update(members, sun, fractions), std::invalid_argument) << field;
    EXPECT_NO_THROW(shadows.update(lit_and_above(0.0), kSunAbove, fractions)) << field;
  }
}

}  // namespace
}  // namespace deploydyn::thermal
