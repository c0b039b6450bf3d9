#include "deploydyn/elements/hinge/hinge_lock.hpp"

namespace deploydyn {

HingeLock::HingeLock(const HingeRecord& record, int hinge, std::string label)
    : SwitchedConstraint(1, record.dofs), record_(record), hinge_(static_cast<std::size_t>(hinge)),
      label_(std::move(label)) {}

void HingeLock::evaluate(const EvaluationPoint& at, Eigen::Ref<Eigen::VectorXd> phi,
                         Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  const HingeState s = state(at);
  if (s.mode == HingeMode::free) {
    // A plain loop: Eigen's setZero on this 1 × n strided block was 5 % of a hinged chain's
    // step (its locks are free after the first step, evaluated with every residual and matrix).
    phi[0] = 0.0;
    for (Eigen::Index c = 0; c < jacobian.cols(); ++c) jacobian(0, c) = 0.0;
    return;
  }
  const HingeKinematics k = record_.angle_and_gradient(record_.gather(at.q));
  phi[0] = k.angle_rad - s.lock_angle_rad;
  jacobian.row(0) = k.gradient.transpose();
}

void HingeLock::add_hessian_term(const EvaluationPoint& at, Eigen::Ref<const Eigen::VectorXd> lambda,
                                 Eigen::Ref<Eigen::MatrixXd> hessian) const {
  if (!active(at.history)) return;
  hessian += lambda[0] * record_.angle_hessian(record_.gather(at.q));  // ∇²θ alone: no θ, ∇θ
}

void HingeLock::time_derivatives(const EvaluationPoint& at, Eigen::Ref<Eigen::VectorXd> phi_t,
                                 Eigen::Ref<Eigen::VectorXd> bias) const {
  phi_t.setZero();  // θ_lock does not move
  bias.setZero();
  if (!active(at.history)) return;
  const HingeVector rates = record_.gather(*at.rates);
  bias[0] = rates.dot(record_.angle_hessian(record_.gather(at.q)) * rates);  // q̇ᵀ ∇²θ q̇
}

std::string HingeLock::describe(int /*row*/, std::span<const double> history) const {
  switch (hinge_state(history, hinge_).mode) {
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
