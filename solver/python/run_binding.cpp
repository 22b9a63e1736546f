#include "python/run_binding.h"

#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "python/case_binding.h"
#include "python/interruptible.h"
#include "python/results_binding.h"
#include "run/case_run.h"

namespace py = pybind11;

namespace limber::python {

namespace {

py::object run(const py::object& case_or_path, std::optional<std::string> integrator, std::optional<double> step,
               std::optional<double> rtol, std::optional<double> t_end, std::optional<std::filesystem::path> output,
               std::optional<py::function> progress, std::optional<int> modes, std::optional<std::string> formulation) {
  const std::shared_ptr<const io::Case> input = case_of(case_or_path);
  run::SettingsOverrides overrides;
  overrides.integrator = integrator.value_or("");
  overrides.formulation = formulation.value_or("");
  overrides.step = step;
  overrides.rtol = rtol;
  overrides.t_end = t_end;
  // Signals are checked (Python's handlers run) only in the main thread; elsewhere the GIL is
  // taken at a sample only for the progress callback.
  const bool check_signals = in_main_thread();
  std::optional<py::error_already_set> raised;  // by a signal handler or the callback
  std::vector<std::string> warnings;
  // results.h5 in `output`, or the same file in memory: one writer, one reader for both. The
  // writer lives and dies with the GIL released (it takes HDF5's lock; results_binding.h).
  std::vector<unsigned char> image;
  {
    py::gil_scoped_release released;
    const run::CaseRun prepared = run::prepare_case_run(*input, overrides, modes);
    const std::unique_ptr<results::ResultsWriter> writer =
        output ? run::open_case_results(*output, *input) : run::open_case_results_in_memory(*input);
    run::RunHooks hooks;
    hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample&) {
      if (!check_signals && !progress) return;
      py::gil_scoped_acquire acquired;
      try {
        if (check_signals && PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (progress) (*progress)(sample.t, prepared.settings.t_end);
      } catch (py::error_already_set& error) {
        const std::string what = py::str(error.type().attr("__name__"));
        raised.emplace(std::move(error));
        throw run::RunStopped{fmt::format("interrupted by {} after t = {:g} s", what, sample.t)};
      }
    };
    hooks.on_warning = [&](const std::string& warning) { warnings.push_back(warning); };
    try {
      run::run_case(prepared, *writer, hooks);
    } catch (const run::RunStopped&) {
      // The file is closed as "interrupted"; the Python error is raised below.
    }
    image = writer->file_image();
  }
  if (raised) throw std::move(*raised);
  const py::module_ python_warnings = py::module_::import("warnings");
  for (const std::string& warning : warnings) python_warnings.attr("warn")(warning, py::handle(PyExc_RuntimeWarning), 2);
  return output ? read_results(*output / results::kResultsFileName) : read_results(image);
}

}  // namespace

void bind_run(py::module_& module) {
  module.def("run", &run, py::arg("case_or_path"), py::kw_only(), py::arg("integrator") = py::none(),
             py::arg("step") = py::none(), py::arg("rtol") = py::none(), py::arg("t_end") = py::none(),
             py::arg("output") = py::none(), py::arg("progress") = py::none(), py::arg("modes") = py::none(),
             py::arg("formulation") = py::none(),
             R"(run(case_or_path, *, integrator=None, step=None, rtol=None, t_end=None, output=None, progress=None, modes=None, formulation=None) -> Results

Runs a mechanism as `limber run` does, in this process, and returns its Results.

Arguments (None keeps the case's `run` settings, docs/case-format.md):
  case_or_path  a Case (limber.load_case, limber.case_from_dict) or a case file's path
                (str or os.PathLike)
  integrator    'ida' (variable-step BDF, error control) or 'galpha' (fixed-step
                Lie-group generalized-alpha)
  step          generalized-alpha step [s] (> 0)
  rtol          IDA relative tolerance (>= 1e-11)
  t_end         end time [s] (>= 0)
  output        a folder (str or os.PathLike, created when missing) for results.h5 exactly as
                `limber run -o output` writes it; with None the results stay in memory and
                nothing is written (Results.path is then None). Both are the same file, written
                by the command's writer and read by one reader (in memory: an HDF5 file image),
                so the numbers are those of `limber run`, bit for bit.
  progress      a callable progress(t, t_end) [s], called after each sample written (with the
                GIL held); an exception it raises stops the run like Ctrl-C
  modes         normal modes of every flexible body in place of the case's (>= 0; their
                static modes kept), as `limber run --modes`
  formulation   'nonlinear' makes every flexible body of the case a nonlinear (co-rotational,
                unreduced) body, as `limber run --formulation nonlinear`; 'modal' or None
                keeps the case's (docs/nonlinear-beams.md)

The GIL is released while the mechanism is reduced, built and integrated, so threads can
run cases side by side. Ctrl-C (in the main thread) or an exception from `progress` stops the
run at its next sample: the file is closed with status 'interrupted' (kept in `output`) and
the exception (KeyboardInterrupt) propagates. A run that fails numerically returns its
Results with status 'failed' and a message, as the command keeps its samples; a run whose
own accuracy check fails returns status 'ok_inaccurate' (see Results.accuracy). Warnings
(a flexible body leaving its linear range, a singular configuration passed) are issued as
RuntimeWarning. Raises CaseError for bad input (the case, or an argument out of range),
RuntimeError when a flexible body's modes cannot be computed.)");
}

}  // namespace limber::python
