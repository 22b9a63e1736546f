#include "multibody/state.h"

namespace limber::multibody {

State initial_state(const Model& model) {
  State state;
  state.q.setZero(model.nq);
  state.v.setZero(model.nv);
  for (const Body& b : model.bodies) {
    if (b.kind == BodyKind::kGround) continue;
    state.q.segment<3>(b.q_offset) = b.initial_pose.position;
    state.q.segment<4>(b.q_offset + 3) = b.initial_pose.orientation;
    state.v.segment<3>(b.v_offset) = b.initial_velocity_W;
    state.v.segment<3>(b.v_offset + 3) = b.initial_angular_velocity_B;
    if (b.kind == BodyKind::kFlexible) {
      state.q.segment(b.q_offset + 7, b.nq - 7) = b.flexible->initial_modal_coordinates;
      state.v.segment(b.v_offset + 6, b.nv - 6) = b.flexible->initial_modal_velocities;
    }
  }
  return state;
}

Workspace::Workspace(const Model& model)
    : markers(model.markers.size()),
      g(Eigen::VectorXd::Zero(model.num_equations())),
      g_t(Eigen::VectorXd::Zero(model.num_equations())),
      gamma(Eigen::VectorXd::Zero(model.num_equations())),
      G(Eigen::MatrixXd::Zero(model.num_equations(), model.nv)),
      M(Eigen::MatrixXd::Zero(model.nv, model.nv)),
      Q(Eigen::VectorXd::Zero(model.nv)) {}

}  // namespace limber::multibody
