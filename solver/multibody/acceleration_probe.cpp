#include "multibody/acceleration_probe.h"

#include "multibody/body.h"
#include "multibody/flexible_marker.h"

namespace limber::multibody {

PointMotion probe_motion(const Model& model, const AccelerationProbe& probe, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& v, const Eigen::VectorXd& v_dot, FrameKinematics& frame) {
  // Kinematics of a frame at the point: on the node (its elastic motion) or fixed on the body.
  if (probe.node >= 0) {
    node_frame_kinematics(model, probe.body, probe.node, Eigen::Matrix3d::Identity(), q, &v, frame);
  } else {
    body_frame_kinematics(model, probe.body, probe.p_B, Eigen::Matrix3d::Identity(), q, &v, frame);
  }
  // p̈ = J_p v̇ + a_bias, over the body's own columns.
  PointMotion motion{frame.p_W, frame.v_W, frame.a_bias};
  motion.a_W.noalias() += frame.J_p.middleCols(frame.body_v_offset, frame.body_nv) *
                          v_dot.segment(frame.body_v_offset, frame.body_nv);
  return motion;
}

}  // namespace limber::multibody
