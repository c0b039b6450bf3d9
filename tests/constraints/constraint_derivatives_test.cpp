// Constraint derivatives by finite differences (docs/verification.md, STYLE practice 9): Jacobian B,
// Hessian term H(λ) = ∂(Bᵀλ)/∂q, Φ_t, and the bias of Φ̈ = B q̈ + bias along a trajectory;
// and the driver torque against the power of the constraint force.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "deploydyn/constraints/driven_bar_angle.hpp"
#include "deploydyn/constraints/driven_hinge_angle.hpp"
#include "deploydyn/constraints/driven_length.hpp"
#include "deploydyn/constraints/driven_revolute.hpp"
#include "deploydyn/constraints/frame_support.hpp"
#include "deploydyn/constraints/pin_joint.hpp"
#include "deploydyn/constraints/point_joint.hpp"
#include "deploydyn/constraints/prescribed_coordinates.hpp"
#include "support/finite_difference.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Central differences in q (m) and t (s): truncation O(1e-10), round-off O(1e-11).
constexpr double kStep = 1e-5;
constexpr double kDerivativeTolerance = 1e-7;  // absolute, for quantities of size ~1
// Second difference of Φ along q(t): round-off ε|Φ|/δ² ≈ 1e-8 dominates with δ = 1e-4 s.
constexpr double kSecondStep = 1e-4;
constexpr double kBiasTolerance = 1e-6;
constexpr double kTorqueTolerance = 1e-12;  // two evaluations of one product: round-off only
constexpr double kOffDirectionTolerance = 1e-4;  // relative; the chord's tilt costs 1.25e-5
constexpr int kSamples = 5;
constexpr int kDofs = 30;  // the constraints touch a scattered subset of these unknowns

// A smooth rotation while ω rises, 0 → 2 rad/s over [0, 1] s, read as an angular velocity:
// samples in (0.1, 0.9) s stay inside the polynomial piece.
DriverMotion driver_motion() {
  return DriverMotion(TimeFunction(TimeFunction::SmoothTrapezoid{2.0, 0.0, 1.0, 4.0, 5.0}), DriverReading::rate);
}

