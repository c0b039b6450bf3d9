#pragma once
// Foldable roof models built in memory, for `deploydyn generate roof` and for benchmarks.
//
// Planar truss (n_trusses = 1, a 2D model): a chain of n_units parallelogram four-bar units
// that share their posts. Post i stands on the bottom node b_i = (i·s, 0) and its top is
// t_i = b_i + L (cos γ, sin γ); the top chord t_i–t_{i+1} is as long as the bay s, so every unit
// is the paper's parallel linkage (docs/paper-study.md). The last post (b_N–t_N) is driven about
// b_N, as the paper drives D–C.
//
// 3D roof (n_trusses = M > 1): M such trusses in the planes z = j·w, j = 0 … M−1, joined at
// their top nodes by purlins t_i^j–t_i^{j+1} and braced in the roof plane by diagonals
// t_{i+1}^j–t_i^{j+1}. All posts of truss 0 are driven about z.
//
// Bearings (RoofBearings), what the bottom nodes stand on:
// - `sliding` (the default), expansion bearings as a roof designer would use them: a structure
//   whose supports leave it no room to expand carries αΔT·EA in every restrained bar or, where
//   it is a mechanism, changes its shape (below). Here one fixed bearing holds the driven corner
//   b_N^0 (x, y, z); guided bearings along its two edges slide in x (truss 0: y, z held) or in
//   z (line i = N: x, y held); every other bearing slides freely (y held). Bottom members of the
//   top chords' section tie the feet together: bottom chords b_i^j–b_{i+1}^j (planar too),
//   bottom purlins b_i^j–b_i^{j+1} and bottom braces b_{i+1}^j–b_i^{j+1}, so that the bottom
//   grid is a triangulated, rigid plate standing on the bearings instead of on rigid ground.
//   Every constraint is then satisfied by the homothety about b_N^0 with the free thermal
//   stretch k = √(1 + 2αΔT) (Green–Lagrange, docs/theory.md): bars stretch by k, no bar or
//   post turns, the drivers (directions only) and the bearings (lines and planes through the
//   corner) hold. A uniform ΔT scales the whole roof, stress-free, and the deployment is
//   kinematically the cold one scaled (the masses are not scaled, so the small elastic
//   deviations of a dynamic run differ a little). Mobility with rigid bars
//   (coordinates − support and driver equations − bars, as Assembler::rigid_mobility counts
//   it): planar 4(N+1) − (N + 2) − 1 − (3N + 1) = 0, determinate as before; 3D M + N − 1 − 2MN
//   (redundant: both grids are fully triangulated and the edges guided, all compatible with
//   the homothety, so still no thermal stress).
// - `pinned`, the models before bearings, kept for the paper-like thermal-mismatch studies:
//   every bottom node pinned in x, y, z to rigid ground that does not expand, no bottom
//   members. Mobility planar 0; 3D M − 1 − M·N (2N + 1 + M − M·N before the drivers; each 3D
//   bar-angle driver is two equations).
//
// Mechanics of the choices:
// - Purlins are perpendicular to the deployment motion of the top nodes, so alone they give no
//   first-order stiffness against neighbouring trusses deploying at different angles: the
//   diagonals do (their stiffness against it goes as sin γ: weakest folded). In a parallelogram
//   truss all top nodes translate together, so chords, purlins and diagonals keep their lengths
//   while the roof deploys at ΔT = 0.
// - Temperature with pinned bearings (model-wide ΔT; the ground between the pins does not
//   expand). The planar truss is statically determinate: ΔT changes its shape, not its
//   stresses. Heated, a chord is longer than its rigid bay, so the posts fan out from the
//   driven last post and rise towards b_0 (5° → 21° folded, 93.7° at the end, for 20 units at
//   +130 °C; ≈ 2° more per unit, so 500 units lean back to 127° and 1000 have no equilibrium).
//   Cooled, they flatten towards b_0: at γ = 5° the shrunk chain cannot close below
//   ΔT ≈ −85 °C, the same jam as the paper's cold linkage. The 3D roof is redundant: its
//   roof-plane grid is held by truss 0, whose driven posts keep it from expanding, so the bars
//   are strained (the chords of truss 0 up to the full −αΔT at the end). The diagonals run from
//   t_{i+1}^j to t_i^{j+1} so that, heated, they push the next truss's top nodes towards −x,
//   which raises its posts; the other diagonal flattened them until they snapped through (2
//   trusses of 3 units at +89 °C: a top node near the flat state can move only L (1 − cos 5°)
//   = 1.1 mm along x).
// - Measured, pinned (5 s runs): planar, 1 to 20 units, +130 °C and 0 °C deploy (all posts
//   within 3.7° of upright, no thermal stress); −170 °C completes as a jam for up to 5 units
//   (the far post turns through the ground to −12°, mechanical strain up to 2.5e-3) and for 10
//   and 20 units ends 3–5° short of upright with strains of 3e-3. 3D, 2 and 3 trusses of 1 to 5
//   units: +130, 0 and −170 °C all deploy (posts 89.2°–90.6° at the end), heated and cooled
//   with mechanical strains of αΔT (2.6e-3, 3.4e-3). Larger (issue 12): planar 500 units at
//   +130 °C "run" with posts leaning back to 127°, 1000 have no initial equilibrium; 10 × 26
//   stops at 64 % of +130 °C.
// - Measured, sliding (the defaults; initial equilibrium and 0.05 s, README "Generated roofs"):
//   planar 10, 100, 1000 units and 3D 10 trusses of 3, 26, 263 units run at +130, 0 and
//   −170 °C, with |ε_m| ≤ 5e-7 (the deployment's inertia, the same at every ΔT); full 5 s runs
//   of 10 and 100 units deploy at all three (posts 89.95°–90.40° at the end, |ε_m| ≤ 4.6e-5,
//   the bottom chain's elastic strain: pinned 100 units end at 108.7° heated and 64.6° cooled).
//   Planar 10 000 units run at all three too, each start in one load step: b_0 slides
//   (k − 1)·3570 m = 9.3 m (+130 °C) or 12 m (−170 °C) while no bar turns, and the static
//   start limits bar turns, not node movements (solvers/static_solver.hpp; with the node rule
//   it stopped at t = 0).
//
// Driver: the paper's Eq. (23) trapezoid read as angular velocity turns 0.365 · 4 = 1.46 rad,
// 83.65°, which leaves the posts 1.35° short of upright. The roof's profile keeps the shape
// (rise [0, 1] s, hold, fall [4, 5] s) and scales the peak rate to 85°/4 s = 17π/144 ≈
// 0.37088 rad/s so that ∫ω = 85° exactly: the driven posts end upright (γ = 90°) at t = 5 s.
//
// Units SI (m, kg, s, N, Pa; °C for the temperature change).

