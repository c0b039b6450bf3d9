// What the pin joint and the two one-angle drivers constrain, and nothing more (docs/theory.md,
// "Constraints"): the pin keeps positions and (3D frames) the axis; the revolute driver
// prescribes the relative rotation about that axis; the hinge-angle driver the angle A–H–B
// about its axis. Their efforts are torques: the power of the constraint force per unit of
// the driven rotation. Derivatives: constraint_derivatives_test.cpp.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <vector>

#include "deploydyn/constraints/driven_hinge_angle.hpp"
#include "deploydyn/constraints/driven_revolute.hpp"
#include "deploydyn/constraints/pin_joint.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kRoundOff = 1e-12;
// A first-order statement checked with a rotation of δ = 1e-6 rad: the second-order rest is δ².
constexpr double kSmallRotation = 1e-6;
constexpr double kFirstOrderTolerance = 1e-10;

// A value-read motion s(t) = t (rad): the driven angle at time t is t.
DriverMotion angle_equal_to_time() {
  return DriverMotion(TimeFunction(TimeFunction::Table{{0.0, 10.0}, {0.0, 10.0}}), DriverReading::value);
}

std::vector<int> range(int first, int count) {
  std::vector<int> out;
  for (int i = 0; i < count; ++i) out.push_back(first + i);
  return out;
}

// Unknowns of two 3D beam nodes: R_A at 0..8, R_B at 9..17 (row-major).
Eigen::VectorXd frames(const Eigen::Matrix3d& r_a, const Eigen::Matrix3d& r_b) {
  Eigen::VectorXd q(18);
  for (int m = 0; m < 3; ++m) {
    for (int j = 0; j < 3; ++j) {
      q[3 * m + j] = r_a(m, j);
      q[9 + 3 * m + j] = r_b(m, j);
    }
  }
  return q;
}

double phi(const Constraint& c, const Eigen::VectorXd& q, double t, int row = 0) {
  Eigen::VectorXd value(c.n_equations());
  Eigen::MatrixXd jacobian(c.n_equations(), c.dofs().size());
  c.evaluate(q, t, value, jacobian);
  return value[row];
}

const Eigen::Vector3d kAxis = Eigen::Vector3d(0.3, -0.5, 1.0).normalized();
const Eigen::Matrix3d kFrameA =
    (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized())).toRotationMatrix();

TEST(RevoluteDriver, ZeroAtThePrescribedRelativeRotationAboutTheAxisOnly) {
  const DrivenRevolute driver(range(0, 9), range(9, 9), kAxis, angle_equal_to_time(), "r");
  constexpr double t = 0.9;  // s = 0.9 rad
  for (const double psi : {0.9, 0.9 + 0.2, 0.9 - 0.5}) {
    const Eigen::Matrix3d r_b = kFrameA * Eigen::AngleAxisd(psi, kAxis).toRotationMatrix();
    EXPECT_NEAR(phi(driver, frames(kFrameA, r_b), t), std::sin(psi - t), kRoundOff) << psi;
  }
  // At ψ = s, tilting B about the two directions ⟂ axis leaves Φ unchanged to first order;
  // turning it about the axis changes Φ by the angle (∂Φ/∂ψ = 1: λ is the torque).
  const Eigen::Matrix3d r_b = kFrameA * Eigen::AngleAxisd(t, kAxis).toRotationMatrix();
  const Eigen::Vector3d normal = kAxis.unitOrthogonal();
  for (const Eigen::Vector3d& direction : {normal, kAxis.cross(normal), kAxis}) {
    const Eigen::Matrix3d turned = Eigen::AngleAxisd(kSmallRotation, r_b * direction).toRotationMatrix() * r_b;
    const double expected = direction == kAxis ? kSmallRotation : 0.0;
    EXPECT_NEAR(phi(driver, frames(kFrameA, turned), t), expected, kFirstOrderTolerance);
  }
  const Eigen::VectorXd lambda = Eigen::VectorXd::Constant(1, 2.5);
  EXPECT_NEAR(driver.effort(frames(kFrameA, r_b), t, lambda), -2.5, kRoundOff);
}

