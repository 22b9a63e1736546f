#include "multibody/flexible_dynamics.h"

#include <vector>

#include "core/error.h"
#include "multibody/geometric_stiffening.h"
#include "multibody/rotation.h"

namespace limber::multibody {

namespace {

// The η-dependent invariants of one body at one configuration and the products of its forces:
// one set of heap storage per call, shared by the mass block and the forces (the Eigen
// temporaries of each product made ~10 + nm allocations per body and evaluation).
struct FlexibleScratch {
  Eigen::MatrixXd rotation_coupling;            // S(η), 3 x nm
  Eigen::MatrixXd rotation_coupling_rate;       // Ṡ = Σ η̇_k B_k, 3 x nm
  std::vector<Eigen::Matrix3d> inertia_slopes;  // ∂J/∂η_k, nm
  Eigen::VectorXd modal_force;                  // nm: Ṡᵀ ω, then S_tᵀ Aᵀ g
};

// The body's modal coordinates η and rates η̇: views, no copies.
auto modal_coordinates(const Body& b, const Eigen::VectorXd& q) {
  return q.segment(b.q_offset + 7, b.flexible->mode_count());
}

Eigen::Matrix3d frame_rotation(const Body& b, const Eigen::VectorXd& q) {
  return rotation_matrix(q.segment<4>(b.q_offset + 3));
}

// The η-dependent invariants of the deformed body at one configuration: S(η) and ∂J/∂η_k
// into `s`, J(η) into `inertia`; returns the first moment d = m c + S_t η.
Eigen::Vector3d deformed_inertia(const FlexibleBody& f, const Eigen::VectorXd& q, int q_offset,
                                 Eigen::Matrix3d& inertia, FlexibleScratch& s) {
  const modal::ModalInvariants& inv = f.invariants;
  const int nm = f.mode_count();
  const auto eta = q.segment(q_offset + 7, nm);
  const Eigen::Vector3d d_eta = inv.translation_coupling * eta;
  s.rotation_coupling = inv.rotation_coupling;
  s.inertia_slopes.resize(static_cast<std::size_t>(nm));
  inertia = inv.inertia;
  for (int k = 0; k < nm; ++k) {
    // G_k = Σ_j η_j J2_kj: J = J0 + Σ_k η_k (J1_k + G_k), ∂J/∂η_k = J1_k + G_k + G_kᵀ.
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    for (int j = 0; j < nm; ++j) G += eta(j) * inv.inertia_second_order[k * nm + j];
    inertia += eta(k) * (inv.inertia_first_order[k] + G);
    s.inertia_slopes[k] = inv.inertia_first_order[k] + G + G.transpose();
    s.rotation_coupling += eta(k) * inv.rotation_coupling_first_order[k];
  }
  return inv.first_moment + d_eta;
}

// Writes M_b of the header, (6 + nm) square, into `M_b` (every entry), with A the frame's
// rotation, d, J and S (in `s`) at the body's η.
template <typename Block>
void write_mass_block(const Body& b, const Eigen::Matrix3d& A, const Eigen::Vector3d& d,
                      const Eigen::Matrix3d& J, const FlexibleScratch& s, Block&& M_b) {
  const FlexibleBody& f = *b.flexible;
  const int nm = f.mode_count();
  M_b.setZero();
  const Eigen::Matrix3d r_w = -A * skew(d);
  M_b.template topLeftCorner<3, 3>() = f.invariants.mass * Eigen::Matrix3d::Identity();
  M_b.template block<3, 3>(0, 3) = r_w;
  M_b.template block<3, 3>(3, 0) = r_w.transpose();
  // A S_t through a temporary: the lazy product evaluated straight into M's strided block
  // rounds differently (its vectorisation follows the destination's alignment), and the
  // satellite's results then differ from before in the last bits (latch order at 4.19 s).
  const Eigen::MatrixXd r_eta = A * f.invariants.translation_coupling;
  M_b.block(0, 6, 3, nm) = r_eta;
  M_b.block(6, 0, nm, 3) = r_eta.transpose();
  M_b.template block<3, 3>(3, 3) = J;
  M_b.block(3, 6, 3, nm) = s.rotation_coupling;
  M_b.block(6, 3, nm, 3) = s.rotation_coupling.transpose();
  M_b.bottomRightCorner(nm, nm).setIdentity();
}

// The forces of add_flexible_forces, with A, d and J at the body's q and S, ∂J/∂η_k in `s`.
void add_forces(const Body& body, const Eigen::Vector3d& gravity_W, const Eigen::Matrix3d& A,
                const Eigen::Vector3d& d, const Eigen::Matrix3d& J, const Eigen::VectorXd& q,
                const Eigen::VectorXd& v, FlexibleScratch& s, Eigen::VectorXd& Q) {
  const FlexibleBody& f = *body.flexible;
  const modal::ModalInvariants& inv = f.invariants;
  const int nm = f.mode_count(), o = body.v_offset;
  const auto eta = modal_coordinates(body, q);
  const Eigen::Vector3d w = v.segment<3>(o + 3);
  const auto eta_dot = v.segment(o + 6, nm);
  // Rates of the invariants along the motion: ḋ, J̇, Ṡ.
  const Eigen::Vector3d d_dot = inv.translation_coupling * eta_dot;
  Eigen::Matrix3d J_dot = Eigen::Matrix3d::Zero();
  Eigen::MatrixXd& S_dot = s.rotation_coupling_rate;
  S_dot.setZero(3, nm);
  for (int k = 0; k < nm; ++k) {
    J_dot += eta_dot(k) * s.inertia_slopes[k];
    S_dot += eta_dot(k) * inv.rotation_coupling_first_order[k];
  }
  // Frame translation: centripetal and Coriolis forces of the deformed mass.
  Q.segment<3>(o) -= A * (w.cross(w.cross(d)) + 2.0 * w.cross(d_dot));
  // Frame rotation: Euler's equation of the deforming body.
  const Eigen::Vector3d S_dot_eta_dot = S_dot * eta_dot;
  const Eigen::Vector3d S_eta_dot = s.rotation_coupling * eta_dot;
  Q.segment<3>(o + 3) -= J_dot * w + S_dot_eta_dot + w.cross(J * w + S_eta_dot);
  // Modal coordinates: centrifugal (softening) and gyroscopic forces.
  s.modal_force.resize(nm);
  s.modal_force.noalias() = S_dot.transpose() * w;
  for (int k = 0; k < nm; ++k) {
    const Eigen::Vector3d B_eta_dot = inv.rotation_coupling_first_order[k] * eta_dot;
    Q(o + 6 + k) += 0.5 * w.dot(s.inertia_slopes[k] * w) + w.dot(B_eta_dot) - s.modal_force(k);
  }
  // Gravity on the deformed body.
  const Eigen::Vector3d g_B = A.transpose() * gravity_W;
  Q.segment<3>(o) += inv.mass * gravity_W;
  Q.segment<3>(o + 3) += d.cross(g_B);
  s.modal_force.noalias() = inv.translation_coupling.transpose() * g_B;
  Q.segment(o + 6, nm) += s.modal_force;
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
  FlexibleScratch s;
  Eigen::Matrix3d J;
  const Eigen::Vector3d d = deformed_inertia(*b.flexible, q, b.q_offset, J, s);
  Eigen::MatrixXd M_b(b.nv, b.nv);
  write_mass_block(b, frame_rotation(b, q), d, J, s, M_b);
  return M_b;
}

void add_flexible_forces(const Body& body, const Eigen::Vector3d& gravity_W, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& v, Eigen::VectorXd& Q) {
  LIMBER_DEMAND(body.kind == BodyKind::kFlexible);
  FlexibleScratch scratch;
  Eigen::Matrix3d J;
  const Eigen::Vector3d d = deformed_inertia(*body.flexible, q, body.q_offset, J, scratch);
  add_forces(body, gravity_W, frame_rotation(body, q), d, J, q, v, scratch, Q);
}

void add_flexible_mass_matrix_and_forces(const Body& body, const Eigen::Vector3d& gravity_W,
                                         const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                         Eigen::MatrixXd& M, Eigen::VectorXd& Q) {
  LIMBER_DEMAND(body.kind == BodyKind::kFlexible);
  FlexibleScratch scratch;
  const Eigen::Matrix3d A = frame_rotation(body, q);
  Eigen::Matrix3d J;
  const Eigen::Vector3d d = deformed_inertia(*body.flexible, q, body.q_offset, J, scratch);
  write_mass_block(body, A, d, J, scratch, M.block(body.v_offset, body.v_offset, body.nv, body.nv));
  add_forces(body, gravity_W, A, d, J, q, v, scratch, Q);
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
  const auto eta = modal_coordinates(body, q);
  return 0.5 * eta.dot(body.flexible->stiffness.cwiseProduct(eta));
}

}  // namespace limber::multibody
