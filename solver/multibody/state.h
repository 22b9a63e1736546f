// State and Workspace of a multibody Model (house style §1).
//   State: t [s], q (nq: per body r_WB, quaternion[, η]), v (nv: per body ṙ_WB ground,
//          ω body axes[, η̇]); η only on flexible bodies.
//   Workspace: scratch sized from the model; one per thread.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "multibody/model.h"

namespace limber::multibody {

// The loads of one flexible body's geometric-stiffness load cases (geometric_stiffening.h),
// body axes: what scales its unit-load matrices K_α, K_a, K_F and K_T.
struct StiffeningLoads {
  Eigen::Vector3d alpha_B = Eigen::Vector3d::Zero();  // frame's angular acceleration [rad/s²]
  Eigen::Vector3d a_B = Eigen::Vector3d::Zero();      // frame origin's acceleration less gravity [m/s²]
  std::vector<Eigen::Vector3d> F_B, T_B;              // per load node (geometric.load_nodes) [N, N·m]
};

struct State {
  double t = 0.0;
  Eigen::VectorXd q;
  Eigen::VectorXd v;
  // Hybrid modes, one per model force element: a latch locked or a stop in contact
  // (hinge_limit.h). Empty means none engaged. Switched only at located events.
  std::vector<unsigned char> engaged{};
  // Loads of the full geometric stiffening, one entry per model body (used for bodies with
  // GeometricStiffening::kFull), as of the last accepted step: lagged state, set by
  // MultibodySystem::step_accepted. Empty means none: evaluations then solve for them at
  // the state itself (geometric_stiffening.h).
  std::vector<StiffeningLoads> stiffening{};
};

// The builder's initial poses and velocities (not yet consistent with the constraints:
// see assembly.h).
State initial_state(const Model& model);

// Kinematics of a frame F fixed on a body, all in ground axes (size nv = model.nv):
//   ṗ_WF = J_p v,  ω_WF = J_w v,  p̈_WF = J_p v̇ + a_bias,  ω̇_WF = J_w v̇ + alpha_bias.
struct FrameKinematics {
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R_WF = Eigen::Matrix3d::Identity();
  Eigen::MatrixXd J_p, J_w;  // 3 x nv, zero outside the body's columns
  int body_v_offset = 0, body_nv = 0;  // those columns (none for ground)
  Eigen::Vector3d v_W = Eigen::Vector3d::Zero(), w_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d a_bias = Eigen::Vector3d::Zero(), alpha_bias = Eigen::Vector3d::Zero();
};

struct Workspace {
  explicit Workspace(const Model& model);

  std::vector<FrameKinematics> markers;  // one per model marker
  Eigen::VectorXd g, g_t, gamma;         // full constraint set (model.num_equations())
  Eigen::MatrixXd G;                     // full velocity Jacobian, m x nv
  Eigen::MatrixXd M;                     // nv x nv
  Eigen::VectorXd Q;                     // nv
};

}  // namespace limber::multibody
