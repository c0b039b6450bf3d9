#pragma once
// How many motions a model leaves free with its elements taken as rigid (docs/theory.md,
// "Mobility: the count and the rank"). Two answers:
//  - the count by types (Grübler–Kutzbach): coordinates − constraint equations − the
//    elements' rigid-body conditions (Assembler::rigid_mobility), exact when no equation is
//    redundant;
//  - the rank at the initial configuration: coordinates − rank [B; S], B the constraint
//    Jacobian and S the rigid-body rows (the tangent stiffness of the elements that count as
//    rigid, unstressed: no thermal strain, t = 0, whose null space is their strain-free motions).
//    It sees special geometry the count cannot (parallel or meeting axes, a Cardan shaft held at
//    both ends, a Bennett linkage): count − rank = the redundant equations there.
// The rank is that of a dense matrix, so it is computed up to kMaxRankUnknowns coordinates.
// The free motions themselves, a basis of the null space of [B; K_r] (assembly/null_space.hpp),
// up to kMaxFreeMotionUnknowns, for assembly/free_motion.hpp to name.

#include <optional>

#include "deploydyn/assembly/assembler.hpp"

namespace deploydyn {

// Rows and columns are scaled to a largest entry of 1 (twice each way) before a column-pivoted
// QR; a pivot below this share of the largest counts as zero. The stiffness rows of a slender
// element span (r/L)² (r its radius of gyration) between axial and bending entries: 1e-4 at
// r/L = 0.01, far above the tolerance; round-off in B and K is ~1e-15.
inline constexpr double kRankTolerance = 1e-9;
inline constexpr int kMaxRankUnknowns = 800;  // a dense QR of ~2n × n: ~0.1 s at 800
// B is evaluated column by column (n evaluations of every constraint), then inverted sparse.
inline constexpr int kMaxFreeMotionUnknowns = 3000;
inline constexpr int kMostFreeMotions = 8;  // null vectors sought when the rank is not known

struct Mobility {
  int by_count = 0;  // Assembler::rigid_mobility(), the drivers' equations included
  // Free motions at the initial configuration by the rank, drivers included; empty: too large.
  std::optional<int> by_rank;
  // Equations redundant at the initial configuration: by_rank − by_count (0 when not ranked).
  int n_redundant() const { return by_rank ? *by_rank - by_count : 0; }
  // An orthonormal basis of the free motions after the drivers (columns: coordinates' velocities,
  // up to kMostFreeMotions); empty when none, or above max_free_motion_unknowns coordinates.
  Eigen::MatrixXd free_motions;
};

Mobility mobility(const Assembler& assembler, int max_rank_unknowns = kMaxRankUnknowns,
                  int max_free_motion_unknowns = kMaxFreeMotionUnknowns);

}  // namespace deploydyn
