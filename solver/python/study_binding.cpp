#include "python/study_binding.h"

#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/case_reduction.h"
#include "io/formulation_override.h"
#include "io/modes_file.h"
#include "io/modes_json.h"
#include "python/case_binding.h"
#include "python/interruptible.h"
#include "python/sweep_binding.h"
#include "results/file_names.h"
#include "run/settings_overrides.h"
#include "select/selection_json.h"
#include "select/selection_procedure.h"

namespace py = pybind11;

namespace limber::python {

namespace {

py::object json_loads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

// `output`, or the command's default out/<case file stem><suffix> (a case from a file only).
std::filesystem::path output_folder(const io::Case& input, const std::optional<std::filesystem::path>& output,
                                    const std::string& suffix) {
  if (output) return *output;
  if (input.file == "<dict>") throw InputError("expected output=FOLDER for a case built from a dict, got None");
  return std::filesystem::path("out") / (std::filesystem::path(input.file).stem().string() + suffix);
}

py::object modes(const py::object& case_or_path, std::optional<std::filesystem::path> output) {
  const std::shared_ptr<const io::Case> input = case_of(case_or_path);
  if (input->flexible_bodies.empty()) {
    throw InputError("expected at least one body under 'flexible_bodies', got none", SourceLocation{input->file, 0, 0});
  }
  std::string document;
  {
    py::gil_scoped_release released;
    const io::CaseReduction reduction = io::reduce_case(*input, io::ReductionScope::kAllBodies);
    std::vector<io::BodyModesRef> computed;
    std::vector<std::string> failures;
    for (std::size_t b = 0; b < input->flexible_bodies.size(); ++b) {
      const io::FlexibleBodyCase& body = input->flexible_bodies[b];
      const modal::ModalResult& result = reduction.bodies[b].result;
      if (result.status != modal::ModalStatus::kOk) {
        failures.push_back("body '" + body.name + "': " + modal::to_string(result.status) + ": " + result.message);
        continue;
      }
      computed.push_back({body.name, &body.model, &result.mode_set});
    }
    if (output) {
      std::filesystem::create_directories(*output);
      io::write_modes_file((*output / results::kModesFileName).string(), input->title, input->file, computed);
    }
    document = io::modes_json(computed, failures);
  }
  return json_loads(document);
}

py::object select(const py::object& case_or_path, std::optional<std::filesystem::path> output, double keep,
                  std::optional<double> target, const std::string& rank_by, const std::string& norm,
                  const std::string& static_modes, std::optional<int> max_single, int reference_normal, bool keep_step,
                  bool whole_run, int max_refinement, int jobs, std::optional<std::string> integrator,
                  std::optional<double> step, std::optional<double> rtol, std::optional<double> t_end,
                  std::optional<py::function> progress, const std::string& reference) {
  const std::shared_ptr<const io::Case> input = case_of(case_or_path);
  select::SelectionRequest request;
  request.root = output_folder(*input, output, "_select");
  request.keep = keep;
  request.target = target;
  request.rank_by = select::rank_by_from(rank_by, "rank_by");
  request.norm = select::error_norm_from(norm, "norm");
  request.candidates.static_kind = select::static_kind_from(static_modes, "static_modes");
  request.candidates.max_single = max_single;
  request.candidates.reference_normal = reference_normal;
  request.nonlinear_reference = io::nonlinear_formulation_requested(reference, "reference");
  request.policy = {keep_step, max_refinement, 1.0, whole_run};
  request.jobs = jobs;
  run::SettingsOverrides overrides;
  overrides.integrator = integrator.value_or("");
  overrides.step = step;
  overrides.rtol = rtol;
  overrides.t_end = t_end;
  request.adjust = [overrides](const io::RunSettings& settings) { return overrides.apply(settings); };
  select::check_request(request);
  const double t_end_run = input->mechanism ? overrides.apply(input->mechanism->run).t_end : 0.0;

  std::optional<py::error_already_set> callback_error;
  std::optional<select::Selection> selection;
  run_interruptible([&](const std::atomic<bool>& stop) {
    select::SelectionHooks hooks;
    hooks.on_sample = [&](const integrate::Sample& sample, bool) {
      if (stop) throw select::SelectionInterrupted{};
      if (!progress) return;
      py::gil_scoped_acquire acquired;
      if (callback_error) throw select::SelectionInterrupted{};
      try {
        (*progress)(sample.t, t_end_run);
      } catch (py::error_already_set& error) {
        callback_error.emplace(std::move(error));
        throw select::SelectionInterrupted{};
      }
    };
    selection = select::run_selection(input, request, hooks);
  });
  if (callback_error) throw std::move(*callback_error);
  if (!selection->refusal.empty()) throw NumericalError(selection->refusal);
  return json_loads(select::selection_json(*selection, request));
}

}  // namespace

void bind_studies(py::module_& module) {
  module.def("modes", &modes, py::arg("case_or_path"), py::kw_only(), py::arg("output") = py::none(),
             R"(modes(case_or_path, *, output=None) -> dict

Computes every flexible body's mode set as `limber modes` does and returns what its --json
prints: {'bodies': {name: {'dofs': N, 'modes': [{'kind', 'frequency_hz', 'label'}]}}} (rigid
modes first), with 'failures': [message] when a body's eigen-solver failed (the others are
still there).

Arguments:
  case_or_path  a Case (limber.load_case, limber.case_from_dict) or a case file's path
  output        a folder (created) for modes.h5 as `limber modes -o output` writes it (no VTU
                files, no animations); None writes nothing

Raises CaseError for bad input (no flexible body). The GIL is released while the modes are
computed.)");

