// IDA's first step at a (re)start, chosen by us rather than by IDA (IDASetInitStep).
#pragma once

#include <Eigen/Core>

#include "core/mechanical_system.h"
#include "integrate/integrator.h"
#include "integrate/integrator_options.h"

namespace limber::integrate {

// Weighted RMS norm of x with IDA's weights 1/(rtol |y| + atol).
double weighted_rms(const Eigen::VectorXd& x, const Eigen::VectorXd& y, double rtol, double atol);

// First step from the second derivative (Hairer, Nørsett & Wanner, Solving ODEs I, §II.4):
// ‖y'‖ and ‖y''‖ of [q, v] in IDA's weights (options' rtol, atol), y'' by a difference of
// accelerations over an explicit Euler step from the consistent state x0 with accelerations
// `vdot`. IDA's own choice, 0.5/‖y'‖, is first-order: a body at rest with an acceleration a and
// atol = 1e-10 gets h0 ~ 1e-10/a, where the multipliers, which carry round-off divided by h,
// cannot converge in Newton.
double initial_step(MechanicalSystem& system, const InitialState& x0, const Eigen::VectorXd& vdot,
                    const IntegratorOptions& options);

}  // namespace limber::integrate
