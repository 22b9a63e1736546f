#include "multibody/hybrid_coordinates.h"

#include <Eigen/Dense>

#include "core/error.h"
#include "multibody/rotation.h"

namespace limber::multibody {

Eigen::MatrixXd rigid_motion_basis(const Model& model, const State& state, const Eigen::Vector3d& p_WP) {
  Eigen::MatrixXd Psi = Eigen::MatrixXd::Zero(model.nv, 6);
  for (const Body& body : model.bodies) {
    if (body.nv == 0) continue;
    const Eigen::Vector3d r = state.q.segment<3>(body.q_offset);
    const Eigen::Matrix3d R_WB = rotation_matrix(state.q.segment<4>(body.q_offset + 3));
    // ṙ = u − (r − P) × θ, ω_B = R_WBᵀ θ, η̇ = 0.
    Psi.block<3, 3>(body.v_offset, 0).setIdentity();
    Psi.block<3, 3>(body.v_offset, 3) = -skew(Eigen::Vector3d(r - p_WP));
    Psi.block<3, 3>(body.v_offset + 3, 3) = R_WB.transpose();
  }
  return Psi;
}

MassProperties mass_properties(const Eigen::MatrixXd& rigid_mass_P, const Eigen::Vector3d& p_WP) {
  MassProperties out;
  out.mass = rigid_mass_P.topLeftCorner<3, 3>().trace() / 3.0;
  if (out.mass <= 0.0) return out;
  // The translation–rotation block is −m [c − P]×; the rotation block I_P = I_c + m(|d|² 1 − d dᵀ).
  const Eigen::Matrix3d S = -rigid_mass_P.block<3, 3>(0, 3) / out.mass;
  const Eigen::Vector3d d(0.5 * (S(2, 1) - S(1, 2)), 0.5 * (S(0, 2) - S(2, 0)), 0.5 * (S(1, 0) - S(0, 1)));
  out.com_W = p_WP + d;
  const Eigen::Matrix3d I_P = rigid_mass_P.block<3, 3>(3, 3);
  out.inertia_com_W = I_P - out.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  out.inertia_com_W = 0.5 * (out.inertia_com_W + out.inertia_com_W.transpose()).eval();
  return out;
}

CantileveredModes cantilevered_modes(const Model& model, const State& state, const TangentMatrices& tangent,
                                     int reference_body, double zero_threshold_hz) {
  LIMBER_DEMAND(reference_body > 0 && reference_body < static_cast<int>(model.bodies.size()) &&
                model.bodies[static_cast<std::size_t>(reference_body)].nv > 0);
  const Body& ref = model.bodies[static_cast<std::size_t>(reference_body)];
  CantileveredModes out;
  out.reference_body = reference_body;
  const Eigen::Matrix3d R_WB = rotation_matrix(state.q.segment<4>(ref.q_offset + 3));
  out.p_WP = state.q.segment<3>(ref.q_offset) + R_WB * ref.com_B;

  // The joints' rows and the reference body's six frame velocities held.
  Eigen::MatrixXd G_held = Eigen::MatrixXd::Zero(tangent.G.rows() + 6, model.nv);
  G_held.topRows(tangent.G.rows()) = tangent.G;
  G_held.bottomRows(6).middleCols(ref.v_offset, 6).setIdentity();
  const Eigen::MatrixXd Z = null_space_basis(G_held, model.nv);
  out.modes = system_modes(tangent, Z, zero_threshold_hz);

  // Ψ about P, the whole mechanism's and the appendages' rigid mass, and L = Φᵀ M Ψ.
  const Eigen::MatrixXd Psi = rigid_motion_basis(model, state, out.p_WP);
  out.largest_constraint_rate =
      tangent.G.rows() > 0 ? (tangent.G * Psi).cwiseAbs().maxCoeff() / Psi.cwiseAbs().maxCoeff() : 0.0;
  out.rigid_mass = Psi.transpose() * tangent.M * Psi;
  Eigen::MatrixXd Psi_a = Psi;
  Psi_a.middleRows(ref.v_offset, ref.nv).setZero();
  out.appendage_mass = Psi_a.transpose() * tangent.M * Psi_a;
  out.participation = out.modes.shapes.transpose() * tangent.M * Psi;
  out.effective_mass = out.participation.cwiseAbs2();
  out.effective_sum = out.effective_mass.colwise().sum().transpose();
  return out;
}

}  // namespace limber::multibody
