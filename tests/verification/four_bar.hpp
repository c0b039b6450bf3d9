#pragma once
// Two answers for the paper's four-bar linkages obtained without deploydyn's solvers:
//   RigidFourBar      closed-form kinematics of the rigid linkage (loop closure and its time
//                     derivatives), for verification 4;
//   FlexibleGeneralLinkage  the elastic general linkage as an ODE in its three free coordinates,
//                     integrated by classical Runge–Kutta, for verifications 5 and 6.
// Both read the geometry from a loaded Model and the driven angle from its driver:
//   θ(t) = θ0 + ∫₀ᵗ ω,   θ̇ = ω,   θ̈ = ω̇    (the profile read as an angular velocity).

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"

namespace deploydyn::verification {

using Vector2 = Eigen::Vector2d;

inline Vector2 perpendicular(const Vector2& v) { return {-v.y(), v.x()}; }
inline double cross(const Vector2& a, const Vector2& b) { return a.x() * b.y() - a.y() * b.x(); }

inline int node_named(const Model& model, const std::string& name) {
  for (int i = 0; i < model.n_nodes(); ++i) {
    if (model.nodes[i].name == name) return i;
  }
  throw std::invalid_argument("four_bar: the model has no node " + name);
}

// The driven bar turns about ground pivot O1 (its tip P at O1 + Ld (cos θ, sin θ)); the free
// joint Q closes the loop: |Q − P| = Lc (coupler), |Q − O2| = Lr (other bar about ground pivot
// O2). Differentiating the two closure equations once and twice gives linear systems in Q̇, Q̈:
//   (Q−P)·(Q̇−Ṗ) = 0,                    (Q−O2)·Q̇ = 0
//   (Q−P)·(Q̈−P̈) + |Q̇−Ṗ|² = 0,          (Q−O2)·Q̈ + |Q̇|² = 0
// with Ṗ = Ld θ̇ e⊥, P̈ = Ld (θ̈ e⊥ − θ̇² e), e = (cos θ, sin θ).
class RigidFourBar {
 public:
  struct Motion {
    Vector2 x, v, a;  // position (m), velocity (m/s), acceleration (m/s²)
  };
  struct State {
    Motion tip, joint;  // P (driven bar's moving end) and Q (the other moving joint)
  };

  // From a model whose only driver turns one bar about one ground pivot; node names of the
  // driven tip and free joint are returned by tip_node()/joint_node().
  explicit RigidFourBar(const Model& model) : omega_(model.drivers.at(0).profile) {
    const Driver& driver = model.drivers.at(0);
    const BarElement& driven = model.bars.at(driver.element);
    pivot_node_ = driver.pivot;
    tip_node_ = driven.node_a == driver.pivot ? driven.node_b : driven.node_a;
    // The bar from the tip that is not the driven one is the coupler; its far end is Q.
    for (const BarElement& bar : model.bars) {
      if (&bar == &driven) continue;
      if (bar.node_a == tip_node_ || bar.node_b == tip_node_) {
        joint_node_ = bar.node_a == tip_node_ ? bar.node_b : bar.node_a;
        coupler_length_ = bar.reference_length_m;
      }
    }
    for (const BarElement& bar : model.bars) {
      if ((bar.node_a == joint_node_ || bar.node_b == joint_node_) && bar.node_a != tip_node_ &&
          bar.node_b != tip_node_) {
        other_pivot_node_ = bar.node_a == joint_node_ ? bar.node_b : bar.node_a;
        other_length_ = bar.reference_length_m;
      }
    }
    driven_length_ = driven.reference_length_m;
    o1_ = model.nodes[pivot_node_].position_m.head<2>();
    o2_ = model.nodes[other_pivot_node_].position_m.head<2>();
    const Vector2 p0 = model.nodes[tip_node_].position_m.head<2>();
    const Vector2 q0 = model.nodes[joint_node_].position_m.head<2>();
    theta0_ = std::atan2(p0.y() - o1_.y(), p0.x() - o1_.x());
    branch_ = cross(o2_ - p0, q0 - p0) > 0.0 ? 1.0 : -1.0;
  }

  int tip_node() const { return tip_node_; }
  int joint_node() const { return joint_node_; }

  double angle(double t) const { return theta0_ + omega_.integral(t); }

