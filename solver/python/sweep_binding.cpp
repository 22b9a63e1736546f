#include "python/sweep_binding.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fmt/format.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "python/case_binding.h"
#include "python/interruptible.h"
#include "python/temporary_folder.h"
#include "sweep/process_pool.h"

namespace py = pybind11;

namespace limber::python {

namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The last non-empty line of `text`, without the command's "limber: error: " prefix.
std::string last_line(const std::string& text) {
  std::string line;
  std::istringstream lines(text);
  for (std::string next; std::getline(lines, next);) {
    if (!next.empty()) line = next;
  }
  const std::string prefix = "limber: error: ";
  return line.rfind(prefix, 0) == 0 ? line.substr(prefix.size()) : line;
}

std::string option_value(double value) { return fmt::format("{}", value); }

py::object sweep(const py::object& case_or_path, const std::vector<std::string>& over,
                 std::optional<std::filesystem::path> output, const std::string& reference,
                 std::optional<double> target, const std::string& norm, const std::vector<std::string>& quantities,
                 int jobs, bool fresh, std::optional<double> t_end, std::optional<double> atol,
                 std::optional<double> max_wall) {
  // The child reads the case file itself.
  const std::string case_file = case_of(case_or_path)->file;
  if (case_file == "<dict>") throw InputError("expected a case file (a path or limber.load_case's Case), got a dict case");
  if (over.empty()) throw InputError("expected over=['integrator', 'rtol', ...] (the axes), got none");
  std::vector<std::string> argv = {limber_executable().string(), "sweep", case_file, "--over"};
  argv.insert(argv.end(), over.begin(), over.end());
  if (output) argv.insert(argv.end(), {"-o", output->string()});
  argv.insert(argv.end(), {"--reference", reference, "--norm", norm, "--jobs", std::to_string(jobs)});
  if (target) argv.insert(argv.end(), {"--target", option_value(*target)});
  if (!quantities.empty()) argv.insert(argv.end(), {"--quantities", fmt::format("{}", fmt::join(quantities, ","))});
  if (fresh) argv.push_back("--fresh");
  if (t_end) argv.insert(argv.end(), {"--t-end", option_value(*t_end)});
  if (atol) argv.insert(argv.end(), {"--atol", option_value(*atol)});
  if (max_wall) argv.insert(argv.end(), {"--max-wall", option_value(*max_wall)});
  argv.push_back("--json");

  const TemporaryFolder streams;
  const sweep::ChildJob job{argv, streams.path() / "stdout.json", streams.path() / "stderr.txt"};
  sweep::ChildOutcome outcome;
  run_interruptible([&](const std::atomic<bool>& stop) {
    sweep::PoolHooks hooks;
    hooks.on_finish = [&](std::size_t, const sweep::ChildOutcome& o) { outcome = o; };
    // SIGTERM: the sweep stops its points, keeps the finished ones and writes its table.
    hooks.should_stop = [&] { return stop.load(); };
    sweep::run_processes({job}, 1, hooks);
  });
  const std::string errors = read_text(job.stderr_file);
  if (!outcome.spawn_error.empty()) throw std::runtime_error("cannot start " + argv[0] + ": " + outcome.spawn_error);
  if (outcome.exit_code == 0) return py::module_::import("json").attr("loads")(read_text(job.stdout_file));
  if (outcome.exit_code == 1) throw InputError(last_line(errors));
  if (outcome.exit_code == 4) {  // interrupted from outside (SIGTERM to the child)
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  throw std::runtime_error(fmt::format("limber sweep ended with {}: {}",
                                       outcome.signal ? fmt::format("signal {}", outcome.signal)
                                                      : fmt::format("exit code {}", outcome.exit_code),
                                       last_line(errors)));
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
             R"(sweep(case_or_path, *, over, output=None, reference='tight', target=None, norm='rms', quantities=[], jobs=0, fresh=False, t_end=None, atol=None, max_wall=None) -> dict

Runs a case over a grid of settings and measures each point's cost and error against a
reference, as `limber sweep` does (docs/sweep.md), and returns what its --json prints:
'status', 'case', 'reference' {'label', 'results'}, 'quantities', 'norm', 'target',
'target_met', 'chosen', 'run_options', 'points' (one dict per grid point: its setting, status,
wall_s, steps, errors, ...), 'directory'.

`limber sweep` runs as a child process of the `limber` executable (each grid point is a child
`limber run` of it, single-threaded, its peak memory measured); found at $LIMBER_EXECUTABLE,
beside the installed module (<prefix>/bin/limber), in the build tree, or on PATH.

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

Ctrl-C stops the sweep (finished points are kept; the same call resumes) and raises
KeyboardInterrupt. Raises CaseError for bad input (the command's message), RuntimeError
when the reference run fails or the command ends otherwise.)");
}

}  // namespace limber::python
