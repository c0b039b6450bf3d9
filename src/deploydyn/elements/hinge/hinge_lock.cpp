#include "deploydyn/elements/hinge/hinge_lock.hpp"

namespace deploydyn {

HingeLock::HingeLock(const HingeRecord& record, const HingeModes& modes, int hinge, std::string label)
    : Constraint(1, record.dofs), record_(record), modes_(modes), hinge_(hinge), label_(std::move(label)) {}

void HingeLock::evaluate(const Eigen::VectorXd& q, double /*t*/, Eigen::Ref<Eigen::VectorXd> phi,
                         Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  if (!active()) {
    phi.setZero();
    jacobian.setZero();
    return;
  }
  const HingeKinematics k = record_.kinematics(record_.gather(q));
  phi[0] = k.angle_rad - modes_.lock_angle_rad[static_cast<std::size_t>(hinge_)];
  jacobian.row(0) = k.gradient.transpose();
}

void HingeLock::add_hessian_term(const Eigen::VectorXd& q, double /*t*/,
                                 Eigen::Ref<const Eigen::VectorXd> lambda,
                                 Eigen::Ref<Eigen::MatrixXd> hessian) const {
  if (!active()) return;
  hessian += lambda[0] * record_.kinematics(record_.gather(q)).hessian;
}

void HingeLock::time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double /*t*/,
                                 Eigen::Ref<Eigen::VectorXd> phi_t,
                                 Eigen::Ref<Eigen::VectorXd> bias) const {
  phi_t.setZero();  // θ_lock does not move
  bias.setZero();
  if (!active()) return;
  const HingeVector rates = record_.gather(v);
  bias[0] = rates.dot(record_.kinematics(record_.gather(q)).hessian * rates);  // q̇ᵀ ∇²θ q̇
}

std::string HingeLock::describe(int /*row*/) const {
  switch (modes_.mode[static_cast<std::size_t>(hinge_)]) {
    case HingeMode::latched: return label_ + " (latched)";
    case HingeMode::stop_min: return label_ + " (at its lower stop)";
    case HingeMode::stop_max: return label_ + " (at its upper stop)";
    case HingeMode::stuck: return label_ + " (sticking by friction)";
    case HingeMode::held: return label_ + " (held at its initial angle until released)";
    case HingeMode::free: break;
  }
  return label_ + " (free)";
}

}  // namespace deploydyn
