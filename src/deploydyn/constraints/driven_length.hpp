#pragma once
// A linear actuator (docs/theory.md, "Drivers: what each one constrains"): the distance between
// two nodes A and B follows its initial value plus the driver's motion s(t) (m),
//   Φ = |d| − (L₀ + s(t)),   d = x_B − x_A,   n = d / |d|,
//   B = [−nᵀ, nᵀ],   H(λ) = (λ / |d|) [P, −P; −P, P],   P = I − n nᵀ,
//   Φ_t = −ṡ,   Φ̈ − B q̈ = ḋᵀ P ḋ / |d| − s̈.
// The actuator pushes B along −λ n: its effort λ ∂Φ/∂s = −λ (N) is positive when it pushes the
// ends apart (towards a larger length), negative when it pulls. The ends turn freely about each
// other: a telescoping cylinder with ball ends; its own mass and stiffness, if wanted, come
// from elements beside it.

#include "deploydyn/constraints/driver_motion.hpp"
#include "deploydyn/constraints/driving_constraint.hpp"

namespace deploydyn {

class DrivenLength final : public DrivingConstraint {
 public:
  // a_dofs/b_dofs: the D coordinates of A and B; their initial positions give L₀. Throws
  // std::invalid_argument when they coincide (no direction).
  DrivenLength(std::vector<int> a_dofs, std::vector<int> b_dofs, const Eigen::Vector3d& a_position,
               const Eigen::Vector3d& b_position, DriverMotion motion, std::string label);

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  bool nonlinear() const override { return true; }
  void add_hessian_term(const Eigen::VectorXd& q, double t, Eigen::Ref<const Eigen::VectorXd> lambda,
                        Eigen::Ref<Eigen::MatrixXd> hessian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t, Eigen::Ref<Eigen::VectorXd> bias) const override;
  std::string describe(int /*row*/) const override { return label_; }

  double effort(const Eigen::VectorXd& /*q*/, double /*t*/, Eigen::Ref<const Eigen::VectorXd> lambda) const override {
    return -lambda[0];
  }

 private:
  int dimension() const { return static_cast<int>(dofs().size()) / 2; }
  Eigen::Vector3d span(const Eigen::VectorXd& x) const;  // d = x_B − x_A (or its rate); z = 0 in 2D

  double initial_length_m_;
  DriverMotion motion_;
  std::string label_;
};

}  // namespace deploydyn