struct Case {
  std::string name;
  std::unique_ptr<Constraint> constraint;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  const DriverMotion coordinate_motion(TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, 1.0, 0.3}),
                                       DriverReading::value);
  out.push_back({"prescribed coordinates", std::make_unique<PrescribedCoordinates>(
                                               std::vector<int>{7, 2, 4}, std::vector<double>{0.1, -0.4, 0.6},
                                               std::vector<std::string>{"a", "b", "c"}, coordinate_motion)});
  out.push_back({"driven bar angle 2D",
                 std::make_unique<DrivenBarAngle>(std::vector<int>{6, 7}, std::vector<int>{1, 3},
                                                  Eigen::Vector3d(0.1, 0.2, 0.0), Eigen::Vector3d(0.5, 0.9, 0.0),
                                                  Eigen::Vector3d::UnitZ(), driver_motion(), "2D")});
  out.push_back({"driven bar angle 3D, tilted axis",
                 std::make_unique<DrivenBarAngle>(std::vector<int>{8, 0, 5}, std::vector<int>{2, 4, 1},
                                                  Eigen::Vector3d(0.1, 0.2, -0.3), Eigen::Vector3d(0.7, -0.1, 0.4),
                                                  Eigen::Vector3d(0.3, -0.5, 1.0).normalized(), driver_motion(),
                                                  "3D")});
  // Rotation unknowns R11 … R33 of two 3D beam nodes, scattered (q is random: the derivatives
  // do not need R orthonormal).
  const std::vector<int> frame_a{10, 12, 11, 14, 13, 15, 17, 16, 18};
  const std::vector<int> frame_b{29, 20, 21, 22, 28, 24, 25, 26, 27};
  const Eigen::Vector3d tilted_axis = Eigen::Vector3d(0.3, -0.5, 1.0);
  out.push_back({"pin joint 2D", std::make_unique<PinJoint>(std::vector<int>{6, 7}, std::vector<int>{1, 3},
                                                            std::vector<int>{}, std::vector<int>{},
                                                            Eigen::Vector3d::UnitZ(), "pin")});
  out.push_back({"pin joint 3D with rotations",
                 std::make_unique<PinJoint>(std::vector<int>{8, 0, 5}, std::vector<int>{2, 4, 1}, frame_a, frame_b,
                                            tilted_axis, "pin")});
  // Ball, universal and offset joints (point_joint.hpp), supports through a frame (frame_support.hpp).
  const std::vector<int> position_a{8, 0, 5}, position_b{2, 4, 1};
  const Eigen::Vector3d offset_a(0.3, -0.2, 0.7), offset_b(-0.5, 0.1, 0.25);
  // Spelled out: `{}` for an Eigen vector leaves its coefficients uninitialised, not zero.
  const Eigen::Vector3d no_offset = Eigen::Vector3d::Zero();
  const Eigen::Vector3d arm_a = Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
  const Eigen::Vector3d arm_b = arm_a.cross(Eigen::Vector3d(0.2, -0.4, 1.0)).normalized();
  out.push_back({"ball joint 2D", std::make_unique<PointJoint>(PointJoint::Side{{6, 7}, {}, no_offset},
                                                               PointJoint::Side{{1, 3}, {}, no_offset},
                                                               std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>{}, "b")});
  out.push_back({"ball joint 3D, offset on A only",
                 std::make_unique<PointJoint>(PointJoint::Side{position_a, frame_a, offset_a},
                                              PointJoint::Side{position_b, {}, no_offset},
                                              std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>{}, "b")});
  out.push_back({"ball joint 3D, offsets on both",
                 std::make_unique<PointJoint>(PointJoint::Side{position_a, frame_a, offset_a},
                                              PointJoint::Side{position_b, frame_b, offset_b},
                                              std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>{}, "b")});
  out.push_back({"universal joint with offsets",
                 std::make_unique<PointJoint>(PointJoint::Side{position_a, frame_a, offset_a},
                                              PointJoint::Side{position_b, frame_b, offset_b},
                                              std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>{{arm_a, arm_b}},
                                              "u")});
  const Eigen::Vector3d pin_axis = tilted_axis.normalized();
  const Eigen::Vector3d pin_normal = normal_to(pin_axis);
  out.push_back({"pin joint with offsets",
                 std::make_unique<PointJoint>(PointJoint::Side{position_a, frame_a, offset_a},
                                              PointJoint::Side{position_b, frame_b, no_offset},
                                              std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>{
                                                  {pin_axis, pin_normal}, {pin_axis, pin_axis.cross(pin_normal)}},
                                              "p")});
  out.push_back({"support with offset, hinge axis", std::make_unique<FrameSupport>(
                                                        position_a, frame_a, Eigen::Vector3d(0.1, 0.2, 0.3), offset_a,
                                                        std::vector<int>{0, 2}, tilted_axis, "s")});
  out.push_back({"support: hinge axis only", std::make_unique<FrameSupport>(position_b, frame_b, Eigen::Vector3d::Zero(),
                                                                           Eigen::Vector3d::Zero(), std::vector<int>{},
                                                                           tilted_axis, "s")});
  out.push_back({"revolute 2D", std::make_unique<DrivenRevolute>(std::vector<int>{19}, std::vector<int>{23},
                                                                 Eigen::Vector3d::UnitZ(), driver_motion(), "r")});
  out.push_back({"revolute 3D",
                 std::make_unique<DrivenRevolute>(frame_a, frame_b, tilted_axis, driver_motion(), "r")});
  // At a hinge to ground: node A is the ground (no unknowns).
  out.push_back({"revolute 2D at a hinge to ground", std::make_unique<DrivenRevolute>(
                                                         std::vector<int>{}, std::vector<int>{23},
                                                         Eigen::Vector3d::UnitZ(), driver_motion(), "r")});
  out.push_back({"revolute 3D at a hinge to ground",
                 std::make_unique<DrivenRevolute>(std::vector<int>{}, frame_b, tilted_axis, driver_motion(), "r")});
  out.push_back({"hinge angle 2D",
                 std::make_unique<DrivenHingeAngle>(std::vector<int>{6, 7}, std::vector<int>{1, 3}, std::vector<int>{9, 0},
                                                    Eigen::Vector3d(1.0, 0.2, 0.0), Eigen::Vector3d(0.1, 0.1, 0.0),
                                                    Eigen::Vector3d(-0.3, 0.8, 0.0), Eigen::Vector3d::UnitZ(),
                                                    driver_motion(), "h")});
  out.push_back({"hinge angle 3D, tilted axis",
                 std::make_unique<DrivenHingeAngle>(std::vector<int>{8, 0, 5}, std::vector<int>{2, 4, 1},
                                                    std::vector<int>{9, 6, 3}, Eigen::Vector3d(1.0, 0.2, -0.3),
                                                    Eigen::Vector3d(0.1, 0.1, 0.2), Eigen::Vector3d(-0.3, 0.8, 0.5),
                                                    tilted_axis, driver_motion(), "h")});
  const DriverMotion stroke(TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, 1.0, 0.3}), DriverReading::value);
  out.push_back({"length 2D", std::make_unique<DrivenLength>(std::vector<int>{6, 7}, std::vector<int>{1, 3},
                                                             Eigen::Vector3d(0.1, 0.2, 0.0),
                                                             Eigen::Vector3d(0.5, 0.9, 0.0), stroke, "l")});
  out.push_back({"length 3D", std::make_unique<DrivenLength>(std::vector<int>{8, 0, 5}, std::vector<int>{2, 4, 1},
                                                             Eigen::Vector3d(0.1, 0.2, -0.3),
                                                             Eigen::Vector3d(0.7, -0.1, 0.4), driver_motion(), "l")});
  return out;
}

