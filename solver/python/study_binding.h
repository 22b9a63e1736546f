// limber.modes, limber.select and limber.sweep: the studies of `limber modes`, `limber select`
// and `limber sweep`, each returning what the command's --json prints, as Python dicts and
// lists (json.loads of the same document, written by the library that owns it: io/modes_json.h,
// select/selection_json.h, and `limber sweep` itself).
#pragma once

#include <pybind11/pybind11.h>

namespace limber::python {

// Adds modes, select and sweep to `module`.
void bind_studies(pybind11::module_& module);

}  // namespace limber::python
