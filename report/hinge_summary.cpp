#include "hinge_summary.h"

#include <cmath>

namespace limber::report {
namespace {

const Series* find_series(const std::vector<Series>& series, const std::string& name) {
  for (const Series& s : series) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

}  // namespace

std::vector<LatchUpPeaks> latch_up_peaks(const RunData& run) {
  std::vector<LatchUpPeaks> out;
  const Eigen::VectorXd& t = run.results.time;
  for (std::size_t e = 0; e < run.events.size(); ++e) {
    const HingeEventRow& event = run.events[e];
    const HingeLimitTrack& limit = run.hinge_limits[static_cast<std::size_t>(event.limit)];
    if (limit.kind != "latch" || !event.engaged) continue;
    LatchUpPeaks peaks;
    peaks.event = static_cast<int>(e);
    for (Eigen::Index k = 0; k < t.size(); ++k) {
      if (t(k) < event.time || t(k) > event.time + kLatchUpWindow) continue;
      if (k < limit.torque.size()) peaks.latch_torque = std::max(peaks.latch_torque, std::abs(limit.torque(k)));
      // Every joint's reaction magnitude; the latched joint's own peak apart.
      for (const JointReactions& joint : run.joints) {
        if (k >= joint.force_ground.rows()) continue;
        const double force = joint.force_ground.row(k).norm();
        if (joint.name == limit.joint) {
          peaks.latched_force_joint = peaks.latched_force_joint.cwiseMax(joint.force_joint.row(k).transpose().cwiseAbs());
        }
        if (joint.name == limit.joint && force > peaks.latched_force) {
          peaks.latched_force = force;
          peaks.latched_force_time = t(k);
        }
        if (force > peaks.largest_force) {
          peaks.largest_force = force;
          peaks.largest_force_time = t(k);
          peaks.largest_joint = joint.name;
        }
      }
    }
    out.push_back(peaks);
  }
  return out;
}

std::optional<EnergyBalance> energy_balance(const RunData& run) {
  const Eigen::Index ns = run.results.time.size();
  // The sum of the named series, or nothing when one is missing or short.
  auto sum = [&](std::initializer_list<const char*> names) -> std::optional<Eigen::VectorXd> {
    Eigen::VectorXd total = Eigen::VectorXd::Zero(ns);
    for (const char* name : names) {
      const Series* s = find_series(run.energies, name);
      if (!s || s->values.size() != ns) return std::nullopt;
      total += s->values;
    }
    return total;
  };
  const auto stored = sum({"kinetic", "gravity", "spring", "strain"});
  const auto work = sum({"driver_work", "force_work"});
  const auto dissipated = sum({"dissipated"});
  if (!stored || !work || !dissipated || ns == 0) return std::nullopt;
  EnergyBalance b;
  b.stored_change = stored->array() - (*stored)(0);
  b.work = work->array() - (*work)(0);
  b.dissipated = dissipated->array() - (*dissipated)(0);
  b.residual = b.stored_change + b.dissipated - b.work;
  return b;
}

std::optional<Series> energy_residual(const RunData& run) {
  const char* stored[] = {"kinetic", "gravity", "spring", "strain", "dissipated"};
  const char* work[] = {"driver_work", "force_work"};
  Eigen::VectorXd balance = Eigen::VectorXd::Zero(run.results.time.size());
  for (const char* name : stored) {
    const Series* s = find_series(run.energies, name);
    if (!s || s->values.size() != balance.size()) return std::nullopt;
    balance += s->values;
  }
  for (const char* name : work) {
    const Series* s = find_series(run.energies, name);
    if (!s || s->values.size() != balance.size()) return std::nullopt;
    balance -= s->values;
  }
  if (balance.size() == 0) return std::nullopt;
  return Series{"balance residual", balance.array() - balance(0)};
}

}  // namespace limber::report
