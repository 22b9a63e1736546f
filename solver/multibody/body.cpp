#include "multibody/body.h"

#include "core/error.h"
#include "multibody/flexible_dynamics.h"
#include "multibody/flexible_marker.h"
#include "multibody/rotation.h"

namespace limber::multibody {

namespace {

Eigen::Vector3d body_position(const Body& b, const Eigen::VectorXd& q) {
  return q.segment<3>(b.q_offset);
}

Eigen::Vector4d body_quaternion(const Body& b, const Eigen::VectorXd& q) {
  return q.segment<4>(b.q_offset + 3);
}

}  // namespace

void clear_frame_jacobians(int nv, int v_offset, int body_nv, FrameKinematics& out) {
  if (out.J_p.cols() != nv || out.J_w.cols() != nv || out.body_v_offset != v_offset || out.body_nv != body_nv) {
    out.J_p.setZero(3, nv);
    out.J_w.setZero(3, nv);
  } else {
    out.J_p.middleCols(v_offset, body_nv).setZero();
    out.J_w.middleCols(v_offset, body_nv).setZero();
  }
  out.body_v_offset = v_offset;
  out.body_nv = body_nv;
}

void marker_kinematics(const Model& model, int marker, const Eigen::VectorXd& q,
                       const Eigen::VectorXd* v, FrameKinematics& out) {
  const Marker& m = model.markers[marker];
  if (m.node >= 0) {
    node_frame_kinematics(model, m.body, m.node, m.R_BM, q, v, out);
  } else {
    body_frame_kinematics(model, m.body, m.p_BM, m.R_BM, q, v, out);
  }
}

void body_frame_kinematics(const Model& model, int body, const Eigen::Vector3d& p_BF,
                           const Eigen::Matrix3d& R_BF, const Eigen::VectorXd& q,
                           const Eigen::VectorXd* v, FrameKinematics& out) {
  const Body& b = model.bodies[body];
  clear_frame_jacobians(model.nv, b.v_offset, b.kind == BodyKind::kGround ? 0 : b.nv, out);
  // Ground: a fixed frame.
  if (b.kind == BodyKind::kGround) {
    out.p_W = p_BF;
    out.R_WF = R_BF;
    out.v_W.setZero();
    out.w_W.setZero();
    out.a_bias.setZero();
    out.alpha_bias.setZero();
    return;
  }
  // Position stage: p = r + A s, R = A R_BF.
  const Eigen::Matrix3d A = rotation_matrix(body_quaternion(b, q));
  const Eigen::Vector3d s_W = A * p_BF;
  out.p_W = body_position(b, q) + s_W;
  out.R_WF = A * R_BF;
  // Jacobians: ṗ = ṙ − A s̃ ω', ω_W = A ω'.
  out.J_p.block<3, 3>(0, b.v_offset).setIdentity();
  out.J_p.block<3, 3>(0, b.v_offset + 3) = -A * skew(p_BF);
  out.J_w.block<3, 3>(0, b.v_offset + 3) = A;
  if (v == nullptr) return;
  // Velocity stage and the bias accelerations J̇ v: A (ω' × (ω' × s)) and 0.
  const Eigen::Vector3d rdot = v->segment<3>(b.v_offset);
  const Eigen::Vector3d w_B = v->segment<3>(b.v_offset + 3);
  out.v_W = rdot + A * w_B.cross(p_BF);
  out.w_W = A * w_B;
  out.a_bias = A * w_B.cross(w_B.cross(p_BF));
  out.alpha_bias.setZero();
}

Eigen::MatrixXd body_mass_block(const Model& model, int body, const Eigen::VectorXd& q) {
  const Body& b = model.bodies[body];
  if (b.kind == BodyKind::kGround) return {};
  if (b.kind == BodyKind::kFlexible) return flexible_mass_block(b, q);
  const Eigen::Matrix3d A = rotation_matrix(body_quaternion(b, q));
  const Eigen::Matrix3d c_x = skew(b.com_B);
  Eigen::MatrixXd M_b(6, 6);
  M_b.block<3, 3>(0, 0) = b.mass * Eigen::Matrix3d::Identity();
  M_b.block<3, 3>(0, 3) = -b.mass * A * c_x;
  M_b.block<3, 3>(3, 0) = b.mass * c_x * A.transpose();
  M_b.block<3, 3>(3, 3) = b.inertia_com_B - b.mass * c_x * c_x;
  return M_b;
}

void add_body_inertial_and_gravity_forces(const Model& model, int body, const Eigen::VectorXd& q,
                                          const Eigen::VectorXd& v, Eigen::VectorXd& Q) {
  const Body& b = model.bodies[body];
  if (b.kind == BodyKind::kGround) return;
  if (b.kind == BodyKind::kFlexible) return add_flexible_forces(b, model.gravity_W, q, v, Q);
  const Eigen::Matrix3d A = rotation_matrix(body_quaternion(b, q));
  const Eigen::Vector3d w_B = v.segment<3>(b.v_offset + 3);
  const Eigen::Matrix3d c_x = skew(b.com_B);
  const Eigen::Matrix3d J_o = b.inertia_com_B - b.mass * c_x * c_x;
  const int o = b.v_offset;
  // Quadratic-velocity forces (centripetal at the CoM, gyroscopic moment about the origin).
  Q.segment<3>(o) += -b.mass * A * w_B.cross(w_B.cross(b.com_B));
  Q.segment<3>(o + 3) += -w_B.cross(J_o * w_B);
  // Gravity m g at the centre of mass.
  const Eigen::Vector3d f_W = b.mass * model.gravity_W;
  Q.segment<3>(o) += f_W;
  Q.segment<3>(o + 3) += b.com_B.cross(A.transpose() * f_W);
}

void add_frame_load(const FrameKinematics& frame, const Eigen::Vector3d& f_W,
                    const Eigen::Vector3d& tau_W, Eigen::VectorXd& Q) {
  // Only the frame's body columns: J is zero elsewhere (a satellite's nv is ten times a panel's).
  const int o = frame.body_v_offset, n = frame.body_nv;
  Q.segment(o, n).noalias() += frame.J_p.middleCols(o, n).transpose() * f_W;
  Q.segment(o, n).noalias() += frame.J_w.middleCols(o, n).transpose() * tau_W;
}

double body_kinetic_energy(const Model& model, int body, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v) {
  const Body& b = model.bodies[body];
  if (b.kind == BodyKind::kGround) return 0.0;
  if (b.kind == BodyKind::kFlexible) return flexible_kinetic_energy(b, q, v);
  // ½ m |v_c|² + ½ ω'ᵀ J_c ω' with v_c = ṙ + A (ω' × c).
  const Eigen::Matrix3d A = rotation_matrix(body_quaternion(b, q));
  const Eigen::Vector3d w_B = v.segment<3>(b.v_offset + 3);
  const Eigen::Vector3d v_c = v.segment<3>(b.v_offset) + A * w_B.cross(b.com_B);
  return 0.5 * b.mass * v_c.squaredNorm() + 0.5 * w_B.dot(b.inertia_com_B * w_B);
}

double body_gravity_potential(const Model& model, int body, const Eigen::VectorXd& q) {
  const Body& b = model.bodies[body];
  if (b.kind == BodyKind::kGround) return 0.0;
  if (b.kind == BodyKind::kFlexible) return flexible_gravity_potential(b, model.gravity_W, q);
  const Eigen::Matrix3d A = rotation_matrix(body_quaternion(b, q));
  return -b.mass * model.gravity_W.dot(body_position(b, q) + A * b.com_B);
}

void set_body_kinematic_matrix(const Model& model, int body, const Eigen::VectorXd& q,
                               Eigen::MatrixXd& N) {
  const Body& b = model.bodies[body];
  if (b.kind == BodyKind::kGround) return;
  N.block<3, 3>(b.q_offset, b.v_offset).setIdentity();
  N.block<4, 3>(b.q_offset + 3, b.v_offset + 3) = 0.5 * l_matrix(body_quaternion(b, q)).transpose();
  // Modal coordinates: η̇ is a velocity.
  const int nm = b.nv - 6;
  N.block(b.q_offset + 7, b.v_offset + 6, nm, nm).setIdentity();
}

void map_body_jacobian_to_q(const Model& model, int body, const Eigen::VectorXd& q,
                            const Eigen::MatrixXd& f_v, Eigen::MatrixXd& f_q) {
  const Body& b = model.bodies[body];
  if (b.kind == BodyKind::kGround) return;
  const Eigen::Vector4d p = body_quaternion(b, q);
  const double norm = p.norm();
  f_q.middleCols<3>(b.q_offset) = f_v.middleCols<3>(b.v_offset);
  f_q.middleCols<4>(b.q_offset + 3) =
      f_v.middleCols<3>(b.v_offset + 3) * (2.0 / norm) * l_matrix(p / norm);
  const int nm = b.nv - 6;
  f_q.middleCols(b.q_offset + 7, nm) = f_v.middleCols(b.v_offset + 6, nm);
}

void integrate_body_coordinates(const Model& model, int body, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& dv, Eigen::VectorXd& q_out) {
  const Body& b = model.bodies[body];
  if (b.kind == BodyKind::kGround) return;
  q_out.segment<3>(b.q_offset) = q.segment<3>(b.q_offset) + dv.segment<3>(b.v_offset);
  q_out.segment<4>(b.q_offset + 3) =
      quaternion_product(body_quaternion(b, q), quaternion_exp(dv.segment<3>(b.v_offset + 3)));
  const int nm = b.nv - 6;
  q_out.segment(b.q_offset + 7, nm) = q.segment(b.q_offset + 7, nm) + dv.segment(b.v_offset + 6, nm);
}

}  // namespace limber::multibody