Eigen::VectorXd random_vector(std::mt19937& rng, int size) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::VectorXd v(size);
  for (int i = 0; i < size; ++i) v[i] = unit(rng);
  return v;
}

double random_time(std::mt19937& rng) { return std::uniform_real_distribution<double>(0.1, 0.9)(rng); }

Eigen::VectorXd phi(const Constraint& c, const Eigen::VectorXd& q, double t) {
  Eigen::VectorXd value(c.n_equations());
  Eigen::MatrixXd jacobian(c.n_equations(), c.dofs().size());
  c.evaluate(q, t, value, jacobian);
  return value;
}

Eigen::MatrixXd jacobian(const Constraint& c, const Eigen::VectorXd& q, double t) {
  Eigen::VectorXd value(c.n_equations());
  Eigen::MatrixXd local(c.n_equations(), c.dofs().size());
  c.evaluate(q, t, value, local);
  return local;
}

// The local Jacobian scattered to all kDofs columns.
Eigen::MatrixXd global_jacobian(const Constraint& c, const Eigen::VectorXd& q, double t) {
  const Eigen::MatrixXd local = jacobian(c, q, t);
  Eigen::MatrixXd global = Eigen::MatrixXd::Zero(c.n_equations(), q.size());
  for (std::size_t j = 0; j < c.dofs().size(); ++j) global.col(c.dofs()[j]) = local.col(j);
  return global;
}

// Tolerances are absolute for quantities of size ~1 and relative beyond: the hinge angle's
// derivatives grow as 1/|arm|ⁿ on random states with short arms, and so do the truncation
// errors of their differences.
double scale(const Eigen::MatrixXd& analytic) { return std::max(1.0, analytic.cwiseAbs().maxCoeff()); }

struct Rates {
  Eigen::VectorXd phi_t, bias;
};
Rates rates(const Constraint& c, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t) {
  Rates r{Eigen::VectorXd(c.n_equations()), Eigen::VectorXd(c.n_equations())};
  c.time_derivatives(q, v, t, r.phi_t, r.bias);
  return r;
}

TEST(ConstraintDerivatives, JacobianMatchesFiniteDifferences) {
  std::mt19937 rng(1);
  for (const Case& c : cases()) {
    for (int k = 0; k < kSamples; ++k) {
      const Eigen::VectorXd q = random_vector(rng, kDofs);
      const double t = random_time(rng);
      const Eigen::MatrixXd fd =
          testing::central_jacobian([&](const Eigen::VectorXd& y) { return phi(*c.constraint, y, t); }, q, kStep);
      EXPECT_LT((global_jacobian(*c.constraint, q, t) - fd).cwiseAbs().maxCoeff(), kDerivativeTolerance)
          << c.name << ", t = " << t;
    }
  }
}