// With A's frame held, B's nine unknowns are fixed by orthonormality RᵀR = I (6 equations, as
// the 3D beam adds them), the pin's axis (2) and the revolute driver (1): a square system
// whose Newton iteration must land on R_B = R_A Rot(a, s), i.e. the three constraints of the
// pin and driver are independent of each other and of orthonormality.
TEST(RevoluteDriver, WithThePinAndOrthonormalityDeterminesTheRelativeRotation) {
  constexpr double s = 0.7;
  const DriverMotion motion(TimeFunction::constant(s), DriverReading::value);
  const PinJoint pin(range(0, 3), range(3, 3), range(6, 9), range(15, 9), kAxis, "pin");
  const DrivenRevolute driver(range(6, 9), range(15, 9), kAxis, motion, "r");
  Eigen::VectorXd q = Eigen::VectorXd::Zero(24);
  q.tail(18) = frames(kFrameA, kFrameA);  // start with ψ = 0
  const auto residual_and_jacobian = [&](Eigen::VectorXd& r, Eigen::MatrixXd& j) {
    r.setZero(9);
    j.setZero(9, 9);
    Eigen::VectorXd value(5);
    Eigen::MatrixXd local(5, 24);
    pin.evaluate(q, 0.0, value, local);
    r.head(2) = value.tail(2);
    j.topRows(2) = local.block(3, 15, 2, 9);  // columns of R_B
    Eigen::VectorXd one(1);
    Eigen::MatrixXd row(1, 18);
    driver.evaluate(q, 0.0, one, row);
    r[2] = one[0];
    j.row(2) = row.rightCols(9);
    int k = 3;
    for (int a = 0; a < 3; ++a) {
      for (int b = a; b < 3; ++b, ++k) {  // Σ_m R[m][a] R[m][b] − δ_ab
        r[k] = (a == b) ? -1.0 : 0.0;
        for (int m = 0; m < 3; ++m) {
          r[k] += q[15 + 3 * m + a] * q[15 + 3 * m + b];
          j(k, 3 * m + a) += q[15 + 3 * m + b];
          j(k, 3 * m + b) += q[15 + 3 * m + a];
        }
      }
    }
  };
  Eigen::VectorXd r;
  Eigen::MatrixXd j;
  for (int iteration = 0; iteration < 20; ++iteration) {
    residual_and_jacobian(r, j);
    if (r.cwiseAbs().maxCoeff() < 1e-14) break;
    q.tail(9) -= j.fullPivLu().solve(r);
  }
  residual_and_jacobian(r, j);
  EXPECT_LT(r.cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_GT(std::abs(j.determinant()), 1e-3) << "the nine conditions are independent";
  const Eigen::Matrix3d expected = kFrameA * Eigen::AngleAxisd(s, kAxis).toRotationMatrix();
  EXPECT_LT((frames(kFrameA, expected).tail(9) - q.tail(9)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(RevoluteDriver, In2DIsTheDifferenceOfTheNodeRotations) {
  const DrivenRevolute driver({0}, {1}, Eigen::Vector3d::UnitZ(), angle_equal_to_time(), "r");
  Eigen::VectorXd q(2);
  q << 0.3, 0.3 + 0.4;
  EXPECT_NEAR(phi(driver, q, 0.4), 0.0, kRoundOff);
  EXPECT_NEAR(driver.effort(q, 0.4, Eigen::VectorXd::Constant(1, 2.5)), -2.5, kRoundOff);
}

// At a hinge to ground A is the ground: the same constraint as the joint's with R_A = I (θ_A = 0
// in 2D), on B's unknowns alone.
TEST(RevoluteDriver, AtAHingeToGroundIsTheJointsWithTheGroundAsA) {
  const DrivenRevolute grounded({}, range(0, 9), kAxis, angle_equal_to_time(), "g");
  const DrivenRevolute joint(range(0, 9), range(9, 9), kAxis, angle_equal_to_time(), "r");
  ASSERT_EQ(grounded.dofs().size(), 9U);
  EXPECT_FALSE(grounded.nonlinear());
  constexpr double t = 0.9;
  const Eigen::VectorXd lambda = Eigen::VectorXd::Constant(1, 2.5);
  for (const double psi : {0.9, 0.9 + 0.2, 0.9 - 0.5}) {
    const Eigen::Matrix3d r_b = Eigen::AngleAxisd(psi, kAxis).toRotationMatrix()  *
                                Eigen::AngleAxisd(0.1 * psi, kAxis.unitOrthogonal()).toRotationMatrix();
    const Eigen::VectorXd q_joint = frames(Eigen::Matrix3d::Identity(), r_b);
    const Eigen::VectorXd q_b = q_joint.tail(9);
    Eigen::VectorXd value_g(1), value_j(1);
    Eigen::MatrixXd jacobian_g(1, 9), jacobian_j(1, 18);
    grounded.evaluate(q_b, t, value_g, jacobian_g);
    joint.evaluate(q_joint, t, value_j, jacobian_j);
    EXPECT_NEAR(value_g[0], value_j[0], kRoundOff) << psi;
    EXPECT_LT((jacobian_g - jacobian_j.rightCols(9)).cwiseAbs().maxCoeff(), kRoundOff) << psi;
    EXPECT_NEAR(grounded.effort(q_b, t, lambda), joint.effort(q_joint, t, lambda), kRoundOff) << psi;
  }
  const Eigen::Matrix3d at_s = Eigen::AngleAxisd(t, kAxis).toRotationMatrix();
  EXPECT_NEAR(phi(grounded, frames(Eigen::Matrix3d::Identity(), at_s).tail(9), t), 0.0, kRoundOff);
  EXPECT_NEAR(grounded.effort(frames(Eigen::Matrix3d::Identity(), at_s).tail(9), t, lambda), -2.5, kRoundOff);

  const DrivenRevolute planar({}, {0}, Eigen::Vector3d::UnitZ(), angle_equal_to_time(), "g");
  const Eigen::VectorXd theta = Eigen::VectorXd::Constant(1, 0.4);
  EXPECT_NEAR(phi(planar, theta, 0.4), 0.0, kRoundOff);
  EXPECT_NEAR(phi(planar, theta, 0.1), 0.3, kRoundOff);
  EXPECT_NEAR(planar.effort(theta, 0.4, lambda), -2.5, kRoundOff);
}

TEST(PinJoint, KeepsPositionsAndTheAxisAndLeavesTheRotationAboutItFree) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(24);
  q.head(6) << 0.1, 0.2, 0.3, 0.1, 0.2, 0.3;  // x_A = x_B
  const PinJoint pin(range(0, 3), range(3, 3), range(6, 9), range(15, 9), kAxis, "pin");
  ASSERT_EQ(pin.n_equations(), 5);
  const auto set_frames = [&](const Eigen::Matrix3d& r_b) { q.tail(18) = frames(kFrameA, r_b); };
  for (const double psi : {0.0, 1.0, -2.5}) {
    set_frames(kFrameA * Eigen::AngleAxisd(psi, kAxis).toRotationMatrix());
    for (int row = 0; row < 5; ++row) EXPECT_NEAR(phi(pin, q, 0.0, row), 0.0, kRoundOff) << psi << ", " << row;
  }
  // Tilting B's frame by δ about a direction ⟂ axis opens the axis by δ: |Φ_axis| = δ.
  const Eigen::Vector3d across = kFrameA * kAxis.unitOrthogonal();
  set_frames(Eigen::AngleAxisd(kSmallRotation, across).toRotationMatrix() * kFrameA);
  const double opening = std::hypot(phi(pin, q, 0.0, 3), phi(pin, q, 0.0, 4));
  EXPECT_NEAR(opening, kSmallRotation, kFirstOrderTolerance);
  // Positions only without rotations.
  EXPECT_EQ(PinJoint(range(0, 3), range(3, 3), {}, {}, kAxis, "ball").n_equations(), 3);
  EXPECT_EQ(PinJoint(range(0, 2), range(2, 2), {}, {}, Eigen::Vector3d::UnitZ(), "2D").n_equations(), 2);
}

// Nodes A, H, B of a 3D hinge about kAxis through H; B turned by `turn` about the axis.
struct Hinge {
  Eigen::Vector3d a{1.0, 0.2, -0.3}, h{0.1, 0.1, 0.2}, b{-0.3, 0.8, 0.5};
  Eigen::VectorXd q(double turn, const Eigen::Vector3d& b_offset = Eigen::Vector3d::Zero()) const {
    const Eigen::Vector3d b_now = h + Eigen::AngleAxisd(turn, kAxis) * (b - h) + b_offset;
    Eigen::VectorXd out(9);
    out << a, h, b_now;
    return out;
  }
  DrivenHingeAngle driver() const {
    return DrivenHingeAngle(range(0, 3), range(3, 3), range(6, 3), a, h, b, kAxis, angle_equal_to_time(), "h");
  }
};

TEST(HingeAngleDriver, FixesTheAngleAboutTheAxisOnly) {
  const Hinge hinge;
  const DrivenHingeAngle driver = hinge.driver();
  constexpr double t = 0.8;
  EXPECT_NEAR(phi(driver, hinge.q(t), t), 0.0, kRoundOff);
  EXPECT_NEAR(phi(driver, hinge.q(t + 0.1), t), 0.1, kRoundOff);
  // B sliding along the axis or along its arm, and the whole hinge turning about the axis,
  // leave the angle.
  const Eigen::Vector3d arm = Eigen::AngleAxisd(t, kAxis) * (hinge.b - hinge.h);
  for (const Eigen::Vector3d& offset : {Eigen::Vector3d(0.3 * kAxis), Eigen::Vector3d(0.2 * arm)}) {
    EXPECT_NEAR(phi(driver, hinge.q(t, offset), t), 0.0, kRoundOff);
  }
  Eigen::VectorXd q = hinge.q(t);
  for (int node = 0; node < 3; ++node) {
    q.segment<3>(3 * node) = hinge.h + Eigen::AngleAxisd(1.3, kAxis) * (q.segment<3>(3 * node) - hinge.h);
  }
  EXPECT_NEAR(phi(driver, q, t), 0.0, kRoundOff);
}

// The effort is the power of the constraint force −Bᵀλ when B turns about the axis through H,
// per unit rotation: a torque in N·m, −λ.
TEST(HingeAngleDriver, EffortIsTheTorqueAboutTheAxis) {
  const Hinge hinge;
  const DrivenHingeAngle driver = hinge.driver();
  constexpr double t = 0.8, lambda = 1.7;
  const Eigen::VectorXd q = hinge.q(t);
  Eigen::VectorXd value(1);
  Eigen::MatrixXd jacobian(1, 9);
  driver.evaluate(q, t, value, jacobian);
  Eigen::VectorXd turn = Eigen::VectorXd::Zero(9);
  turn.segment<3>(6) = kAxis.cross(q.segment<3>(6) - hinge.h);
  const double power = -(jacobian.transpose() * Eigen::VectorXd::Constant(1, lambda)).dot(turn);
  EXPECT_NEAR(driver.effort(q, t, Eigen::VectorXd::Constant(1, lambda)), power, kRoundOff);
  EXPECT_NEAR(power, -lambda, kRoundOff);
}

// Opened past a straight line: θ0 + s crosses π, where atan2 jumps; Φ stays 0 and continuous.
TEST(HingeAngleDriver, HandlesTheWrapAroundAtPi) {
  Hinge hinge;
  hinge.b = hinge.h + Eigen::AngleAxisd(std::numbers::pi - 0.2, kAxis) * (hinge.a - hinge.h);
  const DrivenHingeAngle driver = hinge.driver();
  EXPECT_NEAR(driver.initial_angle(), std::numbers::pi - 0.2, kRoundOff);
  for (const double t : {0.1, 0.19, 0.21, 0.5, 1.0}) {
    EXPECT_NEAR(phi(driver, hinge.q(t), t), 0.0, kRoundOff) << t;
    EXPECT_NEAR(phi(driver, hinge.q(t + 0.05), t), 0.05, kRoundOff) << t;
  }
}

TEST(HingeAngleDriver, RejectsArmsWithoutLengthAcrossTheAxis) {
  const Hinge hinge;
  EXPECT_THROW(DrivenHingeAngle(range(0, 3), range(3, 3), range(6, 3), hinge.h, hinge.h, hinge.b, kAxis,
                                angle_equal_to_time(), "h"),
               std::invalid_argument);
  EXPECT_THROW(DrivenHingeAngle(range(0, 3), range(3, 3), range(6, 3), hinge.a, hinge.h, hinge.h + 0.5 * kAxis,
                                kAxis, angle_equal_to_time(), "h"),
               std::invalid_argument);
}

}  // namespace
}  // namespace deploydyn
