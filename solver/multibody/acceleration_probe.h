// Motion of an acceleration probe's point (model.h, AccelerationProbe) from the state and the
// accelerations v̇ of an integrator sample, in ground axes: p̈_WP = J_p v̇ + a_bias (state.h)
// with the kinematics of a frame at the point (body.h, flexible_marker.h). With v_b = [ṙ_WB in
// ground, ω in body axes (, η̇)] (model.h), so that v̇_b = [r̈_WB, α in body axes (, η̈)]:
//   rigid body, p_B fixed:   a = r̈ + A (α × p_B + ω × (ω × p_B));
//   flexible body, node n:   a = r̈ + A (α × s + ü + ω × (ω × s) + 2 ω × u̇),
//                            s = x_n + Φ_t η, u̇ = Φ_t η̇, ü = Φ_t η̈ (seed paper eq. 1-2,
//                            differentiated twice; Φ_t the node's translational mode rows).
// The acceleration is absolute (inertial): gravity is not subtracted (an accelerometer's
// specific force would be a − g).
#pragma once

#include <Eigen/Core>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

struct PointMotion {
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();  // [m]
  Eigen::Vector3d v_W = Eigen::Vector3d::Zero();  // [m/s]
  Eigen::Vector3d a_W = Eigen::Vector3d::Zero();  // [m/s²]
};

// The probe's position, velocity and acceleration at (q, v, v̇) (sizes model.nq, nv, nv);
// `frame` is scratch (its Jacobians are sized 3 x nv).
PointMotion probe_motion(const Model& model, const AccelerationProbe& probe, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& v, const Eigen::VectorXd& v_dot, FrameKinematics& frame);

}  // namespace limber::multibody