TEST(ConstraintDerivatives, HessianTermMatchesFiniteDifferencesOfTheConstraintForce) {
  std::mt19937 rng(2);
  for (const Case& c : cases()) {
    const Constraint& con = *c.constraint;
    const auto n_local = static_cast<Eigen::Index>(con.dofs().size());
    for (int k = 0; k < kSamples; ++k) {
      const Eigen::VectorXd q = random_vector(rng, kDofs);
      const Eigen::VectorXd lambda = random_vector(rng, con.n_equations());
      const double t = random_time(rng);
      // Bᵀλ as a function of the local unknowns.
      Eigen::VectorXd q_local(n_local);
      for (Eigen::Index j = 0; j < n_local; ++j) q_local[j] = q[con.dofs()[j]];
      const auto force = [&](const Eigen::VectorXd& y_local) {
        Eigen::VectorXd y = q;
        for (Eigen::Index j = 0; j < n_local; ++j) y[con.dofs()[j]] = y_local[j];
        return Eigen::VectorXd(jacobian(con, y, t).transpose() * lambda);
      };
      Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero(n_local, n_local);
      con.add_hessian_term(q, t, lambda, hessian);
      EXPECT_LT((hessian - testing::central_jacobian(force, q_local, kStep)).cwiseAbs().maxCoeff(),
                kDerivativeTolerance * scale(hessian))
          << c.name;
    }
  }
}

TEST(ConstraintDerivatives, TimeDerivativeMatchesFiniteDifferences) {
  std::mt19937 rng(3);
  for (const Case& c : cases()) {
    for (int k = 0; k < kSamples; ++k) {
      const Eigen::VectorXd q = random_vector(rng, kDofs);
      const double t = random_time(rng);
      const Eigen::VectorXd fd = (phi(*c.constraint, q, t + kStep) - phi(*c.constraint, q, t - kStep)) / (2 * kStep);
      const Rates r = rates(*c.constraint, q, random_vector(rng, kDofs), t);
      EXPECT_LT((r.phi_t - fd).cwiseAbs().maxCoeff(), kDerivativeTolerance) << c.name << ", t = " << t;
    }
  }
}

// ∂(Bᵀλ)/∂t at fixed q and λ (continuation in the driver's time) against central differences.
TEST(ConstraintDerivatives, ForceTimeDerivativeMatchesFiniteDifferences) {
  std::mt19937 rng(6);
  for (const Case& c : cases()) {
    const Constraint& con = *c.constraint;
    for (int k = 0; k < kSamples; ++k) {
      const Eigen::VectorXd q = random_vector(rng, kDofs);
      const Eigen::VectorXd lambda = random_vector(rng, con.n_equations());
      const double t = random_time(rng);
      const auto force = [&](double time) { return Eigen::VectorXd(jacobian(con, q, time).transpose() * lambda); };
      const Eigen::VectorXd fd = (force(t + kStep) - force(t - kStep)) / (2 * kStep);
      Eigen::VectorXd analytic = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(con.dofs().size()));
      con.add_force_time_derivative(q, t, lambda, analytic);
      EXPECT_LT((analytic - fd).cwiseAbs().maxCoeff(), kDerivativeTolerance) << c.name << ", t = " << t;
    }
  }
}

