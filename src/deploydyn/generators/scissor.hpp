#pragma once
// Scissor structures for `deploydyn generate scissor`: the standard retractable-roof forms
// (Escrig 1985; Hoberman 1990; You & Pellegrino 1997), as planar (2D) models of beams
// (docs/theory.md, "Beams") pinned to each other (docs/theory.md, "Joints").
//
// A scissor unit is two straight members pinned at an interior point, the central hinge H;
// units are pinned to their neighbours at their end nodes. Every member is a chain of beam
// elements sharing its nodes (rigid), every pin a joint between two coincident nodes (one per
// member), so a pin carries force but no moment. The whole structure is a one-degree-of-freedom
// mechanism, deployed by a revolute actuator at one central hinge.
//
// Forms (docs/scissor-structures.md has the pictures and the derivations):
// - translational arch: members of half-length l pinned at mid-length; a unit between its unit
//   lines k and k+1 has inner nodes I_k, I_{k+1} and outer nodes O_k, O_{k+1}. With H at the
//   origin and the members at the angle α to the unit's chord,
//       I_k = −a(cos α, sin α),  O_{k+1} = b(cos α, sin α),    member 1: I_k – H – O_{k+1}
//       I_{k+1} = a(cos α, −sin α), O_k = b(−cos α, sin α),    member 2: O_k – H – I_{k+1}
//   with a = b = l: the unit lines stay parallel and the chain is a straight girder of span
//   2 n l cos α.
// - polar arch: the same with the hinge off mid-length, a = l(1 − e), b = l(1 + e), e the hinge
//   offset. Unit lines I_k O_k tilt by ±δ, tan δ = e cot α, so n units form a circular arch
//   subtending 2nδ, flatter folded (α → 90°) and more curved deployed.
// - ring (Hoberman's angulated scissors): n units around a centre, unit lines on the radial
//   lines at 2πk/n. Each member is angulated: two arms of length l with a kink of π − 2π/n at
//   H_k (radius ρ, on the bisector). Its ends P (inner) and Q (outer) lie on the radial lines at
//   radii ρ cos(π/n) ∓ l sin δ, where cos δ = ρ sin(π/n) / l: a member turns rigidly by ±δ as the
//   ring opens, so every node moves radially. The ring spans ρ ∈ (l, l / sin(π/n)).
//
// One deployment parameter for all forms: the opening angle ψ at a central hinge between the
// two arms pointing away from the centre (up, for a girder): ψ = π − 2α for the arches,
// ψ = π + 2π/n − 2δ for the ring. The actuator drives member 2's rotation relative to member 1
// by ψ_deployed − ψ_folded (counterclockwise) in an arch, by its negative in a ring.
//
// Units SI (m, kg, s, N, Pa; °C for temperature changes; angles in rad unless named _deg).

#include <Eigen/Core>
#include <array>
#include <string_view>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/util/name_table.hpp"

namespace deploydyn {

enum class ScissorForm { translational, polar, ring };
inline constexpr NameTable kScissorForms{std::array{
    NamedValue<ScissorForm>{ScissorForm::translational, "translational"},
    NamedValue<ScissorForm>{ScissorForm::polar, "polar"},
    NamedValue<ScissorForm>{ScissorForm::ring, "ring"},
}};

// A steel square hollow section 60 × 60 × 3 mm: a light roof member of a few metres.
inline constexpr double kScissorArea_m2 = 6.84e-4;
inline constexpr double kScissorInertia_m4 = 3.714e-7;
inline constexpr double kScissorDepth_m = 0.06;
inline constexpr double kScissorYoungsModulus_Pa = 2.1e11;
inline constexpr double kScissorExpansion_per_C = 1.2e-5;
inline constexpr double kScissorDensity_kg_m3 = 7850.0;

struct ScissorOptions {
  ScissorForm form = ScissorForm::polar;
  int n_units = 6;                 // ≥ 1 (arches); ring: a multiple of 4, ≥ 8
  double span_m = 10.0;            // deployed: arch span between its feet, ring outer diameter
  double hinge_offset = 0.1;       // polar e ∈ (0, 0.9]; translational and ring: 0
  double folded_angle_deg = 0.0;   // opening angle ψ folded; 0: the form's default
  double deployed_angle_deg = 0.0; // ψ deployed; 0: the form's default
  int elements_per_arm = 2;        // beam elements from an end node to the central hinge
  double area_m2 = kScissorArea_m2;
  double inertia_m4 = kScissorInertia_m4;  // second moment about the bending axis (z)
  double depth_m = kScissorDepth_m;        // section depth, across which a gradient acts
  double delta_t_C = 130.0;                // uniform ΔT of every member
  double gradient_C = 0.0;                 // T(outer face) − T(inner face), e.g. sun on top
  double deploy_time_s = 10.0;             // the actuator's smooth step takes this long
  double end_time_s = 12.0;                // then it holds
  double step_s = 5e-3;
};

// The form's default opening angles (rad) when the options leave them 0.
double folded_opening_rad(const ScissorOptions& options);
double deployed_opening_rad(const ScissorOptions& options);

// Throws std::invalid_argument naming the option, its value and what is allowed.
void validate(const ScissorOptions& options);

// Positions of the rigid-link mechanism at opening angle ψ (rad), members of half-length (arch)
// or arm length (ring) `arm_m`. Arches: unit line k has inner[k], outer[k] (k = 0 … n), feet
// inner[0] at the origin and inner[n] on the x axis, the arch above; ring: inner[k] = P_k,
// outer[k] = Q_k on the radial line at 2πk/n about the origin (k = 0 … n − 1). hinge[k]: H_k.
struct ScissorShape {
  std::vector<Eigen::Vector2d> inner, outer, hinge;
  double span_m = 0.0;  // arch: |inner[n] − inner[0]|; ring: the outer diameter 2|Q|
};
ScissorShape scissor_shape(const ScissorOptions& options, double arm_m, double opening_rad);

// The member length scale (arch: half-length l; ring: arm length l) that makes the deployed
// span equal options.span_m.
double scissor_arm_length_m(const ScissorOptions& options);

// The model: a dynamic deployment from the folded to the deployed opening angle (smooth step
// over deploy_time_s, generalized-α ρ∞ = 0.9). Names: unit k's members m<k>a (member 1) and
// m<k>b, their nodes m<k>a_<j> (j = 0 … 2·elements_per_arm, the hinge in the middle), beams
// m<k>a_e<j>, joints hinge<k> (central) and pin<k>_in / pin<k>_out (where unit k meets unit
// k − 1, or the last unit for a ring), driver motor. Arch feet: inner end of unit 0 pinned
// (x, y), of the last unit on a roller (y); ring: the two nodes on radial line 0 guided along
// x (y held), one on line n/4 along y (x held): no rigid motion, radial deployment free.
Model make_scissor(const ScissorOptions& options);

}  // namespace deploydyn
