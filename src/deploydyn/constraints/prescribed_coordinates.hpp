#pragma once
// Coordinates held at their initial value plus a prescribed motion:
//   Φ_k = q[i_k] − (q0_k + s(t))
// With no motion this is a ground support (fixed node, or a roller when only some axes are
// fixed); with one row and a motion it is a coordinate driver. Linear in q: H(λ) = 0.

#include "deploydyn/constraints/constraint.hpp"
#include "deploydyn/constraints/driver_motion.hpp"

namespace deploydyn {

class PrescribedCoordinates final : public Constraint {
 public:
  // dofs: the coordinates held; initial: their values at s = 0; labels: words per row.
  PrescribedCoordinates(std::vector<int> dofs, std::vector<double> initial,
                        std::vector<std::string> labels, DriverMotion motion = {});

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  std::string describe(int row) const override { return labels_[row]; }
  bool jacobian_diagonal() const override { return true; }

 private:
  std::vector<double> initial_;
  std::vector<std::string> labels_;
  DriverMotion motion_;
};

}  // namespace deploydyn