#include <array>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

// The paper's parallel linkage (Table 1): posts, chords (couplers) and bays.
inline constexpr double kRoofPostLength_m = 0.288;
inline constexpr double kRoofBay_m = 0.357;
inline constexpr double kRoofBarArea_m2 = 4.64e-5;
inline constexpr double kRoofYoungsModulus_Pa = 1.5e11;
inline constexpr double kRoofExpansion_per_C = 2.0e-5;
inline constexpr double kRoofMassPerLength_kg_m = 1.0;  // 0.288 kg and 0.357 kg in the paper
inline constexpr double kRoofFoldedAngle_rad = 5.0 * std::numbers::pi / 180.0;
inline constexpr double kRoofDeployedAngle_rad = std::numbers::pi / 2.0;
// Peak angular velocity of the driver: ∫ω = 4 s · peak = 85°.
inline constexpr double kRoofPeakRate_rad_s = (kRoofDeployedAngle_rad - kRoofFoldedAngle_rad) / 4.0;
// A generated model holds at most this many bars (memory: roughly 200 B per bar and node).
inline constexpr long long kRoofMaxBars = 10'000'000;

// What the bottom nodes stand on (see above).
enum class RoofBearings {
  sliding,  // expansion bearings: one fixed, guided along its edges, the rest sliding
  pinned,   // every bottom node pinned to rigid ground (the models before bearings)
};
// Names as the command line and the file header spell them; the first is the default.
inline constexpr std::array<std::pair<std::string_view, RoofBearings>, 2> kRoofBearingNames{{
    {"sliding", RoofBearings::sliding},
    {"pinned", RoofBearings::pinned},
}};
std::string_view to_string(RoofBearings bearings);
// std::nullopt for a word that names no bearings (exact, lower case).
std::optional<RoofBearings> parse_roof_bearings(std::string_view word);
// "sliding|pinned", for help texts and error messages.
std::string roof_bearing_choices();

struct RoofOptions {
  int n_units = 1;                      // parallelogram units (bays) per truss, ≥ 1
  int n_trusses = 1;                    // 1: planar 2D model; > 1: 3D roof of that many trusses
  double delta_t_C = 130.0;             // model-wide ΔT (°C); the paper's hot case deploys
  RoofBearings bearings = RoofBearings::sliding;
  double truss_spacing_m = kRoofBay_m;  // w, distance of neighbouring trusses (3D)
  double end_time_s = 5.0;              // the deployment takes 5 s
  double step_s = 1e-3;
  double output_interval_s = 0.0;  // 0: 5 ms up to 1000 bars, 50 ms above (history is per bar)
};

// Counts of what make_roof builds, without building it.
struct RoofSize {
  long long n_nodes = 0, n_bars = 0, n_supports = 0, n_drivers = 0;
};
RoofSize roof_size(int n_units, int n_trusses, RoofBearings bearings);

// Throws std::invalid_argument naming the option, its value and what is allowed.
void validate(const RoofOptions& options);

// The roof as a Model: dynamic analysis like the paper's (generalized-α, ρ∞ = 0.9). O(bars).
// Names: planar nodes b<i>, t<i>, bars post<i>, chord<i>, driver motor; 3D nodes b<j>_<i>,
// t<j>_<i>, bars post<j>_<i>, chord<j>_<i>, purlin<j>_<i> (truss j to j+1), brace<j>_<i>
// (t_{i+1}^j to t_i^{j+1}), drivers motor<i> (post0_<i>). i counts posts from 0 at x = 0.
// Sliding bearings add, after those bars, bottom_chord<i> (3D bottom_chord<j>_<i>),
// bottom_purlin<j>_<i> and bottom_brace<j>_<i>; pinned ones build the models before bearings
// node for node and bar for bar.
Model make_roof(const RoofOptions& options);

}  // namespace deploydyn
