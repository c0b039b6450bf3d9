#pragma once
// The angle at a hinge node H between two arms, from H→A to H→B about a unit axis a, both arms
// projected onto the plane ⟂ a (docs/theory.md, "Constraints" and "Hinges"):
//   u = x_A − x_H,  v = x_B − x_H,  X = u_p·v_p,  Y = a·(u × v),  θ = atan2(Y, X)
// with the derivatives of the direction angle of one arm w (w_p: w projected):
//   ∂θ_w/∂w = a × w_p / |w_p|²,   ∂²θ_w/∂w² = [a]× / |w_p|² − 2 (a × w_p) w_pᵀ / |w_p|⁴
// and θ = θ_v − θ_u. The hinge-angle driver and the hinge element share it. In 2D a = z and
// the D = 2 blocks are the x, y parts.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross
#include <cmath>
#include <numbers>

namespace deploydyn {

class HingeAngle {
 public:
  explicit HingeAngle(const Eigen::Vector3d& unit_axis) : axis_(unit_axis) {}

  const Eigen::Vector3d& axis() const { return axis_; }
  Eigen::Vector3d projected(const Eigen::Vector3d& w) const { return w - axis_.dot(w) * axis_; }

  // θ in (−π, π] of the arms u = x_A − x_H and v = x_B − x_H.
  double angle(const Eigen::Vector3d& u, const Eigen::Vector3d& v) const {
    return std::atan2(axis_.dot(u.cross(v)), projected(u).dot(projected(v)));
  }
  // θ continued from a reference angle: in (reference − π, reference + π], so that it runs
  // smoothly through ±π (a hinge opened past a straight line).
  double angle_near(const Eigen::Vector3d& u, const Eigen::Vector3d& v, double reference) const {
    return reference + wrapped(angle(u, v) - reference);
  }
  // remainder(angle, 2π), the same bits: for |angle| < 2π its quotient is 0 or ±1 and
  // angle ∓ 2π is exact (Sterbenz), which saves the library call's cost (6 % of a hinged
  // chain's step, docs/performance.md "Hinges and cables at scale").
  static double wrapped(double angle) {
    constexpr double turn = 2.0 * std::numbers::pi;
    const double size = std::abs(angle);
    if (size <= 0.5 * turn) return angle;
    if (size < turn) return angle > 0.0 ? angle - turn : angle + turn;
    return std::remainder(angle, turn);  // also NaN
  }

  // ∂θ_w/∂w and ∂²θ_w/∂w² of the direction angle of arm w about the axis.
  Eigen::Vector3d arm_gradient(const Eigen::Vector3d& w) const {
    const Eigen::Vector3d p = projected(w);
    return axis_.cross(p) / p.squaredNorm();
  }
  Eigen::Matrix3d arm_hessian(const Eigen::Vector3d& w) const {
    const Eigen::Vector3d p = projected(w);
    const double p2 = p.squaredNorm();
    Eigen::Matrix3d cross;
    cross << 0.0, -axis_.z(), axis_.y(), axis_.z(), 0.0, -axis_.x(), -axis_.y(), axis_.x(), 0.0;
    return cross / p2 - 2.0 * axis_.cross(p) * p.transpose() / (p2 * p2);
  }

  // ∂θ/∂[x_A, x_H, x_B] (3D entries, D each).
  template <int D>
  Eigen::Matrix<double, 3 * D, 1> gradient(const Eigen::Vector3d& u, const Eigen::Vector3d& v) const {
    const Eigen::Vector3d g_u = -arm_gradient(u), g_v = arm_gradient(v);
    Eigen::Matrix<double, 3 * D, 1> g;
    g << g_u.head<D>(), -g_u.head<D>() - g_v.head<D>(), g_v.head<D>();
    return g;
  }
  // ∂²θ/∂[x_A, x_H, x_B]²: blocks of E_uᵀ (−H_u) E_u + E_vᵀ H_v E_v, E_u = [I, −I, 0],
  // E_v = [0, −I, I].
  template <int D>
  Eigen::Matrix<double, 3 * D, 3 * D> hessian(const Eigen::Vector3d& u, const Eigen::Vector3d& v) const {
    const Eigen::Matrix<double, D, D> h_u = -arm_hessian(u).topLeftCorner<D, D>();
    const Eigen::Matrix<double, D, D> h_v = arm_hessian(v).topLeftCorner<D, D>();
    Eigen::Matrix<double, 3 * D, 3 * D> h = Eigen::Matrix<double, 3 * D, 3 * D>::Zero();
    h.template block<D, D>(0, 0) = h_u;
    h.template block<D, D>(0, D) = -h_u;
    h.template block<D, D>(D, 0) = -h_u;
    h.template block<D, D>(D, D) = h_u + h_v;
    h.template block<D, D>(D, 2 * D) = -h_v;
    h.template block<D, D>(2 * D, D) = -h_v;
    h.template block<D, D>(2 * D, 2 * D) = h_v;
    return h;
  }

 private:
  Eigen::Vector3d axis_;
};

}  // namespace deploydyn
