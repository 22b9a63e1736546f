// limber.run: a case's run through the code `limber run` uses (run/case_run.h) into a
// results.h5 (a temporary one unless `output` names a folder), read back as limber.Results, so
// that its numbers are those of the command, bit for bit. The GIL is released while the run
// goes; it is taken back at each sample to call the progress callback and, in the main thread,
// to let Ctrl-C raise KeyboardInterrupt, which closes the file as "interrupted".
#pragma once

#include <pybind11/pybind11.h>

namespace limber::python {

// Adds run to `module`.
void bind_run(pybind11::module_& module);

}  // namespace limber::python
