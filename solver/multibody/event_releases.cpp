#include "multibody/event_releases.h"

#include <limits>

#include <fmt/format.h>

namespace limber::multibody {

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
}  // namespace

EventReleases::EventReleases(const Model& model)
    : model_(model),
      scheduled_(model.joints.size(), kNever),
      due_at_(model.joints.size(), kNever),
      released_at_(model.joints.size(), kNever) {
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const Joint& joint = model.joints[j];
    if (joint.release_after >= 0 && joint.release_delay > 0.0) delayed_.push_back(static_cast<int>(j));
  }
}

void EventReleases::event_functions(double t, Eigen::Ref<Eigen::VectorXd> e) const {
  for (std::size_t k = 0; k < delayed_.size(); ++k) {
    const auto j = static_cast<std::size_t>(delayed_[k]);
    const bool waiting = scheduled_[j] < kNever && due_at_[j] == kNever;
    e(static_cast<Eigen::Index>(k)) = waiting ? t - scheduled_[j] : -1.0;
  }
}

void EventReleases::on_limit_switch(int force, bool engaged, double t) {
  if (!engaged) return;
  for (std::size_t j = 0; j < model_.joints.size(); ++j) {
    const Joint& joint = model_.joints[j];
    // Only the first engagement counts (a stop touches again and again).
    if (joint.release_after != force || scheduled_[j] < kNever) continue;
    scheduled_[j] = t + joint.release_delay;
    if (joint.release_delay == 0.0) {
      due_at_[j] = t;
      due_ = true;
    }
  }
}

void EventReleases::on_release_event(int k, double t) {
  const auto j = static_cast<std::size_t>(delayed_.at(static_cast<std::size_t>(k)));
  if (due_at_[j] < kNever) return;
  due_at_[j] = t;
  due_ = true;
}

std::vector<int> EventReleases::take_due() {
  std::vector<int> joints;
  for (std::size_t j = 0; j < due_at_.size(); ++j) {
    if (due_at_[j] == kNever || released_at_[j] < kNever) continue;
    released_at_[j] = due_at_[j];
    joints.push_back(static_cast<int>(j));
  }
  due_ = false;
  return joints;
}

std::vector<std::string> unreleased_warnings(const Model& model, const EventReleases& releases, double t_end) {
  std::vector<std::string> lines;
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const Joint& joint = model.joints[j];
    if (joint.release_after < 0 || releases.released_at()[j] < kNever) continue;
    const std::string& limit = force_name(model.forces[static_cast<std::size_t>(joint.release_after)]);
    const double at = releases.scheduled()[j];
    lines.push_back(
        at < kNever
            ? fmt::format("joint {} was not released: due at {:.6g} s ({:g} s after {} engaged), after the "
                          "run's end at {:.6g} s", joint.name, at, joint.release_delay, limit, t_end)
            : fmt::format("joint {} was not released: {}, whose engagement releases it, never engaged up to "
                          "t = {:.6g} s; the joint held throughout", joint.name, limit, t_end));
  }
  return lines;
}

}  // namespace limber::multibody
