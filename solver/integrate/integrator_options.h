// Parameters of the time integrators, with the presets users pick from (house style §6).
// Every field is in SI units; `validate` throws InputError (expected/got) on bad values.
#pragma once

#include <functional>
#include <limits>

#include <Eigen/Core>

namespace limber::integrate {

enum class Method {
  kIda,               // SUNDIALS IDA (variable order BDF) on the stabilised index-2 GGL form
  kGeneralizedAlpha,  // Lie-group generalized-α, index 3, fixed step (Arnold & Brüls 2007)
};

// "ida" / "galpha" (the names of `limber run --integrator`).
const char* to_string(Method method);

// IDA's Newton matrix ∂F/∂y + c ∂F/∂y′ (docs/integrators.md, "SUNDIALS IDA"):
enum class IdaNewtonMatrix {
  kDifferences,  // IDA's difference quotient: ~n residuals per matrix, exact to O(√ε)
  kStructured,   // from F's form and one system evaluation, plus a kept difference of the
                 // dynamics rows (force elements, constraint forces) refreshed after Newton
                 // failures and restarts (ggl_equations.h)
};

// Integrals ∫ f(t, q, v, v̇, λ) dt accumulated along the run, e.g. the work of a force
// (f = its power [W]). `integrand` writes `size` values into f (pre-sized).
struct Quadrature {
  int size = 0;
  std::function<void(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                     const Eigen::VectorXd& vdot, const Eigen::VectorXd& lambda,
                     Eigen::VectorXd& f)>
      integrand;
  // IDA: absolute tolerance of the integrals, in their units (e.g. J for a work); 0 uses the
  // options' atol. Integrals start at 0, so their weight is 1/atol at first: an atol of 1e-11
  // on a work growing at 1e4 W stalls the first steps, and an integral scaled to the system
  // (rtol times its energy) does not. Gen-α ignores it.
  double atol = 0.0;
  // The integrals' jump at a velocity breakpoint (MechanicalSystem::velocity_breakpoints),
  // where v jumps from v_before to v_after at (t, q): e.g. the work of the impulse. Writes
  // `size` values into dz (pre-sized); unset: no jump.
  std::function<void(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v_before,
                     const Eigen::VectorXd& v_after, Eigen::VectorXd& dz)>
      jump;
};

// IDA's error weights of q and v, w_i = 1 / (rtol s_i + atol) (docs/nonlinear-beams.md, "IDA with a
// nonlinear body"):
enum class IdaErrorWeights {
  kPerComponent,  // s_i = |y_i|: IDA's own; a coordinate passing through 0 is held to atol
  kPerGroup,      // s_i = max(|y_i|, max_j |y_j|) over q, resp. v: errors relative to the
                  // mechanism's size and speed, as λ's weight is relative to its largest
};

struct IntegratorOptions {
  Method method = Method::kIda;

  // IDA: local error control ‖e_i‖ ≤ rtol |y_i| + atol on q, v and quadratures.
  double rtol = 1e-6;
  double atol = 1e-8;
  double max_step = 0.0;      // upper bound on IDA's step [s]; 0 = none
  double initial_step = 0.0;  // IDA's first step [s]; 0 = IDA's own estimate
  // Highest BDF order IDA may use, 1..5; 0 = 5 (IDA's own). BDF3-5 are not A-stable (stability
  // angles 86°, 73°, 51°: Hairer & Wanner, Solving ODEs II, §V.2): lightly damped structural
  // modes, whose eigenvalues lie near the imaginary axis, make them fail the error test step
  // after step. `limber run` picks 2 for mechanisms with flexible bodies (docs/integrators.md).
  int max_order = 0;
  // IDA: how its Newton matrix is formed (above).
  IdaNewtonMatrix ida_newton_matrix = IdaNewtonMatrix::kDifferences;
  // IDA: how q's and v's error weights scale (above). `limber run` picks kPerGroup with a
  // nonlinear body.
  IdaErrorWeights ida_error_weights = IdaErrorWeights::kPerComponent;

  // Generalized-α: fixed step h [s] and spectral radius at infinity ρ∞ ∈ [0, 1]
  // (Chung & Hulbert 1993: ρ∞ = 1 no numerical damping, ρ∞ = 0 asymptotic annihilation).
  // Constrained systems need ρ∞ < 1 (see `trapezoidal`).
  double step = 1e-3;
  double rho_inf = 0.8;
  // Generalized-α: a shorter step `event_step` [s] for `event_window` s after the start and after
  // every event, `step` elsewhere (0: `step` throughout). A release or a latch-up rings stiff
  // modes that structural damping quiets within the window; resolving them only there costs a
  // fraction of a run at the short step throughout (docs/integrators.md, "Event windows").
  // IDA ignores both: its error control shortens and lengthens its steps itself.
  double event_step = 0.0;
  double event_window = 0.0;
  int max_newton_iterations = 10;
  // Newton stops when ‖Δξ‖∞ ≤ newton_tolerance ‖ξ‖∞ and ‖GᵀΔλ‖∞ ≤ newton_tolerance ‖Gᵀλ‖∞
  // (each plus a round-off floor), ξ the step's tangent displacement [m, rad]: relative bounds.
  double newton_tolerance = 1e-8;
  int max_step_halvings = 6;  // a Newton failure halves h at most this many times
  // A state event (mechanical_system.h) is located to within this time [s]: the step that
  // crosses it is cut back until it ends no further than this past the crossing. (IDA locates
  // events with its own root finding, to round-off.)
  double event_tolerance = 1e-9;

  // Both: budget of accepted steps, and the time not to step beyond (set by `simulate` to
  // the last sample, so a model is never evaluated past the end of the run).
  long max_steps = 10'000'000;
  // Both: wall-clock budget of the integration [s], checked after every step: a run that asks
  // for more than it can do in that time fails with kWallClock (and keeps its samples).
  double max_wall_seconds = std::numeric_limits<double>::infinity();
  double t_stop = std::numeric_limits<double>::infinity();

  Quadrature quadrature;

  // Both: an observer of the solution the integrator steps through, called in time order at
  // the start (after init) and at the end of every accepted step (IDA: every step IDASolve
  // takes, and every event it locates), with t, q, v, v̇ and λ there: the states between
  // which the output samples are interpolated, so an extreme that falls between two samples
  // is seen at the step nearest it (run/event_peaks.h). Called with the modes of the step
  // just taken, before the events located at its end switch them. Generalized-α leaves out
  // steps shorter than 1 % of its step (cut back to an event): their v̇ and λ carry round-off
  // amplified by 1/(βh²) (generalized_alpha.cpp, kObservedStepFraction). Unset: none.
  std::function<void(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                     const Eigen::VectorXd& vdot, const Eigen::VectorXd& lambda)>
      on_step;

  // Presets.
  static IntegratorOptions ida(double rtol, double atol);
  static IntegratorOptions generalized_alpha(double step, double rho_inf = 0.8);
  // ρ∞ = 1: the trapezoidal rule (Newmark average acceleration), no numerical dissipation.
  // For unconstrained systems only: with index-3 constraints its undamped spurious modes let
  // errors grow (Cardona & Géradin 1989; on the pendulum at h = 1 ms the energy error grows
  // from 1e-5 to 0.2 between 10 and 20 s, while ρ∞ = 0.99 stays at 1.6e-6).
  static IntegratorOptions trapezoidal(double step);

  // Throws InputError when a field is out of range (message says expected/got).
  void validate() const;
};

}  // namespace limber::integrate
