#include "run/event_peaks.h"

#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "multibody/reactions.h"

namespace limber::run {

namespace {

// Raises `peak` to `value` (≥ 0) at `t` when larger.
void raise(double value, double t, double& peak, double& time) {
  if (std::isnan(time) || value > peak) {
    peak = value;
    time = t;
  }
}

// The window's peaks of one joint raised by its reaction at t.
void raise(const multibody::JointReaction& reaction, double t, results::JointPeak& peak) {
  raise(reaction.force_j_J.norm(), t, peak.force, peak.force_time);
  raise(reaction.torque_j_J.norm(), t, peak.torque, peak.torque_time);
  for (int axis = 0; axis < 3; ++axis) {
    raise(std::abs(reaction.force_j_J(axis)), t, peak.force_component(axis), peak.force_component_time(axis));
    raise(std::abs(reaction.torque_j_J(axis)), t, peak.torque_component(axis), peak.torque_component_time(axis));
  }
}

}  // namespace

EventPeakTracker::EventPeakTracker(const multibody::Model& model,
                                   const multibody::ConstraintPartition& partition,
                                   const std::vector<unsigned char>& engaged, double window)
    : model_(model), partition_(partition), engaged_(engaged), workspace_(model),
      engagements_(model.forces.size(), 0) {
  LIMBER_DEMAND(window > 0.0);
  peaks_.window = window;
  for (const multibody::Joint& joint : model.joints) peaks_.joints.push_back(joint.name);
}

void EventPeakTracker::open(const results::WindowStart& start) {
  results::PeakWindow window;
  window.start = start;
  window.end = start.t + peaks_.window;
  window.joints.resize(model_.joints.size());
  peaks_.windows.push_back(std::move(window));
}

void EventPeakTracker::on_event(const multibody::HingeEvent& event) {
  const auto* limit = std::get_if<multibody::HingeLimit>(&model_.forces[static_cast<std::size_t>(event.force)]);
  if (!event.engaged || !limit || limit->kind != multibody::HingeLimitKind::kLatch) return;
  const int n = ++engagements_[static_cast<std::size_t>(event.force)];
  open({event.t, n == 1 ? "latch " + limit->name : fmt::format("latch {} #{}", limit->name, n)});
}

void EventPeakTracker::observe(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               const Eigen::VectorXd& lambda) {
  // Reactions only where a window wants them.
  bool inside = false;
  for (const results::PeakWindow& window : peaks_.windows) inside = inside || (t >= window.start.t && t <= window.end);
  if (!inside) return;
  // The samples' reactions (sample_record.cpp): on body j, joint frame.
  const multibody::Reactions reactions =
      multibody::reactions_from_multipliers(model_, multibody::State{t, q, v, engaged_}, lambda, partition_, workspace_);
  for (results::PeakWindow& window : peaks_.windows) {
    if (t < window.start.t || t > window.end) continue;
    ++window.states;
    for (std::size_t k = 0; k < reactions.joints.size(); ++k) raise(reactions.joints[k], t, window.joints[k]);
  }
}

}  // namespace limber::run
