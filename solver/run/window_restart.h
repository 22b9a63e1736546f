// Restarting a run inside it, from a state another run passed through: `limber select`'s
// windowed convergence check (docs/select.md, "Reference check") re-runs only the reference's
// event windows at half its step, each from the reference's own state just before the window's
// event, instead of the whole run.
//
// A restart point is a state after which no mode switched: the run restarted there meets the
// window's event ahead of it and locates it itself, at its own step, as the first run did
// (a restart exactly at the event would start with the event function already at 0, and miss
// it). Its discrete state is the hinge limits' modes then (MultibodySystem::engaged; a latch
// locked or seated earlier) and the joints released at or before its time (hold-downs).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "multibody/multibody_system.h"
#include "results/event_peaks.h"

namespace limber::run {

// A state to restart a run from (run_mechanism's `restart`).
struct RestartPoint {
  double t = 0.0;                    // [s]
  Eigen::VectorXd q, v;              // coordinates and velocities at t
  std::vector<unsigned char> modes;  // per model force, the mode in force after t (MultibodySystem::engaged)
};

// An event window a run opened after its start (a latch engagement, a release at t > 0), with
// the last restart point before its event.
struct WindowRestart {
  results::WindowStart window;
  RestartPoint before;
};

// Follows the states a run's integrator steps through and keeps the last restart point: the
// latest state whose following step switched no mode.
class RestartPointRecorder {
 public:
  // `modes`: the system's modes (MultibodySystem::engaged), which must outlive the recorder.
  explicit RestartPointRecorder(const std::vector<unsigned char>& modes) : modes_(modes) {}

  // One integrator state, t ascending over the calls; `events` is the count of located events
  // applied so far (MultibodySystem::events().size()). A state is a restart point once the next
  // call shows neither a new event nor a changed mode (a latch's seating changes the mode only).
  void observe(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, std::size_t events);

  // The last restart point; empty until two states have been observed without a switch.
  const std::optional<RestartPoint>& last() const { return last_; }

 private:
  const std::vector<unsigned char>& modes_;
  std::optional<RestartPoint> previous_;  // the state of the previous call, its modes then
  std::size_t previous_events_ = 0;
  std::optional<RestartPoint> last_;
};

// Whether a run of `model` can restart from a RestartPoint: not when a joint is released at an
// event (the schedule is not part of the point) or over a duration (nor is its fading load).
bool restart_points_supported(const multibody::Model& model);

// Puts `system` in the discrete state of `point`: the joints released at or before point.t
// leave its equations (MultibodySystem::release_joints), and each hinge limit is switched
// (apply_event, as the integrators do) until its mode is the point's. The switches append to
// system.events(): a caller that reports events starts after them.
void restore_discrete_state(multibody::MultibodySystem& system, const RestartPoint& point);

}  // namespace limber::run
