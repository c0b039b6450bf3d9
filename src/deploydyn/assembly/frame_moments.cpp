#include "deploydyn/assembly/frame_moments.hpp"

#include <Eigen/Geometry>

namespace deploydyn {

FrameMoments::FrameMoments(const Model& model, const DofMap& dofs) {
  if (model.dimension != 3) return;
  for (const NodalLoad& load : model.loads) {
    if (load.moment_Nm.isZero(0.0)) continue;
    const int first = dofs.index(load.node, "R11");  // the loader admits moments on frames only
    Loaded m{load.moment_Nm, &load.factor, {}};
    for (int i = 0; i < 3; ++i) m.columns[static_cast<std::size_t>(i)] = {first + i, first + 3 + i, first + 6 + i};
    moments_.push_back(m);
  }
}

Eigen::Matrix3d FrameMoments::cross_matrix(const Eigen::Vector3d& m) {
  Eigen::Matrix3d c;
  c << 0.0, -m.z(), m.y(),  //
      m.z(), 0.0, -m.x(),   //
      -m.y(), m.x(), 0.0;
  return c;
}

void FrameMoments::add(const Eigen::VectorXd& q, double scale, const Loaded& m, double factor,
                       Eigen::VectorXd& f) const {
  const Eigen::Vector3d half_moment = 0.5 * scale * factor * m.moment_Nm;
  for (const auto& column : m.columns) {
    const Eigen::Vector3d r(q[column[0]], q[column[1]], q[column[2]]);
    const Eigen::Vector3d force = half_moment.cross(r);
    for (int k = 0; k < 3; ++k) f[column[static_cast<std::size_t>(k)]] += force[k];
  }
}

void FrameMoments::add_force(const Eigen::VectorXd& q, double t, double scale, Eigen::VectorXd& f) const {
  for (const Loaded& m : moments_) add(q, scale, m, m.factor->value(t), f);
}

void FrameMoments::add_force_rate(const Eigen::VectorXd& q, double t, double scale, Eigen::VectorXd& f) const {
  for (const Loaded& m : moments_) add(q, scale, m, m.factor->derivative(t), f);
}

}  // namespace deploydyn
