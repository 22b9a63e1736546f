#include "multibody/geometric_stiffening.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/redundancy.h"
#include "multibody/rotation.h"

namespace limber::multibody {

namespace {

bool has_full_stiffening(const Body& b) {
  return b.kind == BodyKind::kFlexible && b.flexible->stiffening == GeometricStiffening::kFull;
}

// Force and torque on `body` about a frame on it equivalent to the generalized force Q (its
// columns), ground axes: the 6-vector [F; T].
Eigen::Matrix<double, 6, 1> frame_wrench(const Body& body, const FrameKinematics& frame, const Eigen::VectorXd& Q) {
  Eigen::MatrixXd J(body.nv, 6);
  J.leftCols<3>() = frame.J_p.middleCols(body.v_offset, body.nv).transpose();
  J.rightCols<3>() = frame.J_w.middleCols(body.v_offset, body.nv).transpose();
  return J.colPivHouseholderQr().solve(Q.segment(body.v_offset, body.nv));
}

// The index of `node` among the load nodes, or −1 when it is none (such nodes carry no load
// case; the case reader lists every marker's node).
int load_node_index(const modal::ModalGeometricStiffness& g, int node) {
  const auto found = std::find(g.load_nodes.begin(), g.load_nodes.end(), node);
  return found == g.load_nodes.end() ? -1 : static_cast<int>(found - g.load_nodes.begin());
}

// Adds a force F_B and torque T_B (body axes) at the load node of `marker` to `loads`.
void add_node_load(const modal::ModalGeometricStiffness& g, const Marker& marker, const Eigen::Vector3d& F_B,
                   const Eigen::Vector3d& T_B, StiffeningLoads& loads) {
  const int j = load_node_index(g, marker.node);
  if (j < 0) return;
  loads.F_B[static_cast<size_t>(j)] += F_B;
  loads.T_B[static_cast<size_t>(j)] += T_B;
}

// The loads of one body, from v̇, λ (all rows) and the force elements' loads.
StiffeningLoads body_loads(const Model& model, size_t b, const State& state, const Workspace& ws,
                           const Eigen::VectorXd& v_dot, const Eigen::VectorXd& lambda,
                           const std::vector<MarkerLoad>& element_loads) {
  const Body& body = model.bodies[b];
  const modal::ModalGeometricStiffness& g = body.flexible->geometric;
  const int o = body.v_offset;
  const Eigen::Matrix3d A = rotation_matrix(state.q.segment<4>(body.q_offset + 3));
  StiffeningLoads loads;
  loads.F_B.assign(g.load_nodes.size(), Eigen::Vector3d::Zero());
  loads.T_B.assign(g.load_nodes.size(), Eigen::Vector3d::Zero());
  // The frame's angular and translational acceleration, gravity as an acceleration −g.
  loads.alpha_B = v_dot.segment<3>(o + 3);
  loads.a_B = A.transpose() * (v_dot.segment<3>(o) - model.gravity_W);
  // Joint reactions and driver efforts at the load nodes, body axes.
  for (size_t jn = 0; jn < model.joints.size(); ++jn) {
    const Joint& joint = model.joints[jn];
    for (const int m : {joint.marker_i, joint.marker_j}) {
      const Marker& marker = model.markers[m];
      if (marker.body != static_cast<int>(b) || marker.node < 0) continue;
      Eigen::VectorXd Q_joint =
          -ws.G.middleRows(joint.first_row, joint.rows).transpose() * lambda.segment(joint.first_row, joint.rows);
      for (const Driver& d : model.drivers) {
        if (d.joint == static_cast<int>(jn)) Q_joint -= ws.G.row(d.row).transpose() * lambda(d.row);
      }
      const Eigen::Matrix<double, 6, 1> w_W = frame_wrench(body, ws.markers[m], Q_joint);
      add_node_load(g, marker, A.transpose() * w_W.head<3>(), A.transpose() * w_W.tail<3>(), loads);
    }
  }
  // Springs, dampers, actuators, point loads and locked hinges at the load nodes.
  for (const MarkerLoad& load : element_loads) {
    const Marker& marker = model.markers[load.marker];
    if (marker.body != static_cast<int>(b) || marker.node < 0) continue;
    add_node_load(g, marker, A.transpose() * load.force_W, A.transpose() * load.torque_W, loads);
  }
  return loads;
}

// (K_geo − centrifugal part) η of one body: Σ_k α_k K_α,k η + a_k K_a,k η + Σ_nodes F_k K_F,k η
// + T_k K_T,k η, matrix-vector products only.
Eigen::VectorXd load_stiffness_force(const modal::ModalGeometricStiffness& g, const StiffeningLoads& loads,
                                     const Eigen::VectorXd& eta) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(eta.size());
  for (int k = 0; k < 3; ++k) {
    f.noalias() += loads.alpha_B(k) * (g.angular_acceleration[k] * eta);
    f.noalias() += loads.a_B(k) * (g.translational_acceleration[k] * eta);
  }
  for (size_t j = 0; j < g.load_nodes.size(); ++j) {
    for (int k = 0; k < 3; ++k) {
      f.noalias() += loads.F_B[j](k) * (g.node_forces[j][k] * eta);
      f.noalias() += loads.T_B[j](k) * (g.node_moments[j][k] * eta);
    }
  }
  return f;
}

}  // namespace

