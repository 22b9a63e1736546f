// The step each mode set of `limber select` runs at (docs/select.md, "Step"): one that resolves
// the set's highest retained natural frequency f_max, so that a richer set is not measured
// against a step that cannot follow its stiff static modes.
//
// Generalized-α: h ≤ 1 / (N f_max) with N = kStepsPerPeriod = 20. At ρ∞ = 0.8 the method's
// relative period error on an undamped oscillator is 0.86 % at 20 steps per period (3.4 % at
// 10, 0.38 % at 30; measured with limber's integrator in tests/integrate/
// generalized_alpha_test.cpp; the leading term Ω²/12, Ω = 2π/N, gives 0.82 % at N = 20,
// Chung & Hulbert 1993): below 1 % per period, and its numerical damping there is below
// 0.01 % of the amplitude per period.
// IDA: max_step ≤ 1 / (N f_max) likewise (its error control then sees every retained mode).
// The step is never made longer than the case's, and never shorter than the case's divided by
// StepPolicy::max_refinement (the wall time grows with the refinement; IDA without a max_step
// in the case has no such floor): a set whose f_max needs more is run at that floor and marked
// not resolved, and `select` says so.
// Generalized-α, by default: the resolving step only in event windows (the peak window after the
// start and after every event: IntegratorOptions::event_step), the case's between them. The stiff
// modes a release or latch-up rings are damped out within the window (1 % of critical damps a
// 1 kHz mode by e^-19 in 0.3 s); between events the case's step follows the deployment, and the
// run's accuracy check (measured apart in and outside the windows) says when it does not.
#pragma once

#include "integrate/integrator_options.h"
#include "multibody/model.h"

namespace limber::select {

inline constexpr int kStepsPerPeriod = 20;

struct StepPolicy {
  bool keep_case_step = false;  // run every set at the case's settings (only report resolution)
  int max_refinement = 8;       // the step is at least the case's (gen-α step, IDA max_step) / this
  double scale = 1.0;           // the chosen step times this (the reference's halved-step check: 0.5)
  bool whole_run = false;       // the chosen step throughout, not only in the event windows
};

struct StepChoice {
  double f_max = 0.0;             // highest retained natural frequency over the flexible bodies [Hz]
  double needed = 0.0;            // 1 / (kStepsPerPeriod f_max) [s]; 0 without flexible modes
  double step = 0.0;              // generalized-α step, or IDA's max_step (0: none) [s]
  double steps_per_period = 0.0;  // 1 / (step f_max); infinite when nothing bounds it
  bool resolved = true;           // step ≤ needed (IDA with no max_step: only when needed is 0)
  // Generalized-α: `step` applies for `window` s after the start and after every event, and
  // `outside_step` elsewhere; window 0: `step` throughout.
  double window = 0.0;
  double outside_step = 0.0;
};

// Highest natural frequency over the flexible bodies' modes [Hz] (0 without any).
double highest_frequency(const multibody::Model& model);

// The step for a set with highest frequency f_max [Hz] under `policy`, from the case's
// integrator options; `event_window` [s] is the length of the windows after the start and after
// every event in which a refined generalized-α step applies (0: throughout).
StepChoice choose_step(double f_max, const integrate::IntegratorOptions& options, const StepPolicy& policy,
                       double event_window);

// `options` with the choice applied (generalized-α: step, or event_step and event_window with the
// step between windows; IDA: max_step).
integrate::IntegratorOptions apply_step(integrate::IntegratorOptions options, const StepChoice& choice);

}  // namespace limber::select
