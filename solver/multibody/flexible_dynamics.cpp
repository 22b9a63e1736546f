#include "multibody/flexible_dynamics.h"

#include <vector>

#include "core/error.h"
#include "multibody/geometric_stiffening.h"
#include "multibody/rotation.h"

namespace limber::multibody {

namespace {

// The η-dependent invariants of the deformed body at one configuration.
struct DeformedInertia {
  Eigen::Vector3d first_moment;                 // d = m c + S_t η
  Eigen::Matrix3d inertia;                      // J(η)
  Eigen::MatrixXd rotation_coupling;            // S(η), 3 x nm
  std::vector<Eigen::Matrix3d> inertia_slopes;  // ∂J/∂η_k
};

DeformedInertia deformed_inertia(const FlexibleBody& f, const Eigen::VectorXd& eta) {
  const modal::ModalInvariants& inv = f.invariants;
  const int nm = f.mode_count();
  DeformedInertia out;
  out.first_moment = inv.first_moment + inv.translation_coupling * eta;
  out.rotation_coupling = inv.rotation_coupling;
  out.inertia = inv.inertia;
  out.inertia_slopes.resize(nm);
  for (int k = 0; k < nm; ++k) {
    // G_k = Σ_j η_j J2_kj: J = J0 + Σ_k η_k (J1_k + G_k), ∂J/∂η_k = J1_k + G_k + G_kᵀ.
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    for (int j = 0; j < nm; ++j) G += eta(j) * inv.inertia_second_order[k * nm + j];
    out.inertia += eta(k) * (inv.inertia_first_order[k] + G);
    out.inertia_slopes[k] = inv.inertia_first_order[k] + G + G.transpose();
    out.rotation_coupling += eta(k) * inv.rotation_coupling_first_order[k];
  }
  return out;
}

Eigen::Matrix3d frame_rotation(const Body& b, const Eigen::VectorXd& q) {
  return rotation_matrix(q.segment<4>(b.q_offset + 3));
}

Eigen::VectorXd modal_coordinates(const Body& b, const Eigen::VectorXd& q) {
  return q.segment(b.q_offset + 7, b.flexible->mode_count());
}

// M_b of the header, (6 + nm) square, with A the frame's rotation and `in` at the body's η.
Eigen::MatrixXd mass_block(const Body& b, const Eigen::Matrix3d& A, const DeformedInertia& in) {
  const FlexibleBody& f = *b.flexible;
  const int nm = f.mode_count();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(6 + nm, 6 + nm);
  const Eigen::Matrix3d r_w = -A * skew(in.first_moment);
  const Eigen::MatrixXd r_eta = A * f.invariants.translation_coupling;
  M.topLeftCorner<3, 3>() = f.invariants.mass * Eigen::Matrix3d::Identity();
  M.block<3, 3>(0, 3) = r_w;
  M.block<3, 3>(3, 0) = r_w.transpose();
  M.block(0, 6, 3, nm) = r_eta;
  M.block(6, 0, nm, 3) = r_eta.transpose();
  M.block<3, 3>(3, 3) = in.inertia;
  M.block(3, 6, 3, nm) = in.rotation_coupling;
  M.block(6, 3, nm, 3) = in.rotation_coupling.transpose();
  M.bottomRightCorner(nm, nm).setIdentity();
  return M;
}

// The forces of add_flexible_forces, with A and `in` at the body's q.
void add_forces(const Body& body, const Eigen::Vector3d& gravity_W, const Eigen::Matrix3d& A,
                const DeformedInertia& in, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                Eigen::VectorXd& Q) {
  const FlexibleBody& f = *body.flexible;
  const modal::ModalInvariants& inv = f.invariants;
  const int nm = f.mode_count(), o = body.v_offset;
  const Eigen::VectorXd eta = modal_coordinates(body, q);
  const Eigen::Vector3d w = v.segment<3>(o + 3);
  const Eigen::VectorXd eta_dot = v.segment(o + 6, nm);
  // Rates of the invariants along the motion: ḋ, J̇, Ṡ.
  const Eigen::Vector3d d_dot = inv.translation_coupling * eta_dot;
  Eigen::Matrix3d J_dot = Eigen::Matrix3d::Zero();
  Eigen::MatrixXd S_dot = Eigen::MatrixXd::Zero(3, nm);
  for (int k = 0; k < nm; ++k) {
    J_dot += eta_dot(k) * in.inertia_slopes[k];
    S_dot += eta_dot(k) * inv.rotation_coupling_first_order[k];
  }
  // Frame translation: centripetal and Coriolis forces of the deformed mass.
  Q.segment<3>(o) -= A * (w.cross(w.cross(in.first_moment)) + 2.0 * w.cross(d_dot));
  // Frame rotation: Euler's equation of the deforming body.
  Q.segment<3>(o + 3) -=
      J_dot * w + S_dot * eta_dot + w.cross(in.inertia * w + in.rotation_coupling * eta_dot);
  // Modal coordinates: centrifugal (softening) and gyroscopic forces.
  const Eigen::VectorXd S_dot_w = S_dot.transpose() * w;
  for (int k = 0; k < nm; ++k) {
    Q(o + 6 + k) += 0.5 * w.dot(in.inertia_slopes[k] * w) +
                    w.dot(inv.rotation_coupling_first_order[k] * eta_dot) - S_dot_w(k);
  }
  // Gravity on the deformed body.
  const Eigen::Vector3d g_B = A.transpose() * gravity_W;
  Q.segment<3>(o) += inv.mass * gravity_W;
  Q.segment<3>(o + 3) += in.first_moment.cross(g_B);
  Q.segment(o + 6, nm) += inv.translation_coupling.transpose() * g_B;
  // Elastic and damping forces of the modes.
  Q.segment(o + 6, nm) -= (f.stiffness.array() * eta.array() + f.damping.array() * eta_dot.array()).matrix();
  // Centrifugal geometric stiffening (geometric_stiffening.h); load cases needing
  // accelerations or joint forces are added by generalized_forces.
  if (f.stiffening != GeometricStiffening::kOff) {
    Q.segment(o + 6, nm) -= centrifugal_geometric_force(f.geometric, w, eta);
  }
}

}  // namespace

Eigen::MatrixXd flexible_mass_block(const Body& b, const Eigen::VectorXd& q) {
  LIMBER_DEMAND(b.kind == BodyKind::kFlexible);
  return mass_block(b, frame_rotation(b, q), deformed_inertia(*b.flexible, modal_coordinates(b, q)));
}

void add_flexible_forces(const Body& body, const Eigen::Vector3d& gravity_W, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& v, Eigen::VectorXd& Q) {
  LIMBER_DEMAND(body.kind == BodyKind::kFlexible);
  add_forces(body, gravity_W, frame_rotation(body, q), deformed_inertia(*body.flexible, modal_coordinates(body, q)),
             q, v, Q);
}

void add_flexible_mass_matrix_and_forces(const Body& body, const Eigen::Vector3d& gravity_W,
                                         const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                         Eigen::MatrixXd& M, Eigen::VectorXd& Q) {
  LIMBER_DEMAND(body.kind == BodyKind::kFlexible);
  const Eigen::Matrix3d A = frame_rotation(body, q);
  const DeformedInertia in = deformed_inertia(*body.flexible, modal_coordinates(body, q));
  M.block(body.v_offset, body.v_offset, body.nv, body.nv) += mass_block(body, A, in);
  add_forces(body, gravity_W, A, in, q, v, Q);
}

double flexible_kinetic_energy(const Body& body, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  const Eigen::VectorXd v_b = v.segment(body.v_offset, body.nv);
  return 0.5 * v_b.dot(flexible_mass_block(body, q) * v_b);
}

double flexible_gravity_potential(const Body& body, const Eigen::Vector3d& gravity_W, const Eigen::VectorXd& q) {
  const modal::ModalInvariants& inv = body.flexible->invariants;
  const Eigen::Vector3d d = inv.first_moment + inv.translation_coupling * modal_coordinates(body, q);
  return -gravity_W.dot(inv.mass * q.segment<3>(body.q_offset) + frame_rotation(body, q) * d);
}

double flexible_strain_energy(const Body& body, const Eigen::VectorXd& q) {
  const Eigen::VectorXd eta = modal_coordinates(body, q);
  return 0.5 * eta.dot(body.flexible->stiffness.cwiseProduct(eta));
}

}  // namespace limber::multibody
