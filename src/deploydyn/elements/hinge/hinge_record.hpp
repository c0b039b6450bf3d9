#pragma once
// One hinge bound to the global unknowns: its angle θ(q) with ∂θ/∂q and ∂²θ/∂q² on its few
// unknowns, and the pin force |N| that its friction presses with (docs/theory.md, "Hinges").
//   bars:       unknowns [x_A, x_H, x_B] (D each), θ from constraints/hinge_angle.hpp,
//               continued from the initial angle so that it runs smoothly through ±π;
//               |N| = |axial force| of the bar A–H: N = S l / L0, S = EA (ε − α ΔT),
//               (EA = E(T) A and ε_t = ∫α dT with temperature tables: model/material_law.hpp),
//               ∂N/∂u = (EA l / L0³ + S / (L0 l)) u  with u = x_A − x_H.
//   rotations:  unknowns [rz_A, rz_B], θ = rz_B − rz_A (linear), no pin force.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "deploydyn/constraints/hinge_angle.hpp"
#include "deploydyn/elements/bar/bar.hpp"
#include "deploydyn/elements/hinge/hinge_element.hpp"
#include "deploydyn/model/material_law.hpp"
#include "deploydyn/model/time_function.hpp"

namespace deploydyn {

// Local vectors and matrices of a hinge: at most 9 unknowns (three 3D nodes).
constexpr int kMaxHingeDofs = 9;
using HingeVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxHingeDofs, 1>;
using HingeMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxHingeDofs, kMaxHingeDofs>;

// The bar A–H whose axial force is the pin force.
struct PinMember {
  bar::Section section;
  double expansion_per_C = 0.0;
  const TimeFunction* temperature_change_C = nullptr;
  MaterialLaw law;      // E(T), ε_t(T) when tables give them (then EA = E(T) A)
  double area_m2 = 0.0;
};

// θ and its derivatives at one configuration.
struct HingeKinematics {
  double angle_rad = 0.0;
  HingeVector gradient;  // ∂θ/∂q_local
  HingeMatrix hessian;   // ∂²θ/∂q_local²
};

// |N| and its gradient on the hinge's unknowns.
struct PinForce {
  double magnitude_N = 0.0;
  HingeVector gradient;
};

struct HingeRecord {
  const HingeElement* element = nullptr;  // in the model
  int dimension = 2;                      // D of the bars form
  std::vector<int> dofs;                  // bars: A, H, B (D each); rotations: rz_A, rz_B
  HingeAngle geometry{Eigen::Vector3d::UnitZ()};
  std::optional<PinMember> pin_member;    // with friction on the bars form
  double reference_length_m = 0.0;        // the shorter arm; 0 for the rotations form

  int n_dofs() const { return static_cast<int>(dofs.size()); }
  HingeVector gather(const Eigen::VectorXd& x) const {
    HingeVector local(n_dofs());
    for (int i = 0; i < n_dofs(); ++i) local[i] = x[dofs[static_cast<std::size_t>(i)]];
    return local;
  }

  HingeKinematics kinematics(const HingeVector& q) const;
  // θ alone, the same bits as angle_and_gradient's: the step's end needs θ at its start.
  double angle(const HingeVector& q) const;
  // θ and ∇θ only (the hessian left empty): forces, energies and the modes' tests need no
  // more, and ∇²θ is most of a hinge's cost per residual (docs/performance.md, "Hinges and
  // cables at scale").
  HingeKinematics angle_and_gradient(const HingeVector& q) const;
  // ∇²θ alone (what kinematics adds to angle_and_gradient).
  HingeMatrix angle_hessian(const HingeVector& q) const;
  // The same into `k`'s θ, ∇θ and into `hessian`, in place: the hinge group's memo keeps them
  // without a copy of ∇²θ (docs/performance.md, "Hinges and cables at scale").
  void angle_and_gradient(const HingeVector& q, HingeKinematics& k) const;
  void angle_hessian(const HingeVector& q, HingeMatrix& hessian) const;
  // At thermal factor 1 (friction acts in a run, not in a path in ΔT).
  PinForce pin_force(const HingeVector& q, double t) const;
};

}  // namespace deploydyn