Eigen::VectorXd centrifugal_geometric_force(const modal::ModalGeometricStiffness& g, const Eigen::Vector3d& w_B,
                                            const Eigen::VectorXd& eta) {
  const double p[6] = {w_B.x() * w_B.x(), w_B.y() * w_B.y(), w_B.z() * w_B.z(),
                       w_B.x() * w_B.y(), w_B.y() * w_B.z(), w_B.z() * w_B.x()};
  Eigen::VectorXd f = Eigen::VectorXd::Zero(eta.size());
  // Matrix-vector products only, skipping products below 1e-12 of |ω|² (a planar spin has one
  // product; the others are round-off of the frame's rotation, far below any tolerance).
  const double negligible = 1e-12 * w_B.squaredNorm();
  for (int c = 0; c < 6; ++c) {
    if (std::abs(p[c]) > negligible) f.noalias() += p[c] * (g.centrifugal[c] * eta);
  }
  return f;
}

AccelerationEstimate estimate_accelerations(const Eigen::MatrixXd& M, const Eigen::MatrixXd& G,
                                            const Eigen::VectorXd& Q, const Eigen::VectorXd& gamma) {
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  const Eigen::VectorXd y0 = llt.matrixL().solve(Q);
  AccelerationEstimate out;
  out.lambda = Eigen::VectorXd::Zero(G.rows());
  if (G.rows() > 0) {
    // Whitened rows B; B Bᵀ λ = B y0 − γ, its minimum-norm solution from one eigen-decomposition
    // (σ(B)² are its eigenvalues: the relative cut on σ is squared).
    const Eigen::MatrixXd B = llt.matrixL().solve(G.transpose()).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(B * B.transpose());
    const Eigen::VectorXd& mu = eig.eigenvalues();
    const double cut = kRedundancyThreshold * kRedundancyThreshold * mu.cwiseAbs().maxCoeff();
    Eigen::VectorXd c = eig.eigenvectors().transpose() * (B * y0 - gamma);
    for (Eigen::Index i = 0; i < c.size(); ++i) c(i) = mu(i) > cut ? c(i) / mu(i) : 0.0;
    out.lambda = eig.eigenvectors() * c;
    out.v_dot = llt.matrixU().solve(y0 - B.transpose() * out.lambda);
    return out;
  }
  out.v_dot = llt.matrixU().solve(y0);
  return out;
}

bool has_load_stiffening(const Model& model) {
  return std::any_of(model.bodies.begin(), model.bodies.end(), has_full_stiffening);
}

std::vector<StiffeningLoads> stiffening_loads(const Model& model, const State& state, const Eigen::VectorXd& v_dot,
                                              const Eigen::VectorXd& lambda, Workspace& ws) {
  std::vector<MarkerLoad> element_loads;
  force_element_loads(model, state, ws, element_loads);
  std::vector<StiffeningLoads> loads(model.bodies.size());
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    if (has_full_stiffening(model.bodies[b])) loads[b] = body_loads(model, b, state, ws, v_dot, lambda, element_loads);
  }
  return loads;
}

std::vector<StiffeningLoads> solved_stiffening_loads(const Model& model, const State& state, Workspace& ws) {
  // Accelerations and multipliers at this state, from the forces so far.
  mass_matrix(model, state, ws);
  evaluate_constraints(model, state, Stage::kVelocity, ws);
  const AccelerationEstimate estimate = estimate_accelerations(ws.M, ws.G, ws.Q, ws.gamma);
  return stiffening_loads(model, state, estimate.v_dot, estimate.lambda, ws);
}

std::vector<StiffeningLoads> accepted_step_stiffening_loads(const Model& model, const State& state,
                                                            const Eigen::VectorXd& v_dot, const std::vector<int>& rows,
                                                            const Eigen::VectorXd& lambda_rows, Workspace& ws) {
  // The rows held carry the loads; the rows left out (redundant or released) none.
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(ws.G.rows());
  for (size_t k = 0; k < rows.size(); ++k) lambda(rows[k]) = lambda_rows(static_cast<Eigen::Index>(k));
  return stiffening_loads(model, state, v_dot, lambda, ws);
}

void add_load_geometric_stiffness(const Model& model, const State& state, Workspace& ws, double* power) {
  if (!has_load_stiffening(model)) return;
  // The lagged loads, or (a state without them) the loads solved for at the state.
  const std::vector<StiffeningLoads> solved =
      state.stiffening.empty() ? solved_stiffening_loads(model, state, ws) : std::vector<StiffeningLoads>{};
  const std::vector<StiffeningLoads>& loads = state.stiffening.empty() ? solved : state.stiffening;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (!has_full_stiffening(body)) continue;
    const int nm = body.flexible->mode_count();
    const Eigen::VectorXd eta = state.q.segment(body.q_offset + 7, nm);
    const Eigen::VectorXd force = load_stiffness_force(body.flexible->geometric, loads[b], eta);
    ws.Q.segment(body.v_offset + 6, nm) -= force;
    if (power) *power -= state.v.segment(body.v_offset + 6, nm).dot(force);
  }
}

}  // namespace limber::multibody
