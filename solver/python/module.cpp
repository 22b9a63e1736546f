// The Python module `limber` (docs/python.md): cases read and checked, runs and their results
// as numpy arrays, over the libraries the `limber` command uses; no solver code of its own.
#include <pybind11/pybind11.h>

#include "modal/blas_threads.h"
#include "python/case_binding.h"
#include "python/results_binding.h"
#include "python/run_binding.h"
#include "python/study_binding.h"

PYBIND11_MODULE(limber, module) {
  module.doc() =
      "limber: dynamics of mechanisms with flexible parts (docs/python.md).\n\n"
      "  case = limber.load_case('cases/slider_crank.yaml')   # or limber.case_from_dict(d)\n"
      "  results = limber.run(case, t_end=0.1)\n"
      "  results.joints['R3'].force_joint    # numpy [ns, 3]\n"
      "  limber.read_results('out/slider_crank')   # what `limber run` wrote\n"
      "  limber.modes(case), limber.select(case), limber.sweep(path, over=[...])   # their --json";
  module.attr("__version__") = LIMBER_VERSION;
  // A process-wide setting, chosen once at import: one BLAS thread (modal/blas_threads.h;
  // docs/python.md says so, since numpy in the same process shares it).
  limber::modal::use_single_threaded_blas();
  limber::python::bind_case(module);
  limber::python::bind_results(module);
  limber::python::bind_run(module);
  limber::python::bind_studies(module);
}
