// A selection (selection_procedure.h) as the JSON document `limber select --json` prints and
// Python's `limber.select` returns (its fields are listed in `limber select --help`).
#pragma once

#include <string>

#include "select/selection_procedure.h"

namespace limber::select {

// One JSON object; directories relative to the request's root.
std::string selection_json(const Selection& selection, const SelectionRequest& request);

}  // namespace limber::select
