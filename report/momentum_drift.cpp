#include "momentum_drift.h"

#include <algorithm>
#include <cmath>

namespace limber::report {
namespace {

// The name results.h5 gives the ground in a joint's body_i and body_j (the model's body 0,
// solver/multibody/model_builder.cpp).
constexpr const char* kGroundName = "ground";

// A gravity energy that moves by more than rounding: the bodies fall, momentum is not kept.
bool has_gravity(const RunData& run) {
  for (const Series& s : run.energies) {
    if (s.name != "gravity" || s.values.size() == 0) continue;
    const double range = s.values.maxCoeff() - s.values.minCoeff();
    if (range > 1e-12 * std::max(1.0, s.values.cwiseAbs().maxCoeff())) return true;
  }
  return false;
}

// The largest distance between two body origins at the first sample [m].
double system_size(const render::Results& results) {
  double size = 0.0;
  for (const render::BodyTrack& a : results.bodies) {
    for (const render::BodyTrack& b : results.bodies) {
      if (a.position.rows() == 0 || b.position.rows() == 0) continue;
      size = std::max(size, (a.position.row(0) - b.position.row(0)).norm());
    }
  }
  return size;
}

}  // namespace

std::optional<MomentumDrift> momentum_drift(const RunData& run) {
  const Eigen::Index ns = run.momentum.rows();
  if (ns < 2) return std::nullopt;
  const bool grounded = std::any_of(run.results.joints.begin(), run.results.joints.end(),
                                    [](const render::JointTrack& j) {
                                      return j.body_i == kGroundName || j.body_j == kGroundName;
                                    });
  if (grounded || has_gravity(run)) return std::nullopt;
  const Eigen::Vector3d P0 = run.momentum.row(0).head<3>(), L0 = run.momentum.row(0).tail<3>();
  MomentumDrift d;
  d.linear = (run.momentum.row(ns - 1).head<3>().transpose() - P0).norm();
  d.angular = (run.momentum.row(ns - 1).tail<3>().transpose() - L0).norm();
  // The scale: sqrt(2 m T_peak), the whole mass at the peak kinetic energy.
  double mass = 0.0, kinetic = 0.0;
  for (const BodyMass& b : run.body_masses) mass += b.mass;
  for (const Series& s : run.energies) {
    if (s.name == "kinetic" && s.values.size() > 0) kinetic = s.values.maxCoeff();
  }
  const double moving = std::sqrt(2.0 * mass * std::max(kinetic, 0.0));
  d.linear_scale = std::max(P0.norm(), moving);
  d.angular_scale = std::max(L0.norm(), moving * system_size(run.results));
  return d;
}

}  // namespace limber::report