// Along q(t) = q0 + v0 t + ½ a t², Φ̈ from a second difference equals B q̈ + bias.
TEST(ConstraintDerivatives, BiasCompletesTheSecondTimeDerivative) {
  std::mt19937 rng(4);
  for (const Case& c : cases()) {
    for (int k = 0; k < kSamples; ++k) {
      const Eigen::VectorXd q0 = random_vector(rng, kDofs), v0 = random_vector(rng, kDofs);
      const Eigen::VectorXd a = random_vector(rng, kDofs);
      const double t = random_time(rng);
      const auto q_at = [&](double time) -> Eigen::VectorXd { return q0 + time * v0 + 0.5 * time * time * a; };
      const auto phi_along = [&](double time) { return phi(*c.constraint, q_at(time), time); };
      const double d = kSecondStep;
      const Eigen::VectorXd fd = (phi_along(t + d) - 2.0 * phi_along(t) + phi_along(t - d)) / (d * d);
      const Rates r = rates(*c.constraint, q_at(t), v0 + t * a, t);
      const Eigen::VectorXd analytic = global_jacobian(*c.constraint, q_at(t), t) * a + r.bias;
      EXPECT_LT((analytic - fd).cwiseAbs().maxCoeff(), kBiasTolerance * scale(analytic)) << c.name << ", t = " << t;
    }
  }
}

// A driven bar that satisfies its constraint at t: pivot p, tip p + l·R(axis, s(t))·u0.
struct DrivenBar {
  std::unique_ptr<DrivenBarAngle> constraint;
  Eigen::VectorXd q;
  Eigen::Vector3d axis, d;  // rotation axis, x_b − x_a
  std::vector<int> tip_dofs;
};

DrivenBar driven_bar(int dimension, double t, double stretch) {
  const Eigen::Vector3d axis =
      dimension == 2 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d(0.3, -0.5, 1.0).normalized();
  const Eigen::Vector3d pivot(0.1, 0.2, dimension == 2 ? 0.0 : -0.3);
  const Eigen::Vector3d tip(0.7, -0.1, dimension == 2 ? 0.0 : 0.4);
  const std::vector<int> pivot_dofs = dimension == 2 ? std::vector<int>{6, 7} : std::vector<int>{8, 0, 5};
  const std::vector<int> tip_dofs = dimension == 2 ? std::vector<int>{1, 3} : std::vector<int>{2, 4, 1};
  DrivenBar out{std::make_unique<DrivenBarAngle>(pivot_dofs, tip_dofs, pivot, tip, axis, driver_motion(), "d"),
                Eigen::VectorXd::Zero(kDofs), axis, Eigen::Vector3d::Zero(), tip_dofs};
  out.d = stretch * (Eigen::AngleAxisd(driver_motion().position(t), axis) * (tip - pivot));
  for (int i = 0; i < dimension; ++i) {
    out.q[pivot_dofs[i]] = pivot[i];
    out.q[tip_dofs[i]] = pivot[i] + out.d[i];
  }
  return out;
}

// The driver holds the bar on its initial direction turned by s(t) about the axis, whatever
// its length, and nowhere else: turning the tip off that direction by δ ⟂ d gives |Φ| = |δ|,
// the normals n_k being orthonormal across the bar (up to the chord's tilt, 0.005 rad here).
TEST(ConstraintDerivatives, DriverHoldsTheBarOnItsTurnedDirection) {
  constexpr double t = 0.6;
  for (int dimension : {2, 3}) {
    const DrivenBar bar = driven_bar(dimension, t, 1.3);
    EXPECT_LT(phi(*bar.constraint, bar.q, t).cwiseAbs().maxCoeff(), kTorqueTolerance) << dimension << "D";
    const Eigen::Vector3d other_axis = dimension == 2 ? bar.axis : bar.axis.cross(bar.d).normalized();
    for (const Eigen::Vector3d& axis : {bar.axis, other_axis}) {
      const Eigen::Vector3d turned = Eigen::AngleAxisd(0.01, axis) * bar.d;
      Eigen::VectorXd q = bar.q;
      for (int i = 0; i < dimension; ++i) q[bar.tip_dofs[i]] += turned[i] - bar.d[i];
      const double offset = (turned - bar.d).norm();
      EXPECT_NEAR(phi(*bar.constraint, q, t).norm(), offset, kOffDirectionTolerance * offset) << dimension << "D";
    }
  }
}

TEST(ConstraintDerivatives, DriverTorqueIsMinusLambdaTimesLengthIn2D) {
  constexpr double t = 0.6, lambda = -3.7;
  const DrivenBar bar = driven_bar(2, t, 1.05);
  ASSERT_LT(phi(*bar.constraint, bar.q, t).cwiseAbs().maxCoeff(), 1e-14);
  const Eigen::VectorXd multipliers = Eigen::VectorXd::Constant(1, lambda);
  EXPECT_NEAR(bar.constraint->torque(bar.q, t, multipliers), -lambda * bar.d.norm(), kTorqueTolerance);
}

