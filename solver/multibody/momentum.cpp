#include "multibody/momentum.h"
#include "multibody/evaluated.h"

#include "multibody/dynamics.h"
#include "multibody/rotation.h"

namespace limber::multibody {
namespace {

// P and L from the generalized momenta p = M v.
Eigen::Matrix<double, 6, 1> momentum_from(const Model& model, const State& state, const Eigen::VectorXd& p) {
  Eigen::Vector3d P = Eigen::Vector3d::Zero(), L = Eigen::Vector3d::Zero();
  // Each moving body's share: its translational momentum and, about the ground origin, its
  // moment plus its angular momentum turned into ground axes.
  for (const Body& body : model.bodies) {
    if (body.kind == BodyKind::kGround) continue;
    const Eigen::Vector3d r = state.q.segment<3>(body.q_offset);
    const Eigen::Matrix3d A = rotation_matrix(state.q.segment<4>(body.q_offset + 3));
    const Eigen::Vector3d P_b = p.segment<3>(body.v_offset);
    P += P_b;
    L += r.cross(P_b) + A * p.segment<3>(body.v_offset + 3);
  }
  Eigen::Matrix<double, 6, 1> out;
  out << P, L;
  return out;
}
}  // namespace

Eigen::Matrix<double, 6, 1> system_momentum(const Model& model, const State& state) {
  return momentum_from(model, state, mass_times(model, state.q, state.v));
}

Eigen::Matrix<double, 6, 1> momentum_of(const Model& model, const State& state, const Eigen::MatrixXd& M) {
  return momentum_from(model, state, M * state.v);
}

}  // namespace limber::multibody
