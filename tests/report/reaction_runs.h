// Writes small results files with known reactions for the report tests, through the solver's
// results writer (limber_results): one rigid body "slider" on a joint "R3" (revolute,
// rod -> slider) whose reaction in the joint frame is
//   F(t) = A (cos(2 pi f t), 0.05 sin(2 pi f t), sin(2 pi f t)) [N], torque 0,
// and in ground axes (joint frame turned +90 deg about ground x) G(t) = (F_x, -F_z, F_y) [N],
// a driver "crank" with effort A t [N m], energies kinetic = A t^2 and driver_work = A t [J],
// position violation 1e-10 (1 + t) and velocity violation 1e-8 (1 + t).
// Samples at t_k = k T/(ns - 1).
#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <string>

namespace limber::report::testing {

struct ReactionRun {
  double amplitude = 100.0;  // A [N]
  double frequency = 2.0;    // f [Hz]
  double duration = 1.0;     // T [s]
  int samples = 101;         // ns
  std::string title = "reaction test run";
  // "ok": finished; "failed": finished as failed with `message`; "running": never finished.
  std::string status = "ok";
  std::string message;
};

void write_reaction_run(const std::filesystem::path& dir, const ReactionRun& run);

Eigen::Vector3d reaction_force(const ReactionRun& run, double t);        // F(t), joint frame
Eigen::Vector3d reaction_force_ground(const ReactionRun& run, double t);  // G(t), ground axes

}  // namespace limber::report::testing