  State at(double t) const {
    const double theta = angle(t), rate = omega_.value(t), acceleration = omega_.derivative(t);
    const Vector2 e(std::cos(theta), std::sin(theta));
    const Vector2 n = perpendicular(e);
    State s;
    s.tip.x = o1_ + driven_length_ * e;
    s.tip.v = driven_length_ * rate * n;
    s.tip.a = driven_length_ * (acceleration * n - rate * rate * e);

    const Vector2 d = o2_ - s.tip.x;
    const double distance = d.norm();
    const double along = (coupler_length_ * coupler_length_ - other_length_ * other_length_ + distance * distance) /
                         (2.0 * distance);
    const double height_sq = coupler_length_ * coupler_length_ - along * along;
    if (height_sq < 0.0) throw std::runtime_error("RigidFourBar: the loop does not close (dead centre passed)");
    const Vector2 unit = d / distance;
    s.joint.x = s.tip.x + along * unit + branch_ * std::sqrt(height_sq) * perpendicular(unit);

    Eigen::Matrix2d jacobian;
    jacobian.row(0) = (s.joint.x - s.tip.x).transpose();
    jacobian.row(1) = (s.joint.x - o2_).transpose();
    const Eigen::PartialPivLU<Eigen::Matrix2d> lu(jacobian);
    s.joint.v = lu.solve(Vector2((s.joint.x - s.tip.x).dot(s.tip.v), 0.0));
    const Vector2 relative = s.joint.v - s.tip.v;
    s.joint.a = lu.solve(Vector2((s.joint.x - s.tip.x).dot(s.tip.a) - relative.squaredNorm(),
                                 -s.joint.v.squaredNorm()));
    return s;
  }

 private:
  TimeFunction omega_;
  int pivot_node_ = 0, tip_node_ = 0, joint_node_ = 0, other_pivot_node_ = 0;
  double driven_length_ = 0.0, coupler_length_ = 0.0, other_length_ = 0.0;
  Vector2 o1_, o2_;
  double theta0_ = 0.0, branch_ = 1.0;
};

// The general linkage (crank 1 = A–B driven about A, coupler 2 = B–C, rocker 3 = C–D, A and D
// pinned) with elastic bars, written for the test in its free coordinates
//   p = (r, C_x, C_y):   B = A + r e(θ(t)),  r the crank's current length.
// Same physics as deploydyn, derived by hand: bar energy U = ½ EA L0 (ε − αΔT)², ε the
// Green–Lagrange strain; consistent bar masses, so with A, D fixed the kinetic energy is
//   T = ½ (m1 + m2)/3 |Ḃ|² + (m2/6) Ḃ·Ċ + ½ (m2 + m3)/3 |Ċ|².
// Lagrange's equations in p (δB = δr e; the driver's reaction is normal to e and does no
// virtual work), with B̈ = r̈ e + w, w = −r θ̇² e + (2 ṙ θ̇ + r θ̈) e⊥:
//   M_BB r̈ + M_BC e·C̈       = e·F_B + M_BB r θ̇²
//   M_BC r̈ e + M_CC C̈       = F_C − M_BC w
// with M_BB = (m1 + m2)/3, M_BC = m2/6, M_CC = (m2 + m3)/3, F = −∂U/∂x.
class FlexibleGeneralLinkage {
 public:
  using State = Eigen::Matrix<double, 6, 1>;  // r, C_x, C_y, ṙ, Ċ_x, Ċ_y

  struct Bar {
    double reference_length_m, axial_stiffness_N, mass_kg, thermal_strain;
  };
  struct Sample {
    double time_s;
    Vector2 b, c;                  // node positions (m)
    double strain[3];              // total Green–Lagrange, bars 1–3
    double axial_force_N[3];       // true axial force N = EA ε_m l / L0
  };

  // `temperature_change_C` is applied to the three bars, as the examples' thermal.dT does.
  FlexibleGeneralLinkage(const Model& model, double temperature_change_C) : omega_(model.drivers.at(0).profile) {
    a_ = model.nodes[node_named(model, "A")].position_m.head<2>();
    d_ = model.nodes[node_named(model, "D")].position_m.head<2>();
    const Vector2 b0 = model.nodes[node_named(model, "B")].position_m.head<2>();
    const Vector2 c0 = model.nodes[node_named(model, "C")].position_m.head<2>();
    theta0_ = std::atan2(b0.y() - a_.y(), b0.x() - a_.x());
    for (int i = 0; i < 3; ++i) {
      const BarElement& e = model.bars.at(i);
      const Material& material = model.materials.at(e.material);
      bars_[i] = {e.reference_length_m, material.youngs_modulus_Pa * e.area_m2, e.mass_kg,
                  material.expansion_per_C * temperature_change_C};
    }
    mass_bb_ = (bars_[0].mass_kg + bars_[1].mass_kg) / 3.0;
    mass_bc_ = bars_[1].mass_kg / 6.0;
    mass_cc_ = (bars_[1].mass_kg + bars_[2].mass_kg) / 3.0;

    // Initial thermal equilibrium: the linkage is statically determinate, so every bar takes
    // its free length L0 √(1 + 2αΔT) unstressed; C on the same side of B–D as in the model.
    const auto free_length = [&](int i) { return bars_[i].reference_length_m * std::sqrt(1.0 + 2.0 * bars_[i].thermal_strain); };
    const double r0 = free_length(0);
    const Vector2 b = a_ + r0 * Vector2(std::cos(theta0_), std::sin(theta0_));
    const double l2 = free_length(1), l3 = free_length(2);
    const Vector2 bd = d_ - b;
    const double distance = bd.norm();
    const double along = (l2 * l2 - l3 * l3 + distance * distance) / (2.0 * distance);
    const double branch = cross(d_ - b0, c0 - b0) > 0.0 ? 1.0 : -1.0;
    const Vector2 c = b + along * bd / distance + branch * std::sqrt(l2 * l2 - along * along) * perpendicular(bd / distance);
    initial_.setZero();
    initial_ << r0, c.x(), c.y(), 0.0, 0.0, 0.0;  // from rest: ω(0) = 0
  }

