#include "multibody/reactions.h"
#include "multibody/evaluated.h"

#include <limits>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "core/error.h"
#include "core/minimum_norm.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/released_joints.h"
#include "multibody/rotation.h"

namespace limber::multibody {

namespace {

// Force and torque at a frame equivalent to generalized forces on one body's velocities:
// the solution X of [J_p; J_w]ᵀ X = Q_b per column of Q (rows of the body's velocities).
// A joint's rows reach the body through this frame only (Q_b = [J_p; J_w]ᵀ times the rows'
// coefficients), so the equations are consistent and the six rows of the body frame's
// velocities (ṙ, ω first: J = [I −A s̃; 0 A] there, invertible) determine X; a flexible body's
// elastic rows agree with them. A fixed-size LU of those six instead of a least-squares QR of
// all nv rows: the same X to round-off, without allocating.
Eigen::Matrix<double, 6, Eigen::Dynamic> frame_wrenches(const Body& body, const FrameKinematics& frame,
                                                        const Eigen::MatrixXd& Q) {
  LIMBER_DEMAND(body.nv >= 6);
  Eigen::Matrix<double, 6, 6> J;
  J.leftCols<3>() = frame.J_p.middleCols<6>(body.v_offset).transpose();
  J.rightCols<3>() = frame.J_w.middleCols<6>(body.v_offset).transpose();
  return J.partialPivLu().solve(Q.middleRows<6>(body.v_offset));
}

}  // namespace

Eigen::Matrix<double, 6, Eigen::Dynamic> joint_wrench_map(const Model& model, const Workspace& ws, int joint_index) {
  const Joint& joint = model.joints[static_cast<std::size_t>(joint_index)];
  // Generalized constraint force of unit multipliers: Q_k = −G_kᵀ λ_k.
  const Eigen::MatrixXd Q_k = -ws.G.middleRows(joint.first_row, joint.rows).transpose();
  const int body_i = model.markers[static_cast<std::size_t>(joint.marker_i)].body;
  const int body_j = model.markers[static_cast<std::size_t>(joint.marker_j)].body;
  const FrameKinematics& mi = ws.markers[static_cast<std::size_t>(joint.marker_i)];
  const FrameKinematics& mj = ws.markers[static_cast<std::size_t>(joint.marker_j)];
  // Solve on body j when it moves; otherwise on body i, and body j's by equilibrium of the joint:
  // F_j = −F_i, T_j = −T_i + (p_j − p_i) × F_i.
  if (model.bodies[static_cast<std::size_t>(body_j)].kind != BodyKind::kGround) {
    return frame_wrenches(model.bodies[static_cast<std::size_t>(body_j)], mj, Q_k);
  }
  const Eigen::Matrix<double, 6, Eigen::Dynamic> on_i = frame_wrenches(model.bodies[static_cast<std::size_t>(body_i)], mi, Q_k);
  Eigen::Matrix<double, 6, Eigen::Dynamic> on_j(6, joint.rows);
  on_j.topRows<3>() = -on_i.topRows(3);
  on_j.bottomRows<3>() = -on_i.bottomRows(3) + skew(mj.p_W - mi.p_W) * on_i.topRows(3);
  return on_j;
}

namespace {

// The least-squares multipliers of G_activeᵀ λ = b from a Cholesky factor of the Gram matrix
// G Gᵀ when no singular value of G is near minimum_norm_solve's cut, else that solve. Where the
// cut takes nothing both are (G Gᵀ)⁻¹ G b, equal to round-off, and the factor costs a fraction
// of the eigen-solve. Proved by a factor of G Gᵀ − s I: it exists only when every σ² exceeds s
// less the factor's rounding, at most (m + 1) m ε ‖G Gᵀ‖ (Higham, Accuracy and Stability of
// Numerical Algorithms, Thm. 10.3); s = 2 (cut + that rounding) keeps every σ² above the cut,
// the cut taken from ‖G Gᵀ‖∞ ≥ σ_max².
Eigen::VectorXd full_rank_solve(const Eigen::MatrixXd& G_active, const Eigen::VectorXd& b,
                                double relative_threshold) {
  if (G_active.rows() == 0) return Eigen::VectorXd::Zero(0);
  // G Gᵀ from its lower half (LLT reads no other), mirrored for the norm.
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(G_active.rows(), G_active.rows());
  gram.selfadjointView<Eigen::Lower>().rankUpdate(G_active);
  gram.triangularView<Eigen::StrictlyUpper>() = gram.transpose();
  const auto m = static_cast<double>(gram.rows());
  const double norm = gram.cwiseAbs().rowwise().sum().maxCoeff();
  const double cut = relative_threshold * relative_threshold * norm;
  const double rounding = (m + 1.0) * m * std::numeric_limits<double>::epsilon() * norm;
  const Eigen::LLT<Eigen::MatrixXd> shifted(gram - 2.0 * (cut + rounding) * Eigen::MatrixXd::Identity(gram.rows(), gram.cols()));
  if (shifted.info() != Eigen::Success) {
    return minimum_norm_solve(G_active.transpose(), b, relative_threshold);
  }
  return Eigen::LLT<Eigen::MatrixXd>(gram).solve(G_active * b);
}

// Multipliers of all rows: minimum-norm solution of G_fullᵀ λ = b, the rank decided with the
// redundancy analysis' threshold (core/minimum_norm.h says why not Eigen's COD). Released
// joints (hold-downs after their release) are out of the equations: their multipliers are
// zero, and so are their reactions. The solve takes the rows in force only: its eigen-solve
// costs m³, and the satellite's 48 released rows made it 5 times dearer. ws.G evaluated.
Eigen::VectorXd all_multipliers(const Model& model, const Eigen::VectorXd& b,
                                const ConstraintPartition& partition, const Workspace& ws) {
  std::vector<int> active;
  for (int row = 0; row < model.num_equations(); ++row) {
    if (!partition.released(row)) active.push_back(row);
  }
  const Eigen::MatrixXd G_active = ws.G(active, Eigen::all);
  const Eigen::VectorXd lambda_active = full_rank_solve(G_active, b, partition.relative_threshold);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(model.num_equations());
  for (std::size_t k = 0; k < active.size(); ++k) lambda(active[k]) = lambda_active(static_cast<Eigen::Index>(k));
  return lambda;
}

// Joint wrenches and driver efforts from the multipliers of all rows (ws: markers and G at state).
Reactions reactions_of(const Model& model, const State& state, Eigen::VectorXd lambda,
                       const ConstraintPartition& partition, const Workspace& ws) {
  Reactions out;
  out.lambda = std::move(lambda);
  // Joints: the wrench of their rows' multipliers on body j, body i's by equilibrium of the joint.
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const Joint& joint = model.joints[k];
    const FrameKinematics& mi = ws.markers[joint.marker_i];
    const FrameKinematics& mj = ws.markers[joint.marker_j];
    // A released joint carries nothing (its multipliers are zero): no wrench map to build.
    const Eigen::Matrix<double, 6, 1> wrench_j =
        partition.released(joint.first_row)
            ? Eigen::Matrix<double, 6, 1>::Zero().eval()
            : (joint_wrench_map(model, ws, static_cast<int>(k)) * out.lambda.segment(joint.first_row, joint.rows)).eval();
    JointReaction r;
    r.point_W = mj.p_W;
    r.indeterminate = partition.joint_indeterminate[k];
    r.force_j_W = wrench_j.head<3>();
    r.torque_j_W = wrench_j.tail<3>();
    r.force_i_W = -r.force_j_W;
    r.torque_i_W = -r.torque_j_W - (mj.p_W - mi.p_W).cross(r.force_j_W);
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

}  // namespace

Reactions compute_reactions(const Model& model, const State& state, const Eigen::VectorXd& v_dot,
                            const ConstraintPartition& partition, Workspace& ws) {
  evaluate_constraints(model, state, Stage::kVelocity, ws);
  generalized_forces(model, state, ws);
  return reactions_of(model, state, all_multipliers(model, ws.Q - mass_times(model, state.q, v_dot), partition, ws),
                      partition, ws);
}

Reactions reactions_of_evaluation(const Model& model, const State& state, const Eigen::VectorXd& v_dot,
                                  const ConstraintPartition& partition, const Workspace& ws) {
  Eigen::VectorXd b = ws.Q;
  b.noalias() -= ws.M * v_dot;
  return reactions_of(model, state, all_multipliers(model, b, partition, ws), partition, ws);
}

Reactions reactions_from_multipliers(const Model& model, const State& state,
                                     const Eigen::VectorXd& lambda_independent,
                                     const ConstraintPartition& partition, Workspace& ws) {
  // Released joints' rows and markers are not needed: their reactions are zero.
  evaluate_constraints(model, state, Stage::kPosition, released_joints(model, partition.row_released), ws);
  // Without redundant rows the multipliers are unique: the integrator's.
  if (partition.redundant.empty()) {
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(model.num_equations());
    lambda(partition.independent) = lambda_independent;
    return reactions_of(model, state, std::move(lambda), partition, ws);
  }
  const Eigen::VectorXd b = ws.G(partition.independent, Eigen::all).transpose() * lambda_independent;
  return reactions_of(model, state, all_multipliers(model, b, partition, ws), partition, ws);
}

}  // namespace limber::multibody
