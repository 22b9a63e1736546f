#include "python/sweep_binding.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fmt/format.h>

#include <unistd.h>

#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "python/case_binding.h"
#include "python/interruptible.h"
#include "sweep/sweep_study.h"

namespace py = pybind11;

namespace limber::python {

namespace {

// The children's threads: one each (as `limber sweep` sets them) unless the user set a
// number; restored when the sweep ends.
class SingleThreadedChildren {
 public:
  SingleThreadedChildren() {
    for (const char* name : {"OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"}) {
      if (std::getenv(name) == nullptr && setenv(name, "1", 0) == 0) set_.push_back(name);
    }
  }
  ~SingleThreadedChildren() {
    for (const char* name : set_) unsetenv(name);
  }
  SingleThreadedChildren(const SingleThreadedChildren&) = delete;
  SingleThreadedChildren& operator=(const SingleThreadedChildren&) = delete;

 private:
  std::vector<const char*> set_;
};

py::object sweep(const py::object& case_or_path, const std::vector<std::string>& over,
                 std::optional<std::filesystem::path> output, const std::string& reference,
                 std::optional<double> target, const std::string& norm, const std::vector<std::string>& quantities,
                 int jobs, bool fresh, std::optional<double> t_end, std::optional<double> atol,
                 std::optional<double> max_wall, std::optional<py::function> log) {
  // The points' `limber run` children read the case file themselves.
  const std::string case_file = case_of(case_or_path)->file;
  if (case_file == "<dict>") throw InputError("expected a case file (a path or limber.load_case's Case), got a dict case");
  if (norm != "rms" && norm != "peak") throw InputError("expected norm 'rms' or 'peak', got '" + norm + "'");
  sweep::SweepRequest request;
  request.case_file = case_file;
  request.root = output ? *output
                        : std::filesystem::path("out") / (std::filesystem::path(case_file).stem().string() + "_sweep");
  request.over = over;
  request.reference = reference;
  request.target = target;
  request.rms = norm == "rms";
  request.quantities = quantities;
  request.jobs = jobs;
  request.fresh = fresh;
  request.t_end = t_end;
  request.atol = atol;
  request.max_wall = max_wall;
  request.executable = limber_executable();

  const SingleThreadedChildren single_threaded;
  std::optional<sweep::SweepOutcome> outcome;
  run_interruptible([&](const std::atomic<bool>& stop) {
    sweep::SweepHooks hooks;
    if (log) {
      hooks.text = hooks.log = [&](const std::string& line) {
        py::gil_scoped_acquire acquired;
        (*log)(line);
      };
    }
    // SIGTERM to the running points: each closes its file as "interrupted"; a rerun resumes.
    hooks.should_stop = [&] { return stop.load(); };
    outcome = sweep::run_sweep(request, sweep::RankGroup{}, hooks);
  });
  if (outcome->interrupted) {
    PyErr_SetString(PyExc_KeyboardInterrupt, "the sweep was stopped; finished points are kept and a rerun resumes");
    throw py::error_already_set();
  }
  return py::module_::import("json").attr("loads")(outcome->document);
}

}  // namespace

std::filesystem::path limber_executable() {
  std::vector<std::filesystem::path> looked;
  const auto usable = [&](const std::filesystem::path& path) {
    looked.push_back(path);
    return access(path.c_str(), X_OK) == 0;
  };
  if (const char* given = std::getenv("LIMBER_EXECUTABLE")) {
    if (usable(given)) return given;
    throw std::runtime_error(fmt::format("LIMBER_EXECUTABLE={} is not an executable file", given));
  }
  // Installed: <prefix>/lib/python3/dist-packages/limber*.so and <prefix>/bin/limber.
  const std::filesystem::path module_file = py::module_::import("limber").attr("__file__").cast<std::string>();
  const std::filesystem::path installed = module_file.parent_path() / ".." / ".." / ".." / "bin" / "limber";
  if (usable(installed)) return installed.lexically_normal();
#ifdef LIMBER_BUILD_EXECUTABLE
  // The build tree's module: the build tree's executable.
  if (module_file.parent_path() == std::filesystem::path(LIMBER_BUILD_MODULE_DIR) && usable(LIMBER_BUILD_EXECUTABLE)) {
    return LIMBER_BUILD_EXECUTABLE;
  }
#endif
  const py::object on_path = py::module_::import("shutil").attr("which")("limber");
  if (!on_path.is_none()) return on_path.cast<std::string>();
  std::string places;
  for (const std::filesystem::path& path : looked) places += " " + path.string() + ",";
  throw std::runtime_error("cannot find the `limber` executable (looked at" + places +
                           " and PATH); set LIMBER_EXECUTABLE to its path");
}

void bind_sweep(py::module_& module) {
  module.def("sweep", &sweep, py::arg("case_or_path"), py::kw_only(), py::arg("over"), py::arg("output") = py::none(),
             py::arg("reference") = "tight", py::arg("target") = py::none(), py::arg("norm") = "rms",
             py::arg("quantities") = std::vector<std::string>{}, py::arg("jobs") = 0, py::arg("fresh") = false,
             py::arg("t_end") = py::none(), py::arg("atol") = py::none(), py::arg("max_wall") = py::none(),
             py::arg("log") = py::none(),
             R"(sweep(case_or_path, *, over, output=None, reference='tight', target=None, norm='rms', quantities=[], jobs=0, fresh=False, t_end=None, atol=None, max_wall=None, log=None) -> dict

Runs a case over a grid of settings and measures each point's cost and error against a
reference, as `limber sweep` does (docs/sweep.md), and returns what its --json prints:
'status', 'case', 'reference' {'label', 'results'}, 'quantities', 'norm', 'target',
'target_met', 'chosen', 'run_options', 'points' (one dict per grid point: its setting, status,
wall_s, steps, errors, ...), 'directory'.

The sweep runs in this process, through the library `limber sweep` uses; each grid point, as
in the command, is a child `limber run` process (single-threaded, its peak memory measured, a
crash costing one point) of the `limber` executable, found at $LIMBER_EXECUTABLE, beside the
installed module (<prefix>/bin/limber), in the build tree, or on PATH.

Arguments (the options of `limber sweep` of the same names):
  case_or_path  a case file's path, or a Case read from one (limber.load_case)
  over          the axes, a list of strings: names with their default values ('integrator',
                'rtol', 'step', 'modes') or 'axis=v1,v2,...', e.g. ['integrator=galpha',
                'step=1e-3,5e-4']
  output        the sweep's folder (DIR); None: out/<case file stem>_sweep
  reference     'tight' (one much tighter run) or a finished results.h5
  target        error target as a fraction (0.01 = 1 %): 'chosen' names the cheapest point
                meeting it
  norm          'rms' or 'peak': the error measure for target
  quantities    names of the compared quantities, e.g. ['R3 force x'] (default: every
                joint reaction and deflection component >= 1 % of the largest of its kind)
  jobs          runs at a time (0: the number of cores)
  fresh         rerun every point, also those finished in an earlier sweep of DIR
  t_end         end time of every run [s]
  atol          IDA absolute tolerance of every IDA run
  max_wall      wall-clock budget of each point's run [s]
  log           a callable log(line) given the command's progress lines (GIL held)

Ctrl-C stops the sweep (finished points are kept; the same call resumes) and raises
KeyboardInterrupt. Raises CaseError for bad input, RuntimeError when the reference run fails
or its own accuracy check does.)");
}

}  // namespace limber::python