  const State& initial_state() const { return initial_; }

  State rate(double t, const State& y) const {
    const double theta = theta0_ + omega_.integral(t);
    const double theta_rate = omega_.value(t), theta_acceleration = omega_.derivative(t);
    const Vector2 e(std::cos(theta), std::sin(theta));
    const Vector2 n = perpendicular(e);
    const double r = y[0], r_rate = y[3];
    const Vector2 b = a_ + r * e, c(y[1], y[2]);
    // −∂U/∂x_b = −(EA ε_m / L0) d for a bar from a to b, d = x_b − x_a.
    const auto pull_on_end = [&](int i, const Vector2& from, const Vector2& to) -> Vector2 {
      const Bar& bar = bars_[i];
      const Vector2 d = to - from;
      const double strain = (d.squaredNorm() - bar.reference_length_m * bar.reference_length_m) /
                            (2.0 * bar.reference_length_m * bar.reference_length_m);
      return -(bar.axial_stiffness_N * (strain - bar.thermal_strain) / bar.reference_length_m) * d;
    };
    const Vector2 force_b = pull_on_end(0, a_, b) - pull_on_end(1, b, c);
    const Vector2 force_c = pull_on_end(1, b, c) + pull_on_end(2, d_, c);
    const Vector2 w = -r * theta_rate * theta_rate * e + (2.0 * r_rate * theta_rate + r * theta_acceleration) * n;

    Eigen::Matrix3d mass;
    mass << mass_bb_, mass_bc_ * e.x(), mass_bc_ * e.y(),  //
        mass_bc_ * e.x(), mass_cc_, 0.0,                    //
        mass_bc_ * e.y(), 0.0, mass_cc_;
    Eigen::Vector3d rhs;
    rhs[0] = e.dot(force_b) + mass_bb_ * r * theta_rate * theta_rate;
    rhs.tail<2>() = force_c - mass_bc_ * w;
    const Eigen::Vector3d acceleration = mass.ldlt().solve(rhs);

    State out;
    out << y.tail<3>(), acceleration;
    return out;
  }

  Sample sample(double t, const State& y) const {
    const double theta = theta0_ + omega_.integral(t);
    Sample s;
    s.time_s = t;
    s.b = a_ + y[0] * Vector2(std::cos(theta), std::sin(theta));
    s.c = Vector2(y[1], y[2]);
    const Vector2 ends[3][2] = {{a_, s.b}, {s.b, s.c}, {s.c, d_}};
    for (int i = 0; i < 3; ++i) {
      const Bar& bar = bars_[i];
      const double l = (ends[i][1] - ends[i][0]).norm();
      const double l0 = bar.reference_length_m;
      s.strain[i] = (l * l - l0 * l0) / (2.0 * l0 * l0);
      s.axial_force_N[i] = bar.axial_stiffness_N * (s.strain[i] - bar.thermal_strain) * l / l0;
    }
    return s;
  }

  // Classical fourth-order Runge–Kutta with `steps_per_sample` steps of `step_s` between samples,
  // from t = 0 to `n_samples − 1` sample intervals.
  std::vector<Sample> integrate(double step_s, int steps_per_sample, int n_samples) const {
    std::vector<Sample> samples;
    samples.reserve(n_samples);
    State y = initial_;
    long step = 0;
    samples.push_back(sample(0.0, y));
    for (int k = 1; k < n_samples; ++k) {
      for (int i = 0; i < steps_per_sample; ++i, ++step) {
        const double t = static_cast<double>(step) * step_s;
        const State k1 = rate(t, y);
        const State k2 = rate(t + 0.5 * step_s, y + 0.5 * step_s * k1);
        const State k3 = rate(t + 0.5 * step_s, y + 0.5 * step_s * k2);
        const State k4 = rate(t + step_s, y + step_s * k3);
        y += (step_s / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      }
      samples.push_back(sample(static_cast<double>(step) * step_s, y));
    }
    return samples;
  }

 private:
  TimeFunction omega_;
  Vector2 a_, d_;
  double theta0_ = 0.0;
  Bar bars_[3];
  double mass_bb_ = 0.0, mass_bc_ = 0.0, mass_cc_ = 0.0;
  State initial_;
};

}  // namespace deploydyn::verification
