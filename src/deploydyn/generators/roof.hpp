#pragma once
// Foldable roof models built in memory, for `deploydyn generate roof` and for benchmarks.
//
// Planar truss (n_trusses = 1, a 2D model): a chain of n_units parallelogram four-bar units
// that share their posts. Post i stands on the pinned bottom node b_i = (i·s, 0) and its top is
// t_i = b_i + L (cos γ, sin γ); the top chord t_i–t_{i+1} is as long as the bay s, so every unit
// is the paper's parallel linkage (DESIGN §3): one unit is examples/paper/parallel.yaml bar for
// bar. The ground between the pins is rigid and not a bar. The last post (b_N–t_N) is driven
// about b_N, as the paper drives D–C.
//
// 3D roof (n_trusses = M > 1): M such trusses in the planes z = j·w, j = 0 … M−1, joined at
// their top nodes by purlins t_i^j–t_i^{j+1} and braced in the roof plane by diagonals
// t_{i+1}^j–t_i^{j+1}. All posts of truss 0 are driven about z. Bottom nodes are pinned in x,
// y and z (spherical pins: a post could swing out of its plane but for the purlins).
//
// Mechanics of the choices:
// - Purlins are perpendicular to the deployment motion of the top nodes, so alone they give no
//   first-order stiffness against neighbouring trusses deploying at different angles: the
//   diagonals do (their stiffness against it goes as sin γ: weakest folded). In a parallelogram
//   truss all top nodes translate together, so chords, purlins and diagonals keep their lengths
//   while the roof deploys at ΔT = 0.
// - Mobility with rigid bars (coordinates − support and driver equations − bars, as
//   Assembler::rigid_mobility counts it): planar 0, a driven determinate mechanism; 3D with
//   N units and M trusses M − 1 − M·N (2N + 1 + M − M·N before the drivers; each 3D bar-angle
//   driver is two equations): redundant but compatible at ΔT = 0, so a temperature change
//   strains the bars instead of changing the shape.
// - Temperature (model-wide ΔT; the ground between the pins does not expand). The planar truss
//   is statically determinate: ΔT changes its shape, not its stresses. Heated, a chord is
//   longer than its rigid bay, so the posts fan out from the driven last post and rise towards
//   b_0 (5° → 21° folded, 93.7° at the end, for 20 units at +130 °C). Cooled, they flatten
//   towards b_0: at γ = 5° the shrunk chain cannot close below ΔT ≈ −85 °C, the same jam as the
//   paper's cold linkage. The 3D roof is redundant: its roof-plane grid is held by truss 0,
//   whose driven posts keep it from expanding, so the bars are strained (the chords of truss 0
//   up to the full −αΔT at the end). The diagonals run from t_{i+1}^j to t_i^{j+1} so that,
//   heated, they push the next truss's top nodes towards −x, which raises its posts; the other
//   diagonal flattened them until they snapped through (2 trusses of 3 units at +89 °C: a top
//   node near the flat state can move only L (1 − cos 5°) = 1.1 mm along x).
// - Measured (5 s runs): planar, 1 to 20 units, +130 °C and 0 °C deploy (all posts within
//   3.7° of upright, no thermal stress); −170 °C completes as a jam for up to 5 units (the far
//   post turns through the ground to −12°, mechanical strain up to 2.5e-3) and for 10 and 20
//   units ends 3–5° short of upright with strains of 3e-3. 3D, 2 and 3 trusses of 1 to 5
//   units: +130, 0 and −170 °C all deploy (posts 89.2°–90.6° at the end), heated and cooled
//   with mechanical strains of αΔT (2.6e-3, 3.4e-3).
//
// Driver: the paper's Eq. (23) trapezoid read as angular velocity turns 0.365 · 4 = 1.46 rad,
// 83.65°, which leaves the posts 1.35° short of upright. The roof's profile keeps the shape
// (rise [0, 1] s, hold, fall [4, 5] s) and scales the peak rate to 85°/4 s = 17π/144 ≈
// 0.37088 rad/s so that ∫ω = 85° exactly: the driven posts end upright (γ = 90°) at t = 5 s.
//
// Units SI (m, kg, s, N, Pa; °C for the temperature change).

#include <numbers>

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

struct RoofOptions {
  int n_units = 1;                      // parallelogram units (bays) per truss, ≥ 1
  int n_trusses = 1;                    // 1: planar 2D model; > 1: 3D roof of that many trusses
  double delta_t_C = 130.0;             // model-wide ΔT (°C); the paper's hot case deploys
  double truss_spacing_m = kRoofBay_m;  // w, distance of neighbouring trusses (3D)
  double end_time_s = 5.0;              // the deployment takes 5 s
  double step_s = 1e-3;
  double output_interval_s = 0.0;  // 0: 5 ms up to 1000 bars, 50 ms above (history is per bar)
};

// Counts of what make_roof builds, without building it.
struct RoofSize {
  long long n_nodes = 0, n_bars = 0, n_supports = 0, n_drivers = 0;
};
RoofSize roof_size(int n_units, int n_trusses);

// Throws std::invalid_argument naming the option, its value and what is allowed.
void validate(const RoofOptions& options);

// The roof as a Model: dynamic analysis like the paper's (generalized-α, ρ∞ = 0.9). O(bars).
// Names: planar nodes b<i>, t<i>, bars post<i>, chord<i>, driver motor; 3D nodes b<j>_<i>,
// t<j>_<i>, bars post<j>_<i>, chord<j>_<i>, purlin<j>_<i> (truss j to j+1), brace<j>_<i>
// (t_{i+1}^j to t_i^{j+1}), drivers motor<i> (post0_<i>). i counts posts from 0 at x = 0.
Model make_roof(const RoofOptions& options);

}  // namespace deploydyn
