#include "multibody/reactions.h"

#include <vector>

#include <Eigen/QR>

#include "core/minimum_norm.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"

namespace limber::multibody {

namespace {

// Force and torque at a frame equivalent to a generalized force on one body's velocities.
void frame_wrench(const Body& body, const FrameKinematics& frame, const Eigen::VectorXd& Q,
                  Eigen::Vector3d& f_W, Eigen::Vector3d& tau_W) {
  Eigen::MatrixXd J(body.nv, 6);
  J.leftCols<3>() = frame.J_p.middleCols(body.v_offset, body.nv).transpose();
  J.rightCols<3>() = frame.J_w.middleCols(body.v_offset, body.nv).transpose();
  const Eigen::VectorXd wrench = J.colPivHouseholderQr().solve(Q.segment(body.v_offset, body.nv));
  f_W = wrench.head<3>();
  tau_W = wrench.tail<3>();
}

}  // namespace

Reactions compute_reactions(const Model& model, const State& state, const Eigen::VectorXd& v_dot,
                            const ConstraintPartition& partition, Workspace& ws) {
  evaluate_constraints(model, state, Stage::kVelocity, ws);
  generalized_forces(model, state, ws);
  Reactions out;
  // Multipliers of all rows: minimum-norm solution of G_fullᵀ λ = Q − M v̇, the rank decided
  // with the redundancy analysis' threshold (core/minimum_norm.h says why not Eigen's COD).
  // Released joints (hold-downs after their release) are out of the equations: their
  // multipliers are zero, and so are their reactions. The solve takes the rows in force only:
  // its eigen-solve costs m³, and the satellite's 48 released rows made it 5 times dearer.
  const Eigen::MatrixXd& G = ws.G;
  std::vector<int> active;
  for (int row = 0; row < model.num_equations(); ++row) {
    if (!partition.released(row)) active.push_back(row);
  }
  const Eigen::VectorXd lambda_active = minimum_norm_solve(G(active, Eigen::all).transpose(), ws.Q - mass_times(model, state.q, v_dot),
                                                           partition.relative_threshold);
  out.lambda = Eigen::VectorXd::Zero(model.num_equations());
  for (std::size_t k = 0; k < active.size(); ++k) out.lambda(active[k]) = lambda_active(static_cast<Eigen::Index>(k));
  // Joints: generalized constraint force of their rows, turned into a wrench at a marker.
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const Joint& joint = model.joints[k];
    const Eigen::VectorXd Q_k = -G.middleRows(joint.first_row, joint.rows).transpose() *
                                out.lambda.segment(joint.first_row, joint.rows);
    const Marker& marker_i = model.markers[joint.marker_i];
    const Marker& marker_j = model.markers[joint.marker_j];
    const FrameKinematics& mi = ws.markers[joint.marker_i];
    const FrameKinematics& mj = ws.markers[joint.marker_j];
    const Eigen::Vector3d r_ij = mj.p_W - mi.p_W;
    JointReaction r;
    r.point_W = mj.p_W;
    r.indeterminate = partition.joint_indeterminate[k];
    // Solve on a moving body; the other side by equilibrium of the joint.
    if (model.bodies[marker_j.body].kind != BodyKind::kGround) {
      frame_wrench(model.bodies[marker_j.body], mj, Q_k, r.force_j_W, r.torque_j_W);
      r.force_i_W = -r.force_j_W;
      r.torque_i_W = -r.torque_j_W - r_ij.cross(r.force_j_W);
    } else {
      frame_wrench(model.bodies[marker_i.body], mi, Q_k, r.force_i_W, r.torque_i_W);
      r.force_j_W = -r.force_i_W;
      r.torque_j_W = -r.torque_i_W + r_ij.cross(r.force_i_W);
    }
    r.force_j_J = mj.R_WF.transpose() * r.force_j_W;
    r.torque_j_J = mj.R_WF.transpose() * r.torque_j_W;
    r.force_i_I = mi.R_WF.transpose() * r.force_i_W;
    r.torque_i_I = mi.R_WF.transpose() * r.torque_i_W;
    out.joints.push_back(r);
  }
  // Drivers: effort = −λ (unit derivative of the driven coordinate), power = effort · ḟ.
  for (const Driver& d : model.drivers) {
    const double effort = -out.lambda(d.row);
    out.driver_efforts.push_back(effort);
    out.driver_power += effort * d.motion.evaluate(state.t).first;
  }
  return out;
}

}  // namespace limber::multibody
