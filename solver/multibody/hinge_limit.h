// Force law, energy and event function of hinge latches and stops (model.h, HingeLimit).
// A latch holds the hinge at its angle once reached, through a torsional spring-damper of the
// locked hinge (a deployment latch's measured stiffness, not a rigid lock: latch-up loads stay
// finite and converge as the step shrinks). A stop is a one-sided spring-damper contact that
// pushes and never pulls (Hunt & Crossley's objection to a linear damper at separation).
// The switches are state events: the integrators locate the crossing of hinge_limit_event
// and only then flip State::engaged, so Newton never sees the force law change within a step.
// Damping at engagement: a damper acting in full from p = 0 makes the torque jump by c θ̇ at
// the instant of contact, a step load that rings every stiff mode of the hinge (the
// satellite's panel latch-up peaks came 0.4–2.4 ms after it and moved by 5 % between 0.125 ms
// and 62.5 µs steps). With damping_depth d > 0 the damping's share rises as the cubic step
// s = x² (3 − 2x), x = p / d clamped to [0, 1] (the ramp of Adams' IMPACT function over its
// penetration dmax): torque and its slope are continuous at engagement. A locked latch that
// reaches p = d is seated (a located event, not reported as one) and keeps its damping in full
// from then on, so its ringing about the latch angle stays damped.
#pragma once

#include <vector>

#include "multibody/constraints.h"
#include "multibody/model.h"

namespace limber::multibody {

// θ of the limit's joint, unwrapped within ±π of limit.angle_center [rad].
double hinge_limit_angle(const HingeLimit& limit, const RelativeAngle& angle);

// Modes of a hinge limit (State::engaged): free; engaged (a latch locked, a stop in contact);
// a locked latch seated past its damping_depth.
inline constexpr unsigned char kLimitFree = 0;
inline constexpr unsigned char kLimitEngaged = 1;
inline constexpr unsigned char kLatchSeated = 2;

// What a hinge limit applies and removes at (θ, θ̇) in its mode.
struct HingeLimitForce {
  double torque = 0.0;       // on body j about z_i [N·m]
  double dissipation = 0.0;  // power removed, ≥ 0 [W]
};
HingeLimitForce hinge_limit_force(const HingeLimit& limit, double theta, double rate, unsigned char mode);

// Elastic energy stored in the locked latch or the compressed stop [J].
double hinge_limit_energy(const HingeLimit& limit, double theta, bool engaged);

// The event function: its rise through 0 switches the mode (latch: engages; stop: contact
// begins when free, ends when engaged). A locked latch never switches again (−1).
double hinge_limit_event(const HingeLimit& limit, double theta, unsigned char mode);

// The mode after the limit's event in `mode` (latch: free → engaged → seated; stop: toggles).
unsigned char hinge_limit_next_mode(const HingeLimit& limit, unsigned char mode);

// A located mode switch: which limit, when, at what angle and rate, and into which mode.
struct HingeEvent {
  int force = 0;          // index into model.forces
  double t = 0.0;         // [s]
  double angle = 0.0;     // θ at the switch [rad]
  double rate = 0.0;      // θ̇ at the switch [rad/s]
  bool engaged = false;   // the mode after the switch (latch: locked; stop: in contact)
};

// The event functions of the limits `limits` (indices into model.forces) at `state`
// (position stage; updates ws.markers).
void hinge_limit_events(const Model& model, const std::vector<int>& limits, const State& state,
                        Workspace& ws, Eigen::VectorXd& e);

// θ (unwrapped) and θ̇ of a limit's joint from ws.markers, which must hold the velocity stage
// (update_marker_kinematics, constraints.h): one update serves every limit.
RelativeAngle hinge_limit_state(const HingeLimit& limit, const Workspace& ws);

}  // namespace limber::multibody
