#include "deploydyn/elements/hinge/hinge_record.hpp"

#include <cmath>

namespace deploydyn {
namespace {

// Arm k (0: u = x_A − x_H, 1: v = x_B − x_H) of the bars form's local coordinates.
Eigen::Vector3d arm(const HingeVector& q, int dimension, int k) {
  const int far = k == 0 ? 0 : 2 * dimension;
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (int i = 0; i < dimension; ++i) w[i] = q[far + i] - q[dimension + i];
  return w;
}

}  // namespace

double HingeRecord::angle(const HingeVector& q) const {
  if (element->form == HingeElement::Form::rotations) return q[1] - q[0];
  return geometry.angle_near(arm(q, dimension, 0), arm(q, dimension, 1), element->initial_angle_rad);
}

void HingeRecord::angle_and_gradient(const HingeVector& q, HingeKinematics& k) const {
  if (element->form == HingeElement::Form::rotations) {
    k.angle_rad = q[1] - q[0];
    k.gradient.resize(2);
    k.gradient << -1.0, 1.0;
    return;
  }
  const Eigen::Vector3d u = arm(q, dimension, 0), v = arm(q, dimension, 1);
  k.angle_rad = geometry.angle_near(u, v, element->initial_angle_rad);
  k.gradient.resize(3 * dimension);
  if (dimension == 2) {
    Eigen::Map<Eigen::Matrix<double, 6, 1>>(k.gradient.data()) = geometry.gradient<2>(u, v);
  } else {
    Eigen::Map<Eigen::Matrix<double, 9, 1>>(k.gradient.data()) = geometry.gradient<3>(u, v);
  }
}

void HingeRecord::angle_hessian(const HingeVector& q, HingeMatrix& hessian) const {
  if (element->form == HingeElement::Form::rotations) {
    hessian.setZero(2, 2);
    return;
  }
  const Eigen::Vector3d u = arm(q, dimension, 0), v = arm(q, dimension, 1);
  hessian.resize(3 * dimension, 3 * dimension);  // column-major, 3D rows: contiguous
  if (dimension == 2) {
    Eigen::Map<Eigen::Matrix<double, 6, 6>>(hessian.data()) = geometry.hessian<2>(u, v);
  } else {
    Eigen::Map<Eigen::Matrix<double, 9, 9>>(hessian.data()) = geometry.hessian<3>(u, v);
  }
}

HingeKinematics HingeRecord::angle_and_gradient(const HingeVector& q) const {
  HingeKinematics k;
  angle_and_gradient(q, k);
  return k;
}

HingeMatrix HingeRecord::angle_hessian(const HingeVector& q) const {
  HingeMatrix hessian;
  angle_hessian(q, hessian);
  return hessian;
}

HingeKinematics HingeRecord::kinematics(const HingeVector& q) const {
  HingeKinematics k;
  angle_and_gradient(q, k);
  angle_hessian(q, k.hessian);
  return k;
}

PinForce HingeRecord::pin_force(const HingeVector& q, double t) const {
  PinForce p;
  p.gradient = HingeVector::Zero(n_dofs());
  if (!pin_member) return p;
  const PinMember& m = *pin_member;
  const Eigen::Vector3d u = arm(q, dimension, 0);
  const double l0 = m.section.reference_length_m;
  double ea = m.section.axial_stiffness_N;
  double thermal_strain = 0.0;
  if (m.law.varies()) {
    const MaterialAt at = m.law.at(m.temperature_change_C->value(t));
    ea = at.youngs_modulus_Pa * m.area_m2;
    thermal_strain = at.thermal_strain;
  } else {
    thermal_strain = m.expansion_per_C * m.temperature_change_C->value(t);
  }
  const double length = u.norm();
  const double strain = (length * length - l0 * l0) / (2.0 * l0 * l0);
  const double pk2 = ea * (strain - thermal_strain);
  const double force = pk2 * length / l0;
  p.magnitude_N = std::abs(force);
  const double sign = force >= 0.0 ? 1.0 : -1.0;
  const Eigen::Vector3d d_force_du = (ea * length / (l0 * l0 * l0) + pk2 / (l0 * length)) * u;
  for (int i = 0; i < dimension; ++i) {
    p.gradient[i] = sign * d_force_du[i];               // x_A
    p.gradient[dimension + i] = -sign * d_force_du[i];  // x_H
  }
  return p;
}

}  // namespace deploydyn
