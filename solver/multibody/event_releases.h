// Joints released at an event (Joint::release_after): a hold-down that lets go `delay` after a
// hinge latch locks or a stop first touches, e.g. a second-stage hold-down released when the
// root hinge latches. Its release time is known only when the integrator has located that
// event, so it cannot be one of the run's planned restart times (Model::release_times).
//
// The schedule is part of the system's discrete state, beside the hinge modes:
//   - at the trigger's first engagement (t_e) each joint it releases is scheduled at t_e + delay;
//   - a joint with delay > 0 is then a state event of its own, e(t) = t − (t_e + delay), which
//     the integrators locate like a latch (so the release falls between steps, never inside);
//   - once the release time is reached (at t_e itself for delay 0) the joint is due: the
//     system asks the integrator to hand back control there (MechanicalSystem::restart_due),
//     and the run removes the joint and starts a fresh integrator (integrate::simulate).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "multibody/model.h"

namespace limber::multibody {

class EventReleases {
 public:
  explicit EventReleases(const Model& model);

  // The state events of the joints released with a delay (one each, model order).
  int num_events() const { return static_cast<int>(delayed_.size()); }
  // e_k = t − scheduled time while scheduled and not yet released, −1 otherwise.
  void event_functions(double t, Eigen::Ref<Eigen::VectorXd> e) const;

  // Hinge limit `force` (index into model.forces) has switched at t into `engaged`: the joints
  // waiting for its first engagement are scheduled (and due at once without a delay).
  void on_limit_switch(int force, bool engaged, double t);
  // Release event k (num_events order) located at t: its joint is due now.
  void on_release_event(int k, double t);

  // Some scheduled joint has reached its release time and is still in the equations.
  bool due() const { return due_; }
  // The joints due, in model order, marked released (their time: when they became due); due()
  // is false after it.
  std::vector<int> take_due();

  // Per joint: when it was released by an event [s]; +inf while not (or not released by one).
  const std::vector<double>& released_at() const { return released_at_; }
  // Per joint: its scheduled time [s] (t_e + delay) once its trigger engaged; +inf before.
  const std::vector<double>& scheduled() const { return scheduled_; }

 private:
  const Model& model_;
  std::vector<int> delayed_;         // joints with release_after ≥ 0 and a delay > 0
  std::vector<double> scheduled_;    // per joint
  std::vector<double> due_at_;       // per joint: when it became due; +inf while not
  std::vector<double> released_at_;  // per joint
  bool due_ = false;
};

// One line per joint to be released at an event that a run ending at t_end did not release:
// its event never happened, or its release fell after the end.
std::vector<std::string> unreleased_warnings(const Model& model, const EventReleases& releases, double t_end);

}  // namespace limber::multibody
