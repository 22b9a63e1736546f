#include "multibody/flexible_marker.h"

#include "core/error.h"
#include "multibody/body.h"
#include "multibody/rotation.h"

namespace limber::multibody {

void node_frame_kinematics(const Model& model, int body, int node, const Eigen::Matrix3d& R_BF,
                           const Eigen::VectorXd& q, const Eigen::VectorXd* v, FrameKinematics& out) {
  const Body& b = model.bodies[body];
  LIMBER_DEMAND(b.kind == BodyKind::kFlexible);
  const FlexibleBody& f = *b.flexible;
  const int nm = f.mode_count();
  // Views with 3 rows known at compile time: the products below need no heap temporaries.
  const auto Phi_t = f.shapes.middleRows<3>(6 * node);
  const auto Phi_r = f.shapes.middleRows<3>(6 * node + 3);
  // Position stage: deformed node position s and elastic rotation θ.
  const Eigen::Matrix3d A = rotation_matrix(q.segment<4>(b.q_offset + 3));
  const auto eta = q.segment(b.q_offset + 7, nm);
  Eigen::Vector3d s = f.node_positions.col(node);
  s.noalias() += Phi_t * eta;
  Eigen::Vector3d theta;
  theta.noalias() = Phi_r * eta;
  const Eigen::Matrix3d J_l = so3_left_jacobian(theta);
  out.p_W = q.segment<3>(b.q_offset) + A * s;
  out.R_WF = A * rotation_vector_matrix(theta) * R_BF;
  // Jacobians over [ṙ, ω, η̇].
  clear_frame_jacobians(model.nv, b.v_offset, b.nv, out);
  out.J_p.block<3, 3>(0, b.v_offset).setIdentity();
  out.J_p.block<3, 3>(0, b.v_offset + 3) = -A * skew(s);
  out.J_p.middleCols(b.v_offset + 6, nm).noalias() = A * Phi_t;
  out.J_w.block<3, 3>(0, b.v_offset + 3) = A;
  const Eigen::Matrix3d A_J_l = A * J_l;
  out.J_w.middleCols(b.v_offset + 6, nm).noalias() = A_J_l * Phi_r;
  if (v == nullptr) return;
  // Velocity stage and the bias accelerations.
  const Eigen::Vector3d w = v->segment<3>(b.v_offset + 3);
  const auto eta_dot = v->segment(b.v_offset + 6, nm);
  Eigen::Vector3d u_dot, theta_dot;
  u_dot.noalias() = Phi_t * eta_dot;
  theta_dot.noalias() = Phi_r * eta_dot;
  const Eigen::Vector3d w_elastic = J_l * theta_dot;
  out.v_W = v->segment<3>(b.v_offset) + A * (w.cross(s) + u_dot);
  out.w_W = A * (w + w_elastic);
  out.a_bias = A * (w.cross(w.cross(s)) + 2.0 * w.cross(u_dot));
  out.alpha_bias = A * (w.cross(w_elastic) + so3_left_jacobian_rate(theta, theta_dot));
}

}  // namespace limber::multibody
