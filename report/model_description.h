// How the report names what a flexible body is when it has no modes: a body with
// `formulation: nonlinear`, whose shape results.h5 stores node by node (docs/results-format.md,
// "Nonlinear bodies"). Its model is its beam elements, not a mode count.
#pragma once

#include <string>

#include "results_reader.h"

namespace limber::report {

// Whether `body` is nonlinear: flexible, with stored node displacements (and no modes).
bool is_nonlinear(const render::BodyTrack& body);

// Its model in words: "nonlinear, 100 beam elements (101 nodes)".
std::string nonlinear_description(const render::BodyTrack& body);

}  // namespace limber::report
