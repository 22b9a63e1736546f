#include "run/linearize_at.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include <fmt/format.h>

#include "core/error.h"
#include "multibody/constraints.h"
#include "multibody/hinge_limit.h"
#include "multibody/redundancy.h"
#include "multibody/statics.h"

namespace limber::run {

LinearizeSummary linearize_at(const multibody::Model& model, const multibody::AssemblyOptions& assembly,
                              const io::RunSettings& run, double t_at, const LinearizeSettings& settings) {
  if (!(t_at > 0.0 && t_at <= run.t_end)) {
    throw InputError(fmt::format("--at: expected a time within the case's run, 0 < T <= {:g} s (run.t_end), got {:g}",
                                 run.t_end, t_at));
  }
  const auto wall_start = std::chrono::steady_clock::now();
  LinearizeSummary summary;
  summary.at = t_at;
  // The run to T, keeping its last sample and the hinge modes it switched.
  io::RunSettings to_t = run;
  to_t.t_end = t_at;
  std::optional<integrate::Sample> last;
  std::vector<unsigned char> engaged(model.forces.size(), multibody::kLimitFree);
  // A locked latch seats (its damping in full, hinge_limit.h) where its penetration reaches
  // damping_depth, a switch the run does not report as an event: seen here at the samples.
  multibody::Workspace sample_ws(model);
  const auto seat_latches = [&](const integrate::Sample& sample) {
    const multibody::State at{sample.t, sample.q, sample.v, {}};
    bool updated = false;
    for (std::size_t k = 0; k < model.forces.size(); ++k) {
      const auto* limit = std::get_if<multibody::HingeLimit>(&model.forces[k]);
      if (!limit || limit->kind != multibody::HingeLimitKind::kLatch || engaged[k] != multibody::kLimitEngaged) continue;
      if (!updated) multibody::update_marker_kinematics(model, at, multibody::Stage::kVelocity, sample_ws);
      updated = true;
      const double theta = multibody::hinge_limit_state(*limit, sample_ws).theta;
      if (limit->direction * (theta - limit->angle) >= limit->damping_depth) engaged[k] = multibody::kLatchSeated;
    }
  };
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample&) {
    last = sample;
    seat_latches(sample);
  };
  hooks.on_event = [&](const multibody::HingeEvent& event) {
    engaged[static_cast<std::size_t>(event.force)] = event.engaged ? multibody::kLimitEngaged : multibody::kLimitFree;
  };
  const RunSummary ran = run_mechanism(model, assembly, to_t, hooks);
  const auto finish = [&](bool ok) {
    summary.ok = ok;
    summary.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return summary;
  };
  if (!ran.ok || !last || last->t < t_at - 1e-12 * std::max(1.0, t_at)) {
    summary.failure = "run: " + ran.failure;
    summary.message = fmt::format("the run to t = {:g} s stopped at {:g} s: {}", t_at, ran.t_reached, ran.message);
    return finish(false);
  }
  // The state at T, its joints (released hold-downs out) analysed afresh there.
  multibody::State point;
  point.t = last->t;
  point.q = last->q;
  point.v = last->v;
  point.engaged = engaged;
  multibody::Workspace ws(model);
  // Those released at events as well: the run's releases up to T.
  std::vector<bool> released = multibody::rows_released_by(model, point.t);
  released.resize(static_cast<std::size_t>(model.num_equations()), false);
  for (const JointRelease& release : ran.releases) {
    for (const std::string& name : release.joints) {
      const multibody::Joint& joint = model.joints[static_cast<std::size_t>(model.find_joint(name))];
      std::fill_n(released.begin() + joint.first_row, joint.rows, true);
    }
  }
  const multibody::ConstraintPartition partition = multibody::analyse_redundancy(
      model, point, ws, multibody::kRedundancyThreshold, {}, released);
  summary.start.partition = partition;
  // With `statics`: the static equilibrium reached from there, at rest, the hinges in the same
  // modes. A run still ringing at T is not an equilibrium (v̇0 ≠ 0), and about it the rigid
  // modes take a spurious stiffness from ∂(M v̇0)/∂ξ and the responses a first-order error.
  if (settings.statics) {
    multibody::State still = point;
    still.v.setZero();
    summary.statics = multibody::solve_statics(model, partition, still);
    if (summary.statics->status != multibody::StaticsStatus::kOk) {
      summary.failure = "statics";
      summary.message = fmt::format("statics from the run's state at t = {:g} s: {}", t_at, summary.statics->message);
      return finish(false);
    }
    point = summary.statics->state;
    point.engaged = engaged;
  }
  return finish(linearize_about(model, partition, point, settings, summary));
}

}  // namespace limber::run
