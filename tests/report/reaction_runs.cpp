#include "reaction_runs.h"

#include "results/results_writer.h"

#include <cmath>

namespace limber::report::testing {

Eigen::Vector3d reaction_force(const ReactionRun& run, double t) {
  const double w = 2.0 * M_PI * run.frequency * t;
  return run.amplitude * Eigen::Vector3d(std::cos(w), 0.05 * std::sin(w), std::sin(w));
}

Eigen::Vector3d reaction_force_ground(const ReactionRun& run, double t) {
  const Eigen::Vector3d f = reaction_force(run, t);
  return Eigen::Vector3d(f.x(), -f.z(), f.y());
}

void write_reaction_run(const std::filesystem::path& dir, const ReactionRun& run) {
  results::ResultsWriter writer(dir, run.title, "reaction_runs.cpp");
  results::ShapeSpec block;
  block.size = Eigen::Vector3d(0.2, 0.1, 0.1);
  writer.add_rigid_body({"slider", {block}});
  writer.add_joint({"R3", "revolute", "rod", "slider"});
  writer.add_driver("crank");
  writer.add_energy("kinetic");
  writer.add_energy("driver_work");

  for (int k = 0; k < run.samples; ++k) {
    const double t = run.duration * k / std::max(run.samples - 1, 1);
    results::Sample sample;
    sample.time = t;
    results::BodySample slider;
    slider.position = Eigen::Vector3d(0.5 * std::cos(2.0 * M_PI * run.frequency * t), 0.0, 0.0);
    sample.bodies.push_back(slider);
    results::JointSample r3;
    r3.position = slider.position;
    r3.force_joint = reaction_force(run, t);
    r3.force_ground = reaction_force_ground(run, t);
    sample.joints.push_back(r3);
    sample.driver_efforts = {run.amplitude * t};
    sample.energies = {run.amplitude * t * t, run.amplitude * t};
    sample.position_violation = 1e-10 * (1.0 + t);
    sample.velocity_violation = 1e-8 * (1.0 + t);
    sample.steps = 10 * k;
    writer.append_sample(sample);
  }
  // A run that never finishes keeps status "running" (the writer's destructor leaves it).
  if (run.status == "ok") writer.finish(results::RunStatus::kOk);
  if (run.status == "failed") writer.finish(results::RunStatus::kFailed, run.message);
}

}  // namespace limber::report::testing
