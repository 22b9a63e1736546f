#include "multibody/fading_loads.h"

#include <algorithm>
#include <tuple>

#include "multibody/body.h"

namespace limber::multibody {

FadingLoad fading_load(const Model& model, int joint, const JointReaction& reaction, double t) {
  const Joint& released = model.joints[static_cast<std::size_t>(joint)];
  return {joint,
          released.marker_i,
          released.marker_j,
          reaction.force_j_J,
          reaction.torque_j_J,
          reaction.force_i_I,
          reaction.torque_i_I,
          t,
          released.release_duration};
}

double fading_scale(const FadingLoad& load, double t) {
  return std::clamp(1.0 - (t - load.t_release) / load.duration, 0.0, 1.0);
}

namespace {

// The ground-axes force and torque of one side: its marker's rotation times the frozen values.
void side_load(const FrameKinematics& marker, double s, const Eigen::Vector3d& f, const Eigen::Vector3d& tau,
               Eigen::Vector3d& f_W, Eigen::Vector3d& tau_W) {
  f_W = s * marker.R_WF * f;
  tau_W = s * marker.R_WF * tau;
}

}  // namespace

void add_fading_loads(const std::vector<FadingLoad>& loads, double t, Workspace& ws) {
  for (const FadingLoad& load : loads) {
    const double s = fading_scale(load, t);
    if (s == 0.0) continue;
    Eigen::Vector3d f_W, tau_W;
    const FrameKinematics& mj = ws.markers[static_cast<std::size_t>(load.marker_j)];
    side_load(mj, s, load.force_j_J, load.torque_j_J, f_W, tau_W);
    add_frame_load(mj, f_W, tau_W, ws.Q);
    const FrameKinematics& mi = ws.markers[static_cast<std::size_t>(load.marker_i)];
    side_load(mi, s, load.force_i_I, load.torque_i_I, f_W, tau_W);
    add_frame_load(mi, f_W, tau_W, ws.Q);
  }
}

double fading_load_power(const Model& model, const std::vector<FadingLoad>& loads, const State& state,
                         Workspace& ws) {
  double power = 0.0;
  for (const FadingLoad& load : loads) {
    const double s = fading_scale(load, state.t);
    if (s == 0.0) continue;
    for (const auto& [marker, f, tau] : {std::tuple{load.marker_j, load.force_j_J, load.torque_j_J},
                                         std::tuple{load.marker_i, load.force_i_I, load.torque_i_I}}) {
      FrameKinematics& frame = ws.markers[static_cast<std::size_t>(marker)];
      marker_kinematics(model, marker, state.q, &state.v, frame);
      Eigen::Vector3d f_W, tau_W;
      side_load(frame, s, f, tau, f_W, tau_W);
      power += f_W.dot(frame.v_W) + tau_W.dot(frame.w_W);
    }
  }
  return power;
}

}  // namespace limber::multibody
