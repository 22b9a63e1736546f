#include "multibody/hinge_limit.h"

#include <algorithm>

#include "multibody/body.h"

namespace limber::multibody {

double hinge_limit_angle(const HingeLimit& limit, const RelativeAngle& angle) {
  return limit.angle_center + wrap_angle(angle.theta - limit.angle_center);
}

namespace {

// The damping's share at penetration p in `mode` (hinge_limit.h).
double damping_share(const HingeLimit& limit, double p, unsigned char mode) {
  if (mode == kLatchSeated || limit.damping_depth <= 0.0) return 1.0;
  const double x = std::clamp(p / limit.damping_depth, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

}  // namespace

HingeLimitForce hinge_limit_force(const HingeLimit& limit, double theta, double rate, unsigned char mode) {
  HingeLimitForce f;
  if (mode == kLimitFree) return f;
  const double p = limit.direction * (theta - limit.angle);
  const double damping = damping_share(limit, p, mode) * limit.damping;
  if (limit.kind == HingeLimitKind::kLatch) {
    // Locked hinge: a two-sided torsional spring-damper about the latch angle.
    f.torque = -limit.stiffness * (theta - limit.angle) - damping * rate;
    f.dissipation = damping * rate * rate;
    return f;
  }
  // Stop: contact force on the penetration p = direction (θ − angle), clamped to push only.
  const double p_rate = limit.direction * rate;
  const double push = std::max(0.0, limit.stiffness * p + damping * p_rate);
  f.torque = -limit.direction * push;
  // Removed power = −τ θ̇ − d/dt(½ k p²); it is c ṗ² while unclamped and k p |ṗ| when clamped.
  f.dissipation = push * p_rate - limit.stiffness * p * p_rate;
  return f;
}

double hinge_limit_energy(const HingeLimit& limit, double theta, bool engaged) {
  if (!engaged) return 0.0;
  const double p = limit.direction * (theta - limit.angle);
  if (limit.kind == HingeLimitKind::kStop && p <= 0.0) return 0.0;
  return 0.5 * limit.stiffness * p * p;
}

double hinge_limit_event(const HingeLimit& limit, double theta, unsigned char mode) {
  const double p = limit.direction * (theta - limit.angle);
  if (limit.kind == HingeLimitKind::kStop) return mode == kLimitFree ? p : -p;
  if (mode == kLimitFree) return p;
  // Locked: seated when p reaches the damping's depth; then no switch ever again.
  return mode == kLimitEngaged && limit.damping_depth > 0.0 ? p - limit.damping_depth : -1.0;
}

unsigned char hinge_limit_next_mode(const HingeLimit& limit, unsigned char mode) {
  if (limit.kind == HingeLimitKind::kStop) return mode == kLimitFree ? kLimitEngaged : kLimitFree;
  return mode == kLimitFree ? kLimitEngaged : kLatchSeated;
}

void hinge_limit_events(const Model& model, const std::vector<int>& limits, const State& state,
                        Workspace& ws, Eigen::VectorXd& e) {
  e.resize(static_cast<Eigen::Index>(limits.size()));
  if (limits.empty()) return;
  // The limits' own markers only: this runs at every step, the other markers are not needed.
  for (const int force : limits) {
    const auto& limit = std::get<HingeLimit>(model.forces[static_cast<size_t>(force)]);
    for (const int marker : {limit.marker_i, limit.marker_j}) {
      marker_kinematics(model, marker, state.q, nullptr, ws.markers[static_cast<size_t>(marker)]);
    }
  }
  for (size_t k = 0; k < limits.size(); ++k) {
    const auto& limit = std::get<HingeLimit>(model.forces[limits[k]]);
    const RelativeAngle angle =
        relative_angle(ws.markers[limit.marker_i], ws.markers[limit.marker_j], Stage::kPosition);
    const size_t f = static_cast<size_t>(limits[k]);
    const unsigned char mode = f < state.engaged.size() ? state.engaged[f] : kLimitFree;
    e(static_cast<Eigen::Index>(k)) = hinge_limit_event(limit, hinge_limit_angle(limit, angle), mode);
  }
}

RelativeAngle hinge_limit_state(const HingeLimit& limit, const Workspace& ws) {
  RelativeAngle angle =
      relative_angle(ws.markers[limit.marker_i], ws.markers[limit.marker_j], Stage::kVelocity);
  angle.theta = hinge_limit_angle(limit, angle);
  return angle;
}

}  // namespace limber::multibody