  module.def("select", &select, py::arg("case_or_path"), py::kw_only(), py::arg("output") = py::none(),
             py::arg("keep") = 0.1, py::arg("target") = py::none(), py::arg("rank_by") = "peak",
             py::arg("norm") = "event", py::arg("static_modes") = "attachment", py::arg("max_single") = py::none(),
             py::arg("reference_normal") = 0, py::arg("keep_step") = false, py::arg("whole_run") = false,
             py::arg("max_refinement") = 8, py::arg("jobs") = 2, py::arg("integrator") = py::none(),
             py::arg("step") = py::none(), py::arg("rtol") = py::none(), py::arg("t_end") = py::none(),
             py::arg("progress") = py::none(), py::arg("reference") = "modal",
             R"(select(case_or_path, *, output=None, keep=0.1, target=None, rank_by='peak', norm='event', static_modes='attachment', max_single=None, reference_normal=0, keep_step=False, whole_run=False, max_refinement=8, jobs=2, integrator=None, step=None, rtol=None, t_end=None, progress=None, reference='modal') -> dict

Chooses the modes of the flexible bodies by the seed paper's procedure, as `limber select`
does (docs/select.md), in this process, and returns what its --json prints: 'ranking',
'comparison' (one dict per mode set), 'reference_check', 'chosen', 'target', 'target_met',
'norm', 'steps_per_period_needed', 'fragment' (the chosen modes as YAML), 'directory'.

Arguments (the options of `limber select` of the same names):
  case_or_path      a Case or a case file's path; the case needs a flexible body
  output            the folder for the runs and tables (DIR of `limber select -o DIR`);
                    None: out/<case file stem>_select (a dict case needs one)
  keep              keep reaction components >= keep x the body's largest (0 < keep <= 1)
  target            error target as a fraction (0.02 = 2 %): the fewest modes meeting it;
                    None: the procedure's answer ('kept')
  rank_by           'peak' or 'rms' over the run
  norm              error measure for target: 'event' (event peaks), 'peak' or 'rms'
  static_modes      'attachment' (unit loads) or 'constraint' (unit displacements)
  max_single        at most this many one-component sets (>= 0); None: 6 with a target
                    (each can be the answer), 0 without
  reference_normal  normal modes per body in the reference set (0: four times the case's)
  reference         'modal' (the richest modal set) or 'nonlinear' (the case with every
                    flexible body nonlinear: co-rotational FE beams, unreduced; the bodies
                    must be beams with damping 0 or Rayleigh; docs/select.md, "The nonlinear
                    reference"); with 'nonlinear' the richest modal set is one of the sets
  keep_step         run every set at the case's step instead of one resolving its modes
  whole_run         generalized-alpha: the resolving step throughout, not only in the
                    event windows
  max_refinement    a set's step is at least the case's divided by this (>= 1)
  jobs              sets run at a time (threads, >= 1)
  integrator, step, rtol, t_end   the case's run settings overridden, as in limber.run
  progress          a callable progress(t, t_end) [s], called at each sample of every set's
                    run (GIL held; sets on several threads call it in turn); an exception it
                    raises stops the selection and propagates

The GIL is released while the sets run. Ctrl-C stops the selection at the next sample of the
runs going (their files closed as 'interrupted') and raises KeyboardInterrupt. Raises
CaseError for bad input, RuntimeError when the normal-mode run fails or the reference is
refused (its message says why and what to change).)");
  bind_sweep(module);
}

}  // namespace limber::python
