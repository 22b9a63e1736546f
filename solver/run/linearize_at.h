// `limber linearize --at T`: the mechanism linearized about the state a run of the case reaches
// at time T (run_driver.h, without results.h5): hold-downs released by T left out, hinge latches
// and stops in the modes the run switched them to (a locked latch seated, its damping in full,
// once a sample shows its penetration at its damping_depth: the run seats it at a located
// switch it does not report, which a latch-up that only grazes the depth between two samples
// would escape), the constraint rows re-analysed at that state. The state is in motion in general (residual vibration, a driven crank): the
// linearization then holds its velocity as linearize_run.h says (docs/linearize.md). With
// settings.statics the point is instead the static equilibrium statics.h finds from that state
// at rest, the hinges in the modes the run left them in (`--at T --statics`: the deployed
// spacecraft at rest, its rigid modes zeros; docs/linearize.md, "Linearized at rest or in motion").
#pragma once

#include "io/mechanism_reader.h"
#include "run/linearize_run.h"
#include "run/run_driver.h"

namespace limber::run {

// Runs the case from t = 0 (its own run settings: start, integrator) to `t_at`, then linearizes
// there. Throws InputError when t_at is not within (0, run.t_end]. A run that fails is returned
// (ok false, failure "run: <its failure>", its message), and so are statics that fail (failure
// "statics").
LinearizeSummary linearize_at(const multibody::Model& model, const multibody::AssemblyOptions& assembly,
                              const io::RunSettings& run, double t_at, const LinearizeSettings& settings);

}  // namespace limber::run