// Turning the bar rigidly about the axis by δs moves the tip by δs·(axis × d). The torque is
// the power of the constraint force −Bᵀλ in that motion per unit δs; and since the motion
// keeps Φ = 0 while s advances, B δq = −∂Φ/∂s δs, the same power is +λᵀ ∂Φ/∂s = λᵀ Φ_t / ṡ.
TEST(ConstraintDerivatives, DriverTorqueIsThePowerOfTheConstraintForce) {
  constexpr double t = 0.6;
  std::mt19937 rng(5);
  for (int dimension : {2, 3}) {
    const DrivenBar bar = driven_bar(dimension, t, 0.97);
    const DrivenBarAngle& con = *bar.constraint;
    const Eigen::VectorXd lambda = random_vector(rng, con.n_equations());
    Eigen::VectorXd rigid_rotation = Eigen::VectorXd::Zero(kDofs);
    const Eigen::Vector3d tip_velocity = bar.axis.cross(bar.d);
    for (int i = 0; i < dimension; ++i) rigid_rotation[bar.tip_dofs[i]] = tip_velocity[i];
    const Eigen::VectorXd constraint_force = -global_jacobian(con, bar.q, t).transpose() * lambda;
    const double torque = con.torque(bar.q, t, lambda);
    EXPECT_NEAR(torque, constraint_force.dot(rigid_rotation), kTorqueTolerance) << dimension << "D";

    const Rates r = rates(con, bar.q, Eigen::VectorXd::Zero(kDofs), t);
    EXPECT_NEAR(torque, lambda.dot(r.phi_t) / driver_motion().velocity(t), kTorqueTolerance) << dimension << "D";
    // The rigid rotation is indeed the imposed motion: B δq + ∂Φ/∂s = 0.
    EXPECT_LT((global_jacobian(con, bar.q, t) * rigid_rotation + r.phi_t / driver_motion().velocity(t))
                  .cwiseAbs()
                  .maxCoeff(),
              kTorqueTolerance)
        << dimension << "D";
  }
}

// The actuator's force is the power of its constraint force per unit of extension: moving B
// by δ along the line A→B (the actuator longer by δ) takes −Bᵀλ · δ = effort · δ, the effort
// positive when it pushes the ends apart.
TEST(ConstraintDerivatives, LengthDriverEffortIsThePowerOfItsForceAlongTheLine) {
  for (int dimension : {2, 3}) {
    const std::vector<int> a = dimension == 2 ? std::vector<int>{6, 7} : std::vector<int>{8, 0, 5};
    const std::vector<int> b = dimension == 2 ? std::vector<int>{1, 3} : std::vector<int>{2, 4, 1};
    const Eigen::Vector3d xa(0.1, 0.2, dimension == 2 ? 0.0 : -0.3), xb(0.7, -0.1, dimension == 2 ? 0.0 : 0.4);
    const DrivenLength actuator(a, b, xa, xb, driver_motion(), "l");
    Eigen::VectorXd q = Eigen::VectorXd::Zero(kDofs);
    for (int i = 0; i < dimension; ++i) q[a[i]] = xa[i], q[b[i]] = xb[i];
    const Eigen::VectorXd lambda = Eigen::VectorXd::Constant(1, 2.5);
    const Eigen::VectorXd constraint_force = -(global_jacobian(actuator, q, 0.3).transpose() * lambda);
    Eigen::VectorXd longer = Eigen::VectorXd::Zero(kDofs);
    const Eigen::Vector3d along = (xb - xa).normalized();
    for (int i = 0; i < dimension; ++i) longer[b[i]] = along[i];
    EXPECT_NEAR(actuator.effort(q, 0.3, lambda), constraint_force.dot(longer), kTorqueTolerance) << dimension << "D";
    EXPECT_LT(actuator.effort(q, 0.3, lambda), 0.0) << "λ > 0 pulls the ends together";
  }
}

}  // namespace
}  // namespace deploydyn
