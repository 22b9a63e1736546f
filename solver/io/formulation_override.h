// `--formulation nonlinear` (limber run, and the `--reference nonlinear` of limber sweep and
// limber select): a case's flexible bodies all made nonlinear (docs/nonlinear-beams.md), as if
// each entry said `formulation: nonlinear`, so that a modal case runs its own accurate reference
// unchanged.
#pragma once

#include <string>

#include "io/case_reader.h"

namespace limber::io {

// The formulation names the option takes: "modal" (the case's own, nothing changed) or
// "nonlinear". Throws InputError naming `option` for any other.
bool nonlinear_formulation_requested(const std::string& name, const std::string& option);

// Makes every flexible body of `input`'s mechanism nonlinear and drops it from the modal
// reduction. What `formulation: nonlinear` refuses fails here at the body's entry (InputError,
// file:line:col): a model with shells or triangles, initial modal coordinates or velocities,
// damping ratios other than 0 (a nonlinear body takes 0 or a Rayleigh pair; the modal default
// is a ratio of 0.01). Stress output carries over (the beams' stresses are recovered). geometric_stiffening is a correction of the modes and means
// nothing without them: it is ignored. `option` starts the messages (what the user asked for it
// with). Precondition: input.mechanism is set.
void make_flexible_bodies_nonlinear(Case& input, const std::string& option = "--formulation nonlinear");

}  // namespace limber::io
