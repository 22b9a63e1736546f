#include "run/window_restart.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "multibody/hinge_limit.h"

namespace limber::run {

void RestartPointRecorder::observe(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                   std::size_t events) {
  // The previous state is a restart point when nothing switched since it.
  if (previous_ && events == previous_events_ && modes_ == previous_->modes) last_ = previous_;
  previous_ = RestartPoint{t, q, v, modes_};
  previous_events_ = events;
}

bool restart_points_supported(const multibody::Model& model) {
  return std::none_of(model.joints.begin(), model.joints.end(), [](const multibody::Joint& joint) {
    return joint.release_after >= 0 || joint.release_duration > 0.0;
  });
}

void restore_discrete_state(multibody::MultibodySystem& system, const RestartPoint& point) {
  const multibody::Model& model = system.model();
  LIMBER_DEMAND(point.modes.size() == model.forces.size());
  // Hold-downs released by then.
  const bool released = std::any_of(model.joints.begin(), model.joints.end(), [&](const multibody::Joint& joint) {
    return std::isfinite(joint.release_time) && joint.release_time <= point.t;
  });
  // (Instantly: restart_points_supported excludes releases that fade.)
  if (released) system.release_joints(point.t, point.q, point.v, Eigen::VectorXd::Zero(system.nc()));
  // Each limit switched through its modes (a latch: free, locked, seated) to the point's.
  int limit = 0;
  for (std::size_t force = 0; force < model.forces.size(); ++force) {
    if (!std::holds_alternative<multibody::HingeLimit>(model.forces[force])) continue;
    // A latch reaches any of its three modes in at most two switches, a stop in one.
    for (int switches = 0; system.engaged()[force] != point.modes[force]; ++switches) {
      LIMBER_DEMAND(switches < 2);
      system.apply_event(limit, point.t, point.q, point.v);
    }
    ++limit;
  }
}

}  // namespace limber::run
