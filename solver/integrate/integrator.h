// One small interface for every time integrator of limber (house style §6; anchor: MFEM
// linalg/ode.hpp). An integrator advances a MechanicalSystem from a consistent initial state and
// delivers the state at requested output times by interpolating within its own steps (it never
// shortens a step to hit an output time).
#pragma once

#include <memory>

#include <Eigen/Core>

#include "integrate/integrator_options.h"
#include "core/mechanical_system.h"
#include "integrate/status.h"

namespace limber::integrate {

// Start of a run: time [s], coordinates q (nq) and velocities v (nv). They need only satisfy
// the constraints approximately; init() projects them (see consistent_state.h).
struct InitialState {
  double t = 0.0;
  Eigen::VectorXd q;
  Eigen::VectorXd v;
};

// The state at one output time.
struct Sample {
  double t = 0.0;
  Eigen::VectorXd q;          // nq
  Eigen::VectorXd v;          // nv
  Eigen::VectorXd vdot;       // nv, accelerations v̇
  Eigen::VectorXd lambda;     // nc, multipliers of M v̇ + Gᵀλ = Q
  Eigen::VectorXd integrals;  // IntegratorOptions::quadrature.size accumulated integrals
  Statistics statistics;      // work done up to t
};

class Integrator {
 public:
  virtual ~Integrator() = default;

  // Validates options (throws InputError), projects x0 onto the constraints and computes
  // consistent accelerations and multipliers. `system` must outlive the integrator, which
  // changes its discrete state (constraint rows, event modes) as the motion goes.
  // Returns a failure status when that projection does not converge or is singular.
  virtual Status init(MechanicalSystem& system, const InitialState& x0,
                      const IntegratorOptions& options) = 0;
  // Advances to t_out ≥ the previous output time and fills `out`. On failure `out` is not
  // touched and the status says when and why; the integrator cannot continue. When an event
  // located before t_out leaves the system's restart_due() true, it stops there instead:
  // StatusCode::kRestartDue, `out` the state at the event (after its mode switch), and the
  // integrator cannot continue either (its caller starts a new one).
  virtual Status advance_to(double t_out, Sample& out) = 0;
  virtual const Statistics& statistics() const = 0;
};

// An integrator of the given kind (not yet initialised).
std::unique_ptr<Integrator> make_integrator(Method method);

}  // namespace limber::integrate
